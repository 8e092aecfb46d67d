#include "montecarlo_compare.h"

#include <mrpt/core/format.h>

#include <algorithm>
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <filesystem>
#include <fstream>
#include <set>

#include "pedtrack/errors.h"
#include "pedtrack/text.h"
#include "plot.h"

namespace pedtrack::cli {
namespace {

using mrpt::format;
namespace fs = std::filesystem;
namespace pt = boost::property_tree;
constexpr int kPanelWidth = 900, kPanelHeight = 400;

/// A number of the tree at `path`; NaN when absent or null.
double number(const pt::ptree& tree, const char* path) {
  const auto v = tree.get_optional<double>(path);
  return v ? *v : std::nan("");
}

double parseNumber(const std::string& s) {
  if (s.empty()) return std::nan("");
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  return end == s.c_str() ? std::nan("") : v;
}

/// consistency.csv's rows by truth id; nothing when the file is absent.
std::map<long, CompareCurve> readCurves(const std::string& path) {
  std::map<long, CompareCurve> curves;
  std::ifstream in(path);
  if (!in) return curves;
  std::string line;
  if (!std::getline(in, line)) return curves;
  const std::vector<std::string> header = splitFields(line);
  auto column = [&](const char* name, bool required) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end() && required)
      throw ConfigError(path + ": no column '" + name + "' (not a montecarlo consistency.csv?)");
    return it == header.end() ? -1 : int(it - header.begin());
  };
  const int cid = column("truth_id", true), cframe = column("frame", true), ct = column("t", true),
            crmse = column("rmse", true), chead = column("heading_rmse", false);
  long line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line == "\r") continue;
    const std::vector<std::string> f = splitFields(line);
    if (f.size() != header.size())
      throw ConfigError(format("%s:%ld: expected %zu columns, found %zu", path.c_str(), line_no,
                               header.size(), f.size()));
    CompareCurve& c = curves[std::atol(f[cid].c_str())];
    c.frame.push_back(std::size_t(std::atol(f[cframe].c_str())));
    c.t.push_back(parseNumber(f[ct]));
    c.rmse.push_back(parseNumber(f[crmse]));
    c.heading.push_back(chead >= 0 ? parseNumber(f[chead]) : std::nan(""));
  }
  return curves;
}

std::string cell(double v, int decimals) {
  return std::isfinite(v) ? format("%.*f", decimals, v) : std::string("-");
}

/// The curve's values with a NaN wherever frames are skipped (the line breaks there).
void withGaps(const CompareCurve& c, const std::vector<double>& values, double t0,
              std::vector<double>& t, std::vector<double>& v) {
  for (std::size_t i = 0; i < c.t.size(); ++i) {
    if (i && c.frame[i] > c.frame[i - 1] + 1) t.push_back(NAN), v.push_back(NAN);
    t.push_back(c.t[i] - t0);
    v.push_back(values[i]);
  }
}

}  // namespace

CompareEntry readMonteCarloDir(const std::string& dir, const std::string& label) {
  const std::string where = "pedtrack montecarlo --compare: '" + dir + "': ";
  if (!fs::is_directory(dir)) throw ConfigError(where + "no such directory");
  const std::string json = dir + "/montecarlo.json";
  if (!fs::is_regular_file(json))
    throw ConfigError(where + "no montecarlo.json (not a `pedtrack montecarlo` output?)");
  pt::ptree tree;
  try {
    pt::read_json(json, tree);
  } catch (const pt::json_parser_error& e) {
    throw ConfigError(where + "montecarlo.json: " + e.message() + " (line " +
                      std::to_string(e.line()) + ")");
  }
  if (tree.get<std::string>("mode", "") != "montecarlo")
    throw ConfigError(where + "montecarlo.json has no \"mode\": \"montecarlo\"");
  CompareEntry e;
  e.label = label;
  e.dir = dir;
  e.runs = tree.get<std::size_t>("runs_scored", 0);
  e.position_rmse_m = number(tree, "tracking.errors.position_rmse_m");
  e.heading_rmse_rad = number(tree, "tracking.errors.heading_rmse_rad");
  e.axis_rmse_rad = number(tree, "tracking.errors.axis_rmse_rad");  // absent in older results
  e.mota = number(tree, "tracking.clear_mot.mota");
  if (const auto s = tree.get_optional<std::size_t>("tracking.clear_mot.id_switches"))
    e.id_switches = *s;
  e.t0 = number(tree, "t0");
  e.curves = readCurves(dir + "/consistency.csv");
  return e;
}

