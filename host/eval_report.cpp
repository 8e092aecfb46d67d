#include "eval_report.h"

#include <mrpt/core/format.h>

#include <array>
#include <cmath>

#include "pedtrack/outputs.h"
#include "report_format.h"

namespace pedtrack::cli {
namespace {

using mrpt::format;

std::string consistencyJson(const std::optional<eval::ConsistencyReport>& c, const char* p) {
  if (!c) return "null";
  auto k = [&](const char* name) { return std::string(p) + "_" + name; };
  Json j;
  j.count(k("dof").c_str(), std::size_t(c->dof))
      .count(k("samples").c_str(), c->samples)
      .count(k("points").c_str(), c->points.size())
      .num(k("mean").c_str(), c->mean)
      .num(k("mean_lower").c_str(), c->mean_bounds.lower)
      .num(k("mean_upper").c_str(), c->mean_bounds.upper)
      .num(k("point_lower").c_str(), c->nominal_bounds.lower)
      .num(k("point_upper").c_str(), c->nominal_bounds.upper)
      .num(k("fraction_inside").c_str(), c->fraction_inside);
  std::string per = "[";
  for (std::size_t i = 0; i < c->per_truth.size(); ++i) {
    const auto& t = c->per_truth[i];
    Json e;
    e.raw("id", std::to_string(t.id))
        .count("points", t.points)
        .num("mean", t.mean)
        .num("fraction_inside", t.fraction_inside);
    per += (i ? ", " : "") + e.str();
  }
  j.raw(k("per_truth").c_str(), per + "]");
  return j.str();
}

std::string consistencyText(const eval::ConsistencyReport& c, const char* name) {
  std::string o = format("%s (%d dof, %zu run%s, %zu samples)\n", name, c.dof, c.runs,
                         c.runs == 1 ? "" : "s", c.samples);
  o +=
      format("  mean                %s   95%% region of the mean [%s, %s]\n", fixed(c.mean).c_str(),
             fixed(c.mean_bounds.lower).c_str(), fixed(c.mean_bounds.upper).c_str());
  o += format("  points inside       %s %%   of %zu points (truth x frame, averaged over runs)\n",
              fixed(100 * c.fraction_inside, 1).c_str(), c.points.size());
  o += format("  point region        [%s, %s]   (95%% for %zu run%s)\n",
              fixed(c.nominal_bounds.lower).c_str(), fixed(c.nominal_bounds.upper).c_str(), c.runs,
              c.runs == 1 ? "" : "s");
  for (const auto& t : c.per_truth)
    o += format("  truth %-6ld        mean %s, %s %% of %zu points inside\n", t.id,
                fixed(t.mean).c_str(), fixed(100 * t.fraction_inside, 1).c_str(), t.points);
  return o;
}

std::string setupLine(const EvalSetup& s) {
  std::string o = format("threshold %.3f m, %s frame", s.threshold, s.frame.c_str());
  if (s.truth_source == "csv") o += format(", min visible points %ld", s.min_visible);
  if (s.following) o += format(", following truth %ld", *s.following);
  return o;
}

// "Where the errors are": misses by the returns on the person (0–9, 10–29, ≥ 30, unknown: the
// bins holding truths), ID switches by the time since the person was last matched, false
// positives by the nearest person (and how many of them coasted).
std::string budgetText(const eval::ErrorBudget& b, bool following) {
  static const char* visible[] = {"0-9", "10-29", "30+", "unknown"};
  static const char* near[] = {"< 1 m", "1-2 m", ">= 2 m"};
  std::string o =
      "\nWhere the errors are (misses by returns on the person, ID switches by time since the "
      "person was last matched, false positives by distance to the nearest person)\n"
      "  misses              ";
  const char* sep = "";
  for (std::size_t k = 0; k < eval::ErrorBudget::kVisibleBins; ++k) {
    const std::size_t n = b.truths_by_visible[k];
    if (n == 0) continue;
    o += format("%s%s: %zu of %zu (%.1f %%)", sep, visible[k], b.misses_by_visible[k], n,
                100.0 * double(b.misses_by_visible[k]) / double(n));
    sep = ", ";
  }
  o += "\n";
  static const char* gap[] = {"< 0.5 s", "0.5-2 s", ">= 2 s", "first match"};
  o += "  ID switches         ";
  sep = "";
  for (std::size_t k = 0; k < eval::ErrorBudget::kGapBins; ++k) {
    if (b.switches_by_gap[k] == 0) continue;
    o += format("%s%s: %zu (%zu by another person's track, %zu out of sight)", sep, gap[k],
                b.switches_by_gap[k], b.switches_from_other_by_gap[k], b.switches_unseen_by_gap[k]);
    sep = ", ";
  }
  o += *sep ? "\n" : "none\n";
  if (following) return o;
  o += "  false positives     ";
  for (std::size_t k = 0; k < eval::ErrorBudget::kDistanceBins; ++k)
    o += format("%s%s: %zu (%zu coasting)", k ? ", " : "", near[k], b.fp_by_distance[k],
                b.coasting_fp_by_distance[k]);
  return o + "\n";
}

template <std::size_t N>
std::string countList(const std::array<std::size_t, N>& a) {
  std::string o = "[";
  for (std::size_t k = 0; k < N; ++k) o += (k ? ", " : "") + std::to_string(a[k]);
  return o + "]";
}

std::string budgetJson(const eval::ErrorBudget& b) {
  Json j;
  j.raw("visible_bins", "[\"0-9\", \"10-29\", \"30+\", \"unknown\"]")
      .raw("truths_by_visible", countList(b.truths_by_visible))
      .raw("misses_by_visible", countList(b.misses_by_visible))
      .raw("nearest_person_bins_m", "[\"<1\", \"1-2\", \">=2\"]")
      .raw("false_positives_by_nearest_person", countList(b.fp_by_distance))
      .raw("coasting_false_positives_by_nearest_person", countList(b.coasting_fp_by_distance))
      .raw("switch_gap_bins_s", "[\"<0.5\", \"0.5-2\", \">=2\", \"first match\"]")
      .raw("id_switches_by_gap", countList(b.switches_by_gap))
      .raw("id_switches_from_other_person_by_gap", countList(b.switches_from_other_by_gap))
      .raw("id_switches_after_out_of_sight_by_gap", countList(b.switches_unseen_by_gap));
  return j.str();
}

}  // namespace

std::string trackingText(const eval::TrackingReport& r, const EvalSetup& s) {
  const auto& c = r.clear;
  const auto& e = r.errors;
  std::string o = format("pedtrack eval: %zu run%s, %zu frames; %s\n\n", r.runs,
                         r.runs == 1 ? "" : "s", c.frames, setupLine(s).c_str());
  o += "CLEAR MOT (leg_tracker benchmark rules)\n";
  o += format("  MOTA                %s\n", fixed(c.mota()).c_str());
  o += format("  MOTP                %s m\n", fixed(c.motp()).c_str());
  o += format("  truths              %zu\n", c.truths);
  o += format("  matched             %zu   (correct %zu, ID switches %zu)\n", c.matches, c.correct,
              c.id_switches);
  o += format("  misses              %zu\n", c.misses);
  o += format("  false positives     %zu%s\n", c.false_positives,
              s.following ? "   (not counted when following)" : "");
  o += format("  ID switches         %zu\n", c.id_switches);
  o += format("  fragmentations      %zu\n", c.fragmentations);
  o += format("  unscored matches    %zu\n", c.unscored_matches);
  if (c.truths) o += budgetText(r.budget, s.following.has_value());
  o += format("\nErrors over the %zu matches\n", e.pairs);
  o += format("  position RMSE       %s m   (x %s, y %s)\n", fixed(e.rmse()).c_str(),
              fixed(e.rmseX()).c_str(), fixed(e.rmseY()).c_str());
  o += format("  position MAE        %s m\n", fixed(e.mae()).c_str());
  o += format("  body-axis MAE       sagittal %s m, frontal %s m   (%zu pairs with truth yaw)\n",
              fixed(e.sagittalMae()).c_str(), fixed(e.frontalMae()).c_str(), e.body_pairs);
  o += format("  heading MAE         %s rad = %s deg   (%zu pairs with yaw)\n",
              fixed(e.headingMae()).c_str(), fixed(e.headingMae() * 180 / M_PI, 2).c_str(),
              e.heading_pairs);
  o += format("  heading RMSE        %s rad = %s deg\n", fixed(e.headingRmse()).c_str(),
              fixed(e.headingRmse() * 180 / M_PI, 2).c_str());
  o += format("  axis RMSE (mod 180) %s rad = %s deg\n", fixed(e.axisRmse()).c_str(),
              fixed(e.axisRmse() * 180 / M_PI, 2).c_str());
  o += format("  semi-axis MAE       major %s m, minor %s m   (%zu pairs with shape)\n",
              fixed(e.majorMae()).c_str(), fixed(e.minorMae()).c_str(), e.shape_pairs);
  o += format("  speed MAE           %s m/s, velocity RMSE %s m/s   (%zu pairs)\n",
              fixed(e.speedMae()).c_str(), fixed(e.velocityRmse()).c_str(), e.speed_pairs);
  if (r.identity) {
    const auto& i = *r.identity;
    o += "\nIdentity (Ristani et al. 2016)\n";
    o += format("  IDF1                %s\n", fixed(i.idf1()).c_str());
    o += format("  IDP                 %s\n", fixed(i.idp()).c_str());
    o += format("  IDR                 %s\n", fixed(i.idr()).c_str());
    o += format("  IDTP / IDFP / IDFN  %.0f / %.0f / %.0f\n", i.idtp, i.idfp, i.idfn);
  }
  if (r.hota) {
    const auto& h = *r.hota;
    o += format("\nHOTA (TrackEval; similarity max(0, 1 - d / %.3f m), mean over alpha)\n",
                s.hota_distance);
    o += format("  HOTA                %s\n", fixed(h.hota()).c_str());
    o += format("  DetA                %s   (DetRe %s, DetPr %s)\n", fixed(h.detA()).c_str(),
                fixed(h.detRe()).c_str(), fixed(h.detPr()).c_str());
    o += format("  AssA                %s   (AssRe %s, AssPr %s)\n", fixed(h.assA()).c_str(),
                fixed(h.assRe()).c_str(), fixed(h.assPr()).c_str());
    o += format("  LocA                %s\n", fixed(h.locA()).c_str());
  }
  if (r.nees) o += "\n" + consistencyText(*r.nees, "NEES");
  if (r.nis) o += "\n" + consistencyText(*r.nis, "NIS");
  return o;
}

std::string trackingJson(const eval::TrackingReport& r, const EvalSetup& s,
                         const std::vector<std::pair<std::string, std::string>>& extra) {
  const auto& c = r.clear;
  const auto& e = r.errors;
  Json clear;
  clear.count("frames", c.frames)
      .count("truths", c.truths)
      .count("matches", c.matches)
      .count("correct", c.correct)
      .count("misses", c.misses)
      .count("false_positives", c.false_positives)
      .count("id_switches", c.id_switches)
      .count("fragmentations", c.fragmentations)
      .count("unscored_matches", c.unscored_matches)
      .num("mota", c.mota())
      .num("motp_m", c.motp());
  Json err;
  err.count("pairs", e.pairs)
      .num("position_rmse_m", e.rmse())
      .num("position_mae_m", e.mae())
      .num("position_rmse_x_m", e.rmseX())
      .num("position_rmse_y_m", e.rmseY())
      .count("body_axis_pairs", e.body_pairs)
      .num("sagittal_mae_m", e.sagittalMae())
      .num("frontal_mae_m", e.frontalMae())
      .count("heading_pairs", e.heading_pairs)
      .num("heading_mae_rad", e.headingMae())
      .num("heading_mae_deg", e.headingMae() * 180 / M_PI)
      .num("heading_rmse_rad", e.headingRmse())
      .num("heading_rmse_deg", e.headingRmse() * 180 / M_PI)
      .num("axis_rmse_rad", e.axisRmse())
      .num("axis_rmse_deg", e.axisRmse() * 180 / M_PI)
      .count("shape_pairs", e.shape_pairs)
      .num("major_axis_mae_m", e.majorMae())
      .num("minor_axis_mae_m", e.minorMae())
      .count("speed_pairs", e.speed_pairs)
      .num("speed_mae_mps", e.speedMae())
      .num("velocity_rmse_mps", e.velocityRmse());
  std::string identity = "null", hota = "null";
  if (r.identity) {
    const auto& i = *r.identity;
    Json j;
    j.num("idtp", i.idtp)
        .num("idfp", i.idfp)
        .num("idfn", i.idfn)
        .num("idf1", i.idf1())
        .num("idp", i.idp())
        .num("idr", i.idr());
    identity = j.str();
  }
  if (r.hota) {
    const auto& h = *r.hota;
    Json j;
    j.num("hota_distance_m", s.hota_distance)
        .num("hota", h.hota())
        .num("deta", h.detA())
        .num("assa", h.assA())
        .num("loca", h.locA())
        .num("detre", h.detRe())
        .num("detpr", h.detPr())
        .num("assre", h.assRe())
        .num("asspr", h.assPr());
    hota = j.str();
  }
  Json top(true);
  top.text("mode", "tracking")
      .count("runs", r.runs)
      .num("threshold_m", s.threshold)
      .text("frame", s.frame)
      .count("min_visible", std::size_t(s.min_visible))
      .raw("following", s.following ? std::to_string(*s.following) : "null")
      .raw("clear_mot", clear.str())
      .raw("error_budget", budgetJson(r.budget))
      .raw("errors", err.str())
      .raw("identity", identity)
      .raw("hota", hota)
      .raw("nees", consistencyJson(r.nees, "nees"))
      .raw("nis", consistencyJson(r.nis, "nis"));
  for (const auto& [key, value] : extra) top.raw(key.c_str(), value);
  return top.str() + "\n";
}

std::string legCoverageText(const eval::LegCoverage& c, const EvalSetup& s,
                            const std::string& bag) {
  std::string o = format(
      "pedtrack eval: tracks against the labelled legs of %s; a leg is covered by a track within "
      "%.3f m (laser frame)\n\n",
      bag.c_str(), s.threshold);
  o += format("  labelled legs       %ld\n", c.legs);
  o += format("  covered             %ld   (recall %s)\n", c.covered, fixed(c.recall()).c_str());
  o += format("  track rows          %ld\n", c.rows);
  o += format("  near no leg         %ld\n", c.unsupported);
  o += format("  tracks              %zu   (%ld with at most 10 %% of their rows near a leg)\n",
              c.per_track.size(), c.tracksOnNoPerson());
  return o;
}

std::string legCoverageJson(const eval::LegCoverage& c, const EvalSetup& s) {
  Json j;
  j.num("threshold_m", s.threshold)
      .count("labelled_legs", std::size_t(c.legs))
      .count("legs_covered", std::size_t(c.covered))
      .num("leg_recall", c.recall())
      .count("track_rows", std::size_t(c.rows))
      .count("rows_near_no_leg", std::size_t(c.unsupported))
      .count("tracks", c.per_track.size())
      .count("tracks_on_no_person", std::size_t(c.tracksOnNoPerson()));
  return j.str() + "\n";
}

std::string detectionText(const eval::DetectionCounts& c, const EvalSetup& s) {
  std::string o = format("pedtrack eval: detections vs %s%s, %zu frames; %s\n\n",
                         s.truth_source == "bag" ? "labelled legs of a bag" : "truth",
                         s.legs ? " legs" : "", c.frames, setupLine(s).c_str());
  o += format("  precision           %s\n", fixed(c.precision()).c_str());
  o += format("  recall              %s\n", fixed(c.recall()).c_str());
  o += format("  F1                  %s\n", fixed(c.f1()).c_str());
  o +=
      format("  mean distance       %s m   (of true positives)\n", fixed(c.meanDistance()).c_str());
  o += format("  TP / FP / FN        %zu / %zu / %zu\n", c.tp, c.fp, c.fn);
  o += format("  truth points        %zu   (scored)\n", c.truth_points);
  o += format("  detections          %zu   (%s per frame; false positives %s per frame)\n",
              c.detections, fixed(c.frames ? double(c.detections) / c.frames : NAN, 2).c_str(),
              fixed(c.frames ? double(c.fp) / c.frames : NAN, 3).c_str());
  o += format("  unscored matches    %zu\n", c.unscored_matches);
  if (!c.by_range.empty()) {
    o += format("\n  recall by distance from the sensor\n  %-12s %8s %8s %8s\n", "range (m)",
                "truth", "TP", "recall");
    for (const auto& [k, v] : c.by_range)
      o += format("  %4.1f - %-5.1f %8zu %8zu %8s\n", k * c.range_bin, (k + 1) * c.range_bin,
                  v.first + v.second, v.first,
                  fixed(double(v.first) / double(v.first + v.second), 3).c_str());
  }
  return o;
}

std::string detectionJson(const eval::DetectionCounts& c, const EvalSetup& s) {
  Json j(true);
  j.text("mode", "detections")
      .text("truth_source", s.truth_source)
      .raw("legs", s.legs ? "true" : "false")
      .num("threshold_m", s.threshold)
      .text("frame", s.frame)
      .count("min_visible", std::size_t(s.min_visible))
      .count("frames", c.frames)
      .count("truth_points", c.truth_points)
      .count("detections", c.detections)
      .count("tp", c.tp)
      .count("fp", c.fp)
      .count("fn", c.fn)
      .count("unscored_matches", c.unscored_matches)
      .num("precision", c.precision())
      .num("recall", c.recall())
      .num("f1", c.f1())
      .num("mean_distance_m", c.meanDistance())
      .num("false_positives_per_frame", c.frames ? double(c.fp) / c.frames : NAN);
  std::string bins = "[";
  for (const auto& [k, v] : c.by_range) {
    Json b;
    b.num("from_m", k * c.range_bin)
        .num("to_m", (k + 1) * c.range_bin)
        .count("truth", v.first + v.second)
        .count("tp", v.first)
        .num("recall", double(v.first) / double(v.first + v.second));
    bins += (bins.size() > 1 ? ", " : "") + b.str();
  }
  j.raw("recall_by_range", bins + "]");
  return j.str() + "\n";
}

}  // namespace pedtrack::cli
