#include "pedtrack/eval/decisions.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>
#include <unordered_set>

#include "pedtrack/errors.h"
#include "pedtrack/eval/object_table.h"

namespace pedtrack::eval {

namespace {

double ratio(std::size_t num, std::size_t den) {
  return den ? double(num) / double(den) : std::numeric_limits<double>::quiet_NaN();
}

/// The majority owner of a cluster's points. Ties go to a person (the lowest id), then an object,
/// then the ground: a cluster half person is scored as a person.
std::int32_t majorityOwner(const std::map<std::int32_t, long>& owners) {
  std::int32_t best = truth_label::kGround;
  long best_n = -1;
  auto rank = [](std::int32_t l) { return truth_label::isPerson(l) ? 2 : l < 0 ? 1 : 0; };
  for (const auto& [owner, n] : owners)
    if (n > best_n || (n == best_n && rank(owner) > rank(best)) ||
        (n == best_n && rank(owner) == rank(best) && std::abs(owner) < std::abs(best))) {
      best = owner;
      best_n = n;
    }
  return best;
}

ObjectDecisions& entry(std::vector<ObjectDecisions>& v, std::int32_t id) {
  auto it = std::lower_bound(v.begin(), v.end(), id,
                             [](const ObjectDecisions& o, std::int32_t i) { return o.id < i; });
  if (it == v.end() || it->id != id) {
    ObjectDecisions o;
    o.id = id;
    it = v.insert(it, o);
  }
  return *it;
}

}  // namespace

void DecisionMatrix::add(bool actual_person, bool decided_person) {
  if (actual_person)
    ++(decided_person ? tp : fn);
  else
    ++(decided_person ? fp : tn);
}

double DecisionMatrix::detectionRate() const {
  return ratio(tp, tp + fn);
}
double DecisionMatrix::falsePositiveRate() const {
  return ratio(fp, fp + tn);
}
double DecisionMatrix::precision() const {
  return ratio(tp, tp + fp);
}
double DecisionMatrix::accuracy() const {
  return ratio(tp + tn, total());
}

void scoreDecisionFrame(const LabelFrame& truth, const LabelFrame& run,
                        const FrameDecisionInput& in, const DecisionOptions& opt,
                        DecisionReport& rep) {
  ++rep.frames;
  // Points per (cluster, truth owner); the ids the scan hit.
  std::map<std::int32_t, std::map<std::int32_t, long>> in_cluster;
  std::unordered_set<std::int32_t> hit;
  for (std::size_t i = 0; i < truth.labels.size() && i < run.labels.size(); ++i) {
    const std::int32_t t = truth.labels[i], r = run.labels[i];
    if (t != truth_label::kGround) hit.insert(t);
    if (r >= 0) ++in_cluster[r][t];
  }
  for (std::int32_t id : hit) ++entry(rep.per_object, id).hit_frames;
  rep.clusters += in_cluster.size();

  // Each cluster's detection score (the highest of its detections).
  std::map<std::int32_t, double> score;
  rep.detections += in.detections.size();
  for (const auto& [cluster, s] : in.detections) {
    if (cluster < 0) {
      ++rep.detections_without_cluster;
      continue;
    }
    if (!in_cluster.count(cluster)) {
      ++rep.detections_unknown_cluster;
      continue;
    }
    auto [it, fresh] = score.emplace(cluster, s);
    if (!fresh) {
      ++rep.detections_duplicate;
      if (std::isnan(it->second) || s > it->second) it->second = s;
    }
  }
  if (score.empty()) ++rep.frames_without_detections;
  std::unordered_set<std::int32_t> tracked;
  rep.track_rows_person += in.person_track_clusters.size();
  for (std::int32_t c : in.person_track_clusters) {
    if (c < 0) {
      ++rep.track_rows_without_cluster;
      continue;
    }
    if (!score.count(c)) ++rep.track_clusters_unscored;
    tracked.insert(c);
  }

  // Per id this frame: (owned a scored cluster, any passed Q_P, any tracked).
  std::map<std::int32_t, std::pair<bool, bool>> owned;
  for (const auto& [cluster, owners] : in_cluster) {
    const std::int32_t owner = majorityOwner(owners);
    const bool person = truth_label::isPerson(owner);
    const auto s = score.find(cluster);
    if (s == score.end()) {
      ++(person ? rep.unscored_person : rep.unscored_nonperson);
      continue;
    }
    ++rep.clusters_scored;
    const bool appearance = s->second >= opt.q_person, complete = tracked.count(cluster) > 0;
    if (!std::isnan(s->second)) {
      if (std::isnan(rep.min_score) || s->second < rep.min_score) rep.min_score = s->second;
      if (std::isnan(rep.max_score) || s->second > rep.max_score) rep.max_score = s->second;
    }
    rep.per_cluster.appearance.add(person, appearance);
    rep.per_cluster.complete.add(person, complete);
    if (owner == truth_label::kGround) {
      ++rep.scored_ground;
      continue;
    }
    auto& o = owned[owner];
    o.first = o.first || appearance;
    o.second = o.second || complete;
  }
  for (const auto& [id, d] : owned) {
    ObjectDecisions& e = entry(rep.per_object, id);
    ++e.frames;
    e.appearance_frames += d.first;
    e.complete_frames += d.second;
  }
}

void finishDecisions(DecisionReport& rep) {
  std::stable_sort(rep.per_object.begin(), rep.per_object.end(),
                   [](const ObjectDecisions& a, const ObjectDecisions& b) {
                     const bool pa = truth_label::isPerson(a.id), pb = truth_label::isPerson(b.id);
                     if (pa != pb) return pa;
                     return std::abs(a.id) < std::abs(b.id);
                   });
  rep.per_object_any = rep.per_object_majority = DecisionPair();
  rep.persons_never_scored = rep.objects_never_scored = 0;
  for (const ObjectDecisions& o : rep.per_object) {
    const bool person = truth_label::isPerson(o.id);
    if (o.frames == 0) {
      ++(person ? rep.persons_never_scored : rep.objects_never_scored);
      continue;
    }
    rep.per_object_any.appearance.add(person, o.appearance_frames > 0);
    rep.per_object_any.complete.add(person, o.complete_frames > 0);
    rep.per_object_majority.appearance.add(person, 2 * o.appearance_frames > o.frames);
    rep.per_object_majority.complete.add(person, 2 * o.complete_frames > o.frames);
  }
}

namespace {

void requireColumns(const ObjectTable& t, std::initializer_list<const char*> names,
                    const std::string& why) {
  for (const char* n : names)
    if (!t.hasColumn(n))
      throw ConfigError(t.path + ": header lacks column '" + n + "' (" + why + ")");
}

}  // namespace

DecisionReport evaluateDecisions(const DecisionInputs& in, const DecisionOptions& opt) {
  // Every file is opened (and rejected) before the label frames are read.
  LabelFileReader truth(in.truth_points), run(in.point_labels);
  if (truth.kind() != LabelKind::Truth)
    throw ConfigError(in.truth_points +
                      ": not a truth file (truth_points.bin from pedtrack sim / the sim source)");
  if (run.kind() != LabelKind::Run)
    throw ConfigError(in.point_labels +
                      ": not a run's labels (point_labels.bin from pedtrack run --out)");
  const ObjectTable dets = readDetectionTable(in.detections);
  requireColumns(dets, {"frame", "score", "cluster"},
                 "a run of this pedtrack writes it; the cluster links a detection to its points");
  const ObjectTable tracks = readObjectTable(in.tracks);
  requireColumns(tracks, {"frame", "status", "cluster"},
                 "a run of this pedtrack writes it; the cluster links a track to its points");

  std::unordered_map<long, FrameDecisionInput> by_frame;
  for (const ObjectRow& r : dets.rows)
    by_frame[r.frame].detections.emplace_back(static_cast<std::int32_t>(r.cluster), r.score);
  for (const ObjectRow& r : tracks.rows)
    if (r.status == opt.person_status)
      by_frame[r.frame].person_track_clusters.push_back(static_cast<std::int32_t>(r.cluster));

  DecisionReport rep;
  std::unordered_set<long> scored;
  LabelFrame t, r;
  bool have_run = run.next(r);
  const FrameDecisionInput none;
  while (truth.next(t)) {
    while (have_run && r.index < t.index) have_run = run.next(r);
    if (!have_run || r.index != t.index) {
      ++rep.truth_only_frames;
      continue;
    }
    if (r.labels.size() != t.labels.size())
      throw DataError(in.point_labels + ": frame " + std::to_string(r.index) + " has " +
                      std::to_string(r.labels.size()) + " points, the truth " +
                      std::to_string(t.labels.size()) + ": not a run on the simulated data");
    const auto it = by_frame.find(static_cast<long>(t.index));
    const FrameDecisionInput& fin = it == by_frame.end() ? none : it->second;
    scoreDecisionFrame(t, r, fin, opt, rep);
    scored.insert(static_cast<long>(t.index));
  }
  std::unordered_set<long> det_frames;
  for (const ObjectRow& row : dets.rows) det_frames.insert(row.frame);
  for (long f : det_frames) rep.detection_frames_unmatched += scored.count(f) == 0;
  finishDecisions(rep);
  return rep;
}

}  // namespace pedtrack::eval