std::string compareMarkdown(const std::vector<CompareEntry>& entries) {
  std::vector<std::vector<std::string>> rows = {{"label", "position RMSE (mm)",
                                                 "heading RMSE (rad)", "axis RMSE (rad)", "MOTA",
                                                 "ID switches", "runs"}};
  for (const auto& e : entries)
    rows.push_back({e.label, cell(1000 * e.position_rmse_m, 1), cell(e.heading_rmse_rad, 4),
                    cell(e.axis_rmse_rad, 4), cell(e.mota, 4),
                    e.id_switches ? std::to_string(*e.id_switches) : "-", std::to_string(e.runs)});
  std::vector<std::size_t> width(rows[0].size(), 3);
  for (const auto& r : rows)
    for (std::size_t c = 0; c < r.size(); ++c) width[c] = std::max(width[c], r[c].size());
  auto line = [&](const std::vector<std::string>& r) {
    std::string o = "|";
    for (std::size_t c = 0; c < r.size(); ++c) {
      // The label left-aligned, the numbers right-aligned.
      const std::string pad(width[c] - r[c].size(), ' ');
      o += " " + (c == 0 ? r[c] + pad : pad + r[c]) + " |";
    }
    return o + "\n";
  };
  std::string o = line(rows[0]) + "|";
  for (std::size_t c = 0; c < width.size(); ++c)
    o += (c == 0 ? " :" + std::string(width[c] - 1, '-')
                 : " " + std::string(width[c] - 1, '-') + ":") +
         " |";
  o += "\n";
  for (std::size_t i = 1; i < rows.size(); ++i) o += line(rows[i]);
  return o;
}

std::vector<std::string> drawCompareErrors(const std::string& dir,
                                           const std::vector<CompareEntry>& entries) {
  std::set<long> ids;
  double t0 = INFINITY;
  for (const auto& e : entries) {
    if (std::isfinite(e.t0)) t0 = std::min(t0, e.t0);
    for (const auto& [id, c] : e.curves) {
      ids.insert(id);
      if (!std::isfinite(e.t0))
        for (double t : c.t) t0 = std::min(t0, t);
    }
  }
  std::vector<std::string> files;
  if (ids.empty()) return files;
  for (long id : ids) {
    struct Series {
      std::vector<double> t, d, th, h;
    };
    std::vector<Series> series(entries.size());
    std::vector<double> all_t, all_d, all_h;
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const auto it = entries[i].curves.find(id);
      if (it == entries[i].curves.end()) continue;
      withGaps(it->second, it->second.rmse, t0, series[i].t, series[i].d);
      withGaps(it->second, it->second.heading, t0, series[i].th, series[i].h);
      all_t.insert(all_t.end(), series[i].t.begin(), series[i].t.end());
      all_d.insert(all_d.end(), series[i].d.begin(), series[i].d.end());
      all_h.insert(all_h.end(), series[i].h.begin(), series[i].h.end());
    }
    const plot::Axis x = plot::fitAxis("time (s)", all_t);
    plot::Plot top(kPanelWidth, kPanelHeight, x,
                   plot::fitAxis("distance error (m)", all_d, false, true),
                   format("truth %ld: distance error per frame (RMSE over the runs)", id));
    plot::Plot bottom(kPanelWidth, kPanelHeight, x,
                      plot::fitAxis("heading error (rad)", all_h, false, true),
                      format("truth %ld: heading error per frame (RMSE over the runs)", id));
    bool any_heading = false;
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const cv::Scalar c = plot::colour(i);
      top.line(series[i].t, series[i].d, c, 2, false, entries[i].label);
      const bool has = std::any_of(series[i].h.begin(), series[i].h.end(),
                                   [](double v) { return std::isfinite(v); });
      any_heading |= has;
      bottom.line(series[i].th, series[i].h, c, 2, false,
                  entries[i].label + (has ? "" : " (no yaw)"));
    }
    if (!any_heading) bottom.note("no track has yaw", plot::kBlack);
    top.legend();
    bottom.legend();
    const std::string f = format("errors_%ld.png", id);
    if (!plot::writeStacked({&top, &bottom}, dir + "/" + f))
      throw DataError("cannot write '" + dir + "/" + f + "'");
    files.push_back(f);
  }
  return files;
}

}  // namespace pedtrack::cli
