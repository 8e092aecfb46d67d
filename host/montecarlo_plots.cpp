#include "montecarlo_plots.h"

#include <mrpt/core/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "pedtrack/errors.h"
#include "pedtrack/text.h"
#include "plot.h"

namespace pedtrack::cli {
namespace {

using mrpt::format;
constexpr int kWidth = 900, kHeight = 520;
constexpr std::size_t kLegendTracks = 10;  // llr.png names up to this many tracks

/// One truth id's frames, NaN where no run matched it (the plotted lines break there).
struct Series {
  std::vector<double> t, mean, lower, upper;
};

Series consistencySeries(const std::vector<const FramePoint*>& pts, double t0,
                         std::optional<eval::ConsistencyPoint> FramePoint::*member) {
  Series s;
  std::size_t last = 0;
  for (const FramePoint* p : pts) {
    const auto& c = p->*member;
    if (!c) continue;
    if (!s.t.empty() && p->frame > last + 1)  // a gap of unmatched frames
      for (auto* v : {&s.t, &s.mean, &s.lower, &s.upper}) v->push_back(NAN);
    last = p->frame;
    s.t.push_back(p->t - t0);
    s.mean.push_back(c->mean);
    s.lower.push_back(c->bounds.lower);
    s.upper.push_back(c->bounds.upper);
  }
  return s;
}

/// The runs' average of NEES or NIS per frame on a log axis, with the 95 % bounds of the number of
/// runs averaged, and the expected value (the dof). Values far outside the bounds run off the
/// plot rather than squash it.
void drawConsistency(const std::string& path, const Series& s, const std::string& what, int dof,
                     const std::string& title) {
  double lo = INFINITY, hi = 0;
  for (std::size_t i = 0; i < s.mean.size(); ++i)
    if (std::isfinite(s.lower[i])) lo = std::min(lo, s.lower[i]), hi = std::max(hi, s.upper[i]);
  std::vector<double> values = {lo, hi};
  for (double v : s.mean)
    if (v > 0) values.push_back(std::clamp(v, lo / 100, hi * 100));
  const plot::Axis x = plot::fitAxis("time (s)", s.t);
  const plot::Axis y =
      plot::fitAxis(format("average %s (%d dof)", what.c_str(), dof), values, true);
  plot::Plot p(kWidth, kHeight, x, y, title);
  p.hline(dof, plot::kGrey, 1, true, format("expected (%d)", dof));
  p.line(s.t, s.lower, plot::kRed, 1, true, "95 % bounds");
  p.line(s.t, s.upper, plot::kRed, 1, true);
  p.line(s.t, s.mean, plot::kBlue, 2, false, "average " + what);
  p.legend();
  if (!p.write(path)) throw DataError("cannot write '" + path + "'");
}

void drawRmse(const std::string& path, const std::vector<const FramePoint*>& pts, double t0,
              const std::string& title) {
  std::vector<double> t, rx, ry, r;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (i && pts[i]->frame > pts[i - 1]->frame + 1)
      for (auto* v : {&t, &rx, &ry, &r}) v->push_back(NAN);
    t.push_back(pts[i]->t - t0);
    rx.push_back(pts[i]->rmse_x);
    ry.push_back(pts[i]->rmse_y);
    r.push_back(pts[i]->rmse);
  }
  const plot::Axis x = plot::fitAxis("time (s)", t);
  plot::Plot p(kWidth, kHeight, x, plot::fitAxis("RMSE (m)", r, false, true), title);
  p.line(t, r, plot::kGrey, 1, true, "position");
  p.line(t, rx, plot::kBlue, 2, false, "x");
  p.line(t, ry, plot::kRed, 2, false, "y");
  p.legend();
  if (!p.write(path)) throw DataError("cannot write '" + path + "'");
}

/// The heading RMSE per frame; the line breaks over frames without a heading value.
void drawHeading(const std::string& path, const std::vector<const FramePoint*>& pts, double t0,
                 const std::string& title) {
  std::vector<double> t, h;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (i && pts[i]->frame > pts[i - 1]->frame + 1) t.push_back(NAN), h.push_back(NAN);
    t.push_back(pts[i]->t - t0);
    h.push_back(pts[i]->heading_n ? pts[i]->heading_rmse : NAN);
  }
  const plot::Axis x = plot::fitAxis("time (s)", t);
  plot::Plot p(kWidth, kHeight, x, plot::fitAxis("heading RMSE (rad)", h, false, true), title);
  p.line(t, h, plot::kBlue, 2, false, "heading |wrap(yaw - yaw true)|");
  p.legend();
  if (!p.write(path)) throw DataError("cannot write '" + path + "'");
}

double number(const std::string& s) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  return end == s.c_str() ? NAN : v;
}

}  // namespace

