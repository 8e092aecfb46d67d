#include "montecarlo_score.h"

#include <cmath>
#include <map>
#include <set>

#include "pedtrack/errors.h"

namespace pedtrack::cli {
namespace {

constexpr double kTimeTolerance = 1e-4;  // s: two stamps this close are one frame (as eval)

using Key = std::pair<long, std::size_t>;  // truth id, frame index

struct SquaredErrors {
  double sx = 0, sy = 0;
  std::size_t n = 0;
  double syaw = 0;  // rad², pairs where both rows have yaw
  std::size_t n_yaw = 0;
};

void attach(std::map<Key, FramePoint>& points, const std::optional<eval::ConsistencyReport>& rep,
            std::optional<eval::ConsistencyPoint> FramePoint::*member) {
  if (!rep) return;
  for (const auto& c : rep->points) {
    auto it = points.find({c.truth_id, c.frame});
    if (it != points.end()) it->second.*member = c;
  }
}

TruthSummary summarise(long id, std::size_t scored_frames, const std::vector<FramePoint>& points) {
  TruthSummary s;
  s.id = id;
  s.frames = scored_frames;
  std::size_t nees_in = 0, nis_in = 0;
  double rmse_sum = 0, heading_sum = 0;
  for (const auto& p : points) {
    if (p.truth_id != id) continue;
    ++s.matched_frames;
    rmse_sum += p.rmse;
    s.rmse_max = std::max(s.rmse_max, p.rmse);
    if (p.heading_n) {
      ++s.heading_frames;
      heading_sum += p.heading_rmse;
      s.heading_rmse_max = std::max(s.heading_rmse_max, p.heading_rmse);
    }
    if (p.nees) ++s.nees_frames, nees_in += p.nees->inside;
    if (p.nis) ++s.nis_frames, nis_in += p.nis->inside;
  }
  s.rmse_mean = s.matched_frames ? rmse_sum / s.matched_frames : NAN;
  if (!s.matched_frames) s.rmse_max = NAN;
  s.heading_rmse_mean = s.heading_frames ? heading_sum / s.heading_frames : NAN;
  if (!s.heading_frames) s.heading_rmse_max = NAN;
  s.nees_inside = s.nees_frames ? double(nees_in) / s.nees_frames : NAN;
  s.nis_inside = s.nis_frames ? double(nis_in) / s.nis_frames : NAN;
  return s;
}

}  // namespace

std::size_t MonteCarloScore::runsWithoutSwitch() const {
  std::size_t n = 0;
  for (const auto& r : runs) n += r.id_switches == 0;
  return n;
}

MonteCarloScore scoreMonteCarlo(const std::vector<std::string>& truth,
                                const std::vector<std::string>& tracks,
                                const eval::TrackingOptions& opt) {
  if (truth.size() != tracks.size() || truth.empty())
    throw ConfigError("montecarlo: one truth.csv per tracks.csv, at least one run");
  // Every table is read before any frame is built: the frames' objects point into the rows.
  std::vector<ObjectTable> truth_tables, track_tables;
  for (std::size_t r = 0; r < truth.size(); ++r) {
    truth_tables.push_back(readObjectTable(truth[r]));
    track_tables.push_back(readObjectTable(tracks[r]));
  }
  std::vector<std::vector<eval::EvalFrame>> runs;
  for (std::size_t r = 0; r < truth.size(); ++r)
    runs.push_back(eval::alignFrames(
        eval::objectsByTime(truth_tables[r], eval::CoordFrame::Fixed, 1, kTimeTolerance),
        eval::objectsByTime(track_tables[r], eval::CoordFrame::Fixed, 0, kTimeTolerance),
        kTimeTolerance));

  MonteCarloScore s;
  s.t0 = runs[0].empty() ? 0 : runs[0][0].t;
  eval::ClearMotOptions co;
  co.threshold = opt.threshold;
  co.following = opt.following;
  std::map<Key, SquaredErrors> errors;
  std::map<long, std::set<std::size_t>> scored;  // frame indices where each truth is scored
  std::vector<double> times;                     // per frame index, from the first run having it
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const auto& frames = runs[r];
    for (std::size_t k = times.size(); k < frames.size(); ++k) times.push_back(frames[k].t);
    for (std::size_t k = 0; k < frames.size(); ++k)
      for (const auto& o : frames[k].truths)
        if (o.scored && (!opt.following || o.id == *opt.following)) scored[o.id].insert(k);
    RunScore rs;
    rs.track_rows = track_tables[r].rows.size();
    s.track_rows += rs.track_rows;
    const eval::ClearMotResult cm = eval::clearMot(frames, co);
    rs.id_switches = cm.counts.id_switches;
    rs.mota = cm.counts.mota();
    s.runs.push_back(rs);
    for (const auto& p : cm.pairs) {
      SquaredErrors& e = errors[{p.truth.id, p.frame}];
      e.sx += (p.estimate.x - p.truth.x) * (p.estimate.x - p.truth.x);
      e.sy += (p.estimate.y - p.truth.y) * (p.estimate.y - p.truth.y);
      ++e.n;
      const ObjectRow* er = p.estimate.row;
      const ObjectRow* tr = p.truth.row;
      if (er && tr && std::isfinite(er->yaw) && std::isfinite(tr->yaw)) {
        const double d = eval::wrapAngle(er->yaw - tr->yaw);
        e.syaw += d * d;
        ++e.n_yaw;
      }
    }
  }
  if (s.track_rows > 0) {
    s.tracking = eval::evaluateTracking(runs, opt);
    std::map<Key, FramePoint> points;
    for (const auto& [key, e] : errors) {
      FramePoint p;
      p.truth_id = key.first;
      p.frame = key.second;
      p.t = times[key.second];
      p.n = e.n;
      p.rmse_x = std::sqrt(e.sx / e.n);
      p.rmse_y = std::sqrt(e.sy / e.n);
      p.rmse = std::sqrt((e.sx + e.sy) / e.n);
      p.heading_n = e.n_yaw;
      if (e.n_yaw) p.heading_rmse = std::sqrt(e.syaw / e.n_yaw);
      points.emplace(key, p);
    }
    attach(points, s.tracking->nees, &FramePoint::nees);
    attach(points, s.tracking->nis, &FramePoint::nis);
    for (auto& [key, p] : points) s.points.push_back(std::move(p));
  }
  for (const auto& [id, frames] : scored)
    s.truths.push_back(summarise(id, frames.size(), s.points));
  return s;
}

}  // namespace pedtrack::cli
