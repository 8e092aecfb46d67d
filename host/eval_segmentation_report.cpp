// `pedtrack eval --truth-points ... --labels ...`: the segmentation report.
#include <algorithm>
#include <numeric>

#include "eval_report.h"
#include "report_format.h"

namespace pedtrack::cli {
namespace {

using mrpt::format;

double ratio(std::size_t a, std::size_t b) {
  return b ? double(a) / double(b) : NAN;
}

std::string pct(std::size_t a, std::size_t b) {
  return fixed(100 * ratio(a, b), 2);
}

struct Stats {
  double mean = NAN, p95 = NAN, max = NAN;
};
Stats stats(std::vector<double> v) {
  Stats s;
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  s.mean = std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
  s.p95 = v[std::min(v.size() - 1, std::size_t(std::ceil(0.95 * double(v.size()))) - 1)];
  s.max = v.back();
  return s;
}

// The worst person: lowest share of correct samples (and that share).
std::pair<std::int32_t, double> worst(
    const std::vector<std::pair<std::int32_t, eval::PersonSegCounts>>& per) {
  std::pair<std::int32_t, double> w{0, NAN};
  for (const auto& [id, c] : per) {
    const double r = ratio(c.correct, c.samples);
    if (!(r >= w.second)) w = {id, r};
  }
  return w;
}

std::string countsText(const char* title, const eval::PersonSegCounts& c,
                       const std::vector<std::pair<std::int32_t, eval::PersonSegCounts>>& per) {
  std::string o = format("  %s: %zu person-frames of %zu people\n", title, c.samples, per.size());
  o += format("    one cluster (correct)   %7s %%\n", pct(c.correct, c.samples).c_str());
  o += format("    split (over-seg.)       %7s %%\n", pct(c.split, c.samples).c_str());
  o += format("    merged with a person    %7s %%\n", pct(c.merged_person, c.samples).c_str());
  o += format("    merged with an object   %7s %%\n", pct(c.merged_object, c.samples).c_str());
  o += format("    missed (no cluster)     %7s %%\n", pct(c.missed, c.samples).c_str());
  const auto w = worst(per);
  if (!per.empty())
    o += format("    worst person            %7s %%   (id %d)\n", fixed(100 * w.second, 2).c_str(),
                w.first);
  return o;
}

std::string countsJson(const eval::PersonSegCounts& c,
                       const std::vector<std::pair<std::int32_t, eval::PersonSegCounts>>& per) {
  Json j;
  j.count("samples", c.samples)
      .count("people", per.size())
      .num("correct", ratio(c.correct, c.samples))
      .num("split", ratio(c.split, c.samples))
      .num("merged_person", ratio(c.merged_person, c.samples))
      .num("merged_object", ratio(c.merged_object, c.samples))
      .num("missed", ratio(c.missed, c.samples));
  const auto w = worst(per);
  j.raw("worst_person", std::to_string(w.first)).num("worst_person_correct", w.second);
  std::string list = "[";
  for (std::size_t i = 0; i < per.size(); ++i) {
    Json e;
    e.raw("id", std::to_string(per[i].first))
        .count("samples", per[i].second.samples)
        .num("correct", ratio(per[i].second.correct, per[i].second.samples));
    list += (i ? ", " : "") + e.str();
  }
  j.raw("per_person", list + "]");
  return j.str();
}

}  // namespace

std::string segmentationText(const eval::SegmentationReport& r,
                             const eval::SegmentationOptions& o) {
  std::string s = format(
      "pedtrack eval: segmentation, %zu frames (%zu truth frames not in the run); people scored "
      "from %ld returns, a cluster counts from %ld of a person's points, isolated = clear of "
      "everything else by >= %.2f m\n\n",
      r.frames, r.truth_only_frames, o.min_points, o.fragment, o.isolation);
  s += "  points\n";
  s += format("    ground removed as ground        %7s %%   of %zu ground points\n",
              pct(r.ground_removed, r.ground_points).c_str(), r.ground_points);
  s += format("    ground left in clusters         %7s %%\n",
              pct(r.ground_in_clusters, r.ground_points).c_str());
  s += format("    person removed as ground        %7s %%   of %zu person points\n",
              pct(r.person_as_ground, r.person_points).c_str(), r.person_points);
  s += format("    person removed by band/region   %7s %%\n",
              pct(r.person_band_removed, r.person_points).c_str());
  s += format("    person in clusters              %7s %%\n",
              pct(r.person_in_clusters, r.person_points).c_str());
  s += format("    object removed as ground        %7s %%   of %zu object points\n",
              pct(r.object_as_ground, r.object_points).c_str(), r.object_points);
  const Stats a = stats(r.plane_angle_deg), d = stats(r.plane_offset);
  s += format("\n  ground plane (%zu frames with both planes)\n", r.plane_angle_deg.size());
  s += format("    normal error        mean %s  p95 %s  max %s deg\n", fixed(a.mean, 3).c_str(),
              fixed(a.p95, 3).c_str(), fixed(a.max, 3).c_str());
  s += format("    height under robot  mean %s  p95 %s  max %s m\n\n", fixed(d.mean, 4).c_str(),
              fixed(d.p95, 4).c_str(), fixed(d.max, 4).c_str());
  s += countsText("people", r.all, r.per_person);
  s += countsText("isolated people", r.isolated, r.per_person_isolated);
  return s;
}

std::string segmentationJson(const eval::SegmentationReport& r,
                             const eval::SegmentationOptions& o) {
  Json j(true);
  const Stats a = stats(r.plane_angle_deg), d = stats(r.plane_offset);
  j.text("mode", "segmentation")
      .count("min_points", std::size_t(o.min_points))
      .count("fragment", std::size_t(o.fragment))
      .num("isolation_m", o.isolation)
      .count("frames", r.frames)
      .count("truth_only_frames", r.truth_only_frames)
      .count("ground_points", r.ground_points)
      .num("ground_removed", ratio(r.ground_removed, r.ground_points))
      .num("ground_in_clusters", ratio(r.ground_in_clusters, r.ground_points))
      .count("person_points", r.person_points)
      .num("person_as_ground", ratio(r.person_as_ground, r.person_points))
      .num("person_band_removed", ratio(r.person_band_removed, r.person_points))
      .num("person_in_clusters", ratio(r.person_in_clusters, r.person_points))
      .count("object_points", r.object_points)
      .num("object_as_ground", ratio(r.object_as_ground, r.object_points))
      .count("plane_frames", r.plane_angle_deg.size())
      .num("plane_angle_mean_deg", a.mean)
      .num("plane_angle_p95_deg", a.p95)
      .num("plane_angle_max_deg", a.max)
      .num("plane_offset_mean_m", d.mean)
      .num("plane_offset_p95_m", d.p95)
      .num("plane_offset_max_m", d.max)
      .raw("people", countsJson(r.all, r.per_person))
      .raw("isolated", countsJson(r.isolated, r.per_person_isolated));
  return j.str() + "\n";
}

}  // namespace pedtrack::cli