std::vector<std::string> drawConsistencyPlots(const std::string& dir, const MonteCarloScore& score,
                                              const std::string& name) {
  std::vector<std::string> files;
  if (!score.tracking) return files;
  const std::size_t runs = score.runs.size();
  std::map<long, std::vector<const FramePoint*>> by_truth;  // points are sorted by frame
  for (const auto& p : score.points) by_truth[p.truth_id].push_back(&p);
  for (const auto& t : score.truths) {
    const auto it = by_truth.find(t.id);
    if (it == by_truth.end()) continue;
    const std::string head =
        format("%s: truth %ld, %zu run%s", name.c_str(), t.id, runs, runs == 1 ? "" : "s");
    if (t.nees_frames) {
      const std::string f = format("nees_%ld.png", t.id);
      drawConsistency(dir + "/" + f, consistencySeries(it->second, score.t0, &FramePoint::nees),
                      "NEES", score.tracking->nees->dof,
                      format("%s: NEES %.1f %% of %zu frames inside the 95 %% bounds", head.c_str(),
                             100 * t.nees_inside, t.nees_frames));
      files.push_back(f);
    }
    if (t.nis_frames) {
      const std::string f = format("nis_%ld.png", t.id);
      drawConsistency(dir + "/" + f, consistencySeries(it->second, score.t0, &FramePoint::nis),
                      "NIS", score.tracking->nis->dof,
                      format("%s: NIS %.1f %% of %zu frames inside the 95 %% bounds", head.c_str(),
                             100 * t.nis_inside, t.nis_frames));
      files.push_back(f);
    }
    const std::string f = format("rmse_%ld.png", t.id);
    drawRmse(dir + "/" + f, it->second, score.t0,
             format("%s: position RMSE per frame (mean %.3f m, max %.3f m)", head.c_str(),
                    t.rmse_mean, t.rmse_max));
    files.push_back(f);
    if (t.heading_frames) {
      const std::string h = format("heading_%ld.png", t.id);
      drawHeading(dir + "/" + h, it->second, score.t0,
                  format("%s: heading RMSE per frame (mean %.3f rad, max %.3f rad)", head.c_str(),
                         t.heading_rmse_mean, t.heading_rmse_max));
      files.push_back(h);
    }
  }
  return files;
}

bool drawLlrPlot(const std::string& existence_csv, const std::string& png,
                 const std::string& title) {
  std::ifstream in(existence_csv);
  if (!in) return false;
  std::string line;
  if (!std::getline(in, line)) return false;
  const std::vector<std::string> header = splitFields(line);
  auto column = [&](const char* name) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end())
      throw ConfigError(existence_csv + ": no column '" + name +
                        "' (expected t,frame,track,existence,llr,llr_confirm,llr_delete,status)");
    return std::size_t(it - header.begin());
  };
  const std::size_t ct = column("t"), ctrack = column("track"), cllr = column("llr"),
                    cconf = column("llr_confirm"), cdel = column("llr_delete");
  struct Track {
    std::vector<double> t, llr;
  };
  std::map<long, Track> tracks;
  std::vector<double> all_t, all_llr;
  double confirm = NAN, del = NAN, t0 = NAN;
  while (std::getline(in, line)) {
    const auto f = splitFields(line);
    if (f.size() < header.size()) continue;
    const double t = number(f[ct]), llr = number(f[cllr]);
    if (!std::isfinite(t0)) t0 = t;
    if (!std::isfinite(confirm)) confirm = number(f[cconf]);
    if (!std::isfinite(del)) del = number(f[cdel]);
    Track& tr = tracks[std::atol(f[ctrack].c_str())];
    tr.t.push_back(t - t0);
    tr.llr.push_back(llr);
    all_t.push_back(t - t0);
    all_llr.push_back(llr);
  }
  if (tracks.empty()) return false;
  all_llr.push_back(confirm);
  all_llr.push_back(del);
  plot::Plot p(kWidth, kHeight, plot::fitAxis("time (s)", all_t),
               plot::fitAxis("log-likelihood ratio", all_llr), title);
  // The thresholds in black and grey: every colour is some track's.
  if (std::isfinite(confirm))
    p.hline(confirm, plot::kBlack, 2, true, format("confirm %.2f", confirm));
  if (std::isfinite(del)) p.hline(del, plot::kGrey, 2, true, format("delete %.2f", del));
  // Named in the legend when few; with many, one thin line each and a count.
  const bool named = tracks.size() <= kLegendTracks;
  std::size_t i = 0;
  for (const auto& [id, tr] : tracks)
    p.line(tr.t, tr.llr, plot::colour(i++), named ? 2 : 1, false,
           named ? format("track %ld", id) : std::string());
  if (!named) p.note(format("%zu tracks, a colour each", tracks.size()), plot::kBlack);
  p.legend();
  if (!p.write(png)) throw DataError("cannot write '" + png + "'");
  return true;
}

}  // namespace pedtrack::cli
