#include "pedtrack/eval/segmentation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include "pedtrack/errors.h"

namespace pedtrack::eval {

PersonSegCounts& PersonSegCounts::operator+=(const PersonSegCounts& o) {
  samples += o.samples;
  correct += o.correct;
  split += o.split;
  merged_person += o.merged_person;
  merged_object += o.merged_object;
  missed += o.missed;
  return *this;
}

namespace {

void addTo(std::vector<std::pair<std::int32_t, PersonSegCounts>>& v, std::int32_t id,
           const PersonSegCounts& c) {
  auto it = std::find_if(v.begin(), v.end(), [&](const auto& e) { return e.first == id; });
  if (it == v.end())
    v.emplace_back(id, c);
  else
    it->second += c;
}

}  // namespace

void scoreSegmentationFrame(const LabelFrame& truth, const LabelFrame& run,
                            const SegmentationOptions& opt, SegmentationReport& rep) {
  ++rep.frames;
  const std::size_t n = truth.labels.size();
  // Points per (cluster, truth owner), and each person's total.
  std::map<std::int32_t, std::map<std::int32_t, long>> in_cluster;  // cluster -> owner -> count
  std::unordered_map<std::int32_t, long> person_total;
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t t = truth.labels[i], r = run.labels[i];
    if (t == truth_label::kGround) {
      ++rep.ground_points;
      rep.ground_removed += r == run_label::kGround;
      rep.ground_in_clusters += r >= 0;
    } else if (truth_label::isPerson(t)) {
      ++rep.person_points;
      ++person_total[t];
      rep.person_as_ground += r == run_label::kGround;
      rep.person_band_removed += r == run_label::kRemoved;
      rep.person_in_clusters += r >= 0;
    } else {
      ++rep.object_points;
      rep.object_as_ground += r == run_label::kGround;
    }
    if (r >= 0) ++in_cluster[r][t];
  }
  if (truth.plane.valid && run.plane.valid) {
    rep.plane_angle_deg.push_back(truth.plane.angleTo(run.plane) * 180.0 / M_PI);
    // Heights of the point under the robot origin: z where each plane crosses x = y = 0.
    const double z_truth = -truth.plane.d / truth.plane.nz, z_run = -run.plane.d / run.plane.nz;
    rep.plane_offset.push_back(std::abs(z_truth - z_run));
  }
  // Clusters holding each person, and what else those clusters hold.
  std::unordered_map<std::int32_t, std::vector<std::int32_t>> holders;
  for (const auto& [cluster, owners] : in_cluster)
    for (const auto& [owner, count] : owners)
      if (truth_label::isPerson(owner) && count >= opt.fragment) holders[owner].push_back(cluster);
  for (const auto& [id, total] : person_total) {
    if (total < opt.min_points) continue;
    PersonSegCounts c;
    c.samples = 1;
    const auto& hs = holders[id];
    bool other_person = false, object = false;
    for (std::int32_t cl : hs)
      for (const auto& [owner, count] : in_cluster[cl]) {
        if (count < opt.fragment || owner == id || owner == truth_label::kGround) continue;
        (truth_label::isPerson(owner) ? other_person : object) = true;
      }
    c.missed = hs.empty();
    c.split = hs.size() > 1;
    c.merged_person = other_person;
    c.merged_object = object;
    c.correct = hs.size() == 1 && !other_person && !object;
    rep.all += c;
    addTo(rep.per_person, id, c);
    const auto it = std::find_if(truth.people.begin(), truth.people.end(),
                                 [&, pid = id](const PersonClearance& p) { return p.id == pid; });
    if (it != truth.people.end() && it->clearance >= opt.isolation) {
      rep.isolated += c;
      addTo(rep.per_person_isolated, id, c);
    }
  }
}

SegmentationReport evaluateSegmentation(const std::string& truth_path, const std::string& run_path,
                                        const SegmentationOptions& opt) {
  LabelFileReader truth(truth_path), run(run_path);
  if (truth.kind() != LabelKind::Truth)
    throw ConfigError(truth_path + ": not a truth file (truth_points.bin from pedtrack sim)");
  if (run.kind() != LabelKind::Run)
    throw ConfigError(run_path + ": not a run's labels (point_labels.bin from pedtrack run)");
  SegmentationReport rep;
  LabelFrame t, r;
  bool have_run = run.next(r);
  while (truth.next(t)) {
    while (have_run && r.index < t.index) have_run = run.next(r);
    if (!have_run || r.index != t.index) {
      ++rep.truth_only_frames;
      continue;
    }
    if (r.labels.size() != t.labels.size())
      throw DataError(run_path + ": frame " + std::to_string(r.index) + " has " +
                      std::to_string(r.labels.size()) + " points, the truth " +
                      std::to_string(t.labels.size()) + ": not a run on the simulated data");
    scoreSegmentationFrame(t, r, opt, rep);
  }
  auto byId = [](const auto& a, const auto& b) { return a.first < b.first; };
  std::sort(rep.per_person.begin(), rep.per_person.end(), byId);
  std::sort(rep.per_person_isolated.begin(), rep.per_person_isolated.end(), byId);
  return rep;
}

}  // namespace pedtrack::eval
