#include "pedtrack/eval/evaluate.h"

namespace pedtrack::eval {

TrackingReport evaluateTracking(const std::vector<std::vector<EvalFrame>>& runs,
                                const TrackingOptions& opt) {
  TrackingReport rep;
  rep.runs = runs.size();
  const double tau = std::isfinite(opt.hota_distance) ? opt.hota_distance : opt.threshold;
  ClearMotOptions co;
  co.threshold = opt.threshold;
  co.following = opt.following;
  std::vector<ConsistencySample> nees, nis;
  std::vector<HotaResult> hotas;
  IdentityCounts id;
  for (const auto& frames : runs) {
    const ClearMotResult cm = clearMot(frames, co);
    rep.clear += cm.counts;
    rep.budget += errorBudget(frames, cm);
    rep.errors += pairErrors(cm.pairs);
    const auto ne = neesSamples(cm.pairs);
    const auto ni = nisSamples(cm.pairs);
    nees.insert(nees.end(), ne.begin(), ne.end());
    nis.insert(nis.end(), ni.begin(), ni.end());
    if (opt.following) continue;
    const std::vector<EvalFrame> scored = withoutUnscored(frames, cm);
    id += identity(scored, opt.threshold);
    hotas.push_back(hota(scored, tau));
  }
  if (!opt.following) {
    rep.identity = id;
    if (!hotas.empty()) rep.hota = combineHota(hotas);
  }
  if (!nees.empty()) rep.nees = consistency(nees, 2, runs.size());
  if (!nis.empty()) rep.nis = consistency(nis, opt.nis_dof, runs.size());
  return rep;
}

}  // namespace pedtrack::eval
