#include "eval_range_bands.h"

#include <mrpt/core/format.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>

#include "pedtrack/errors.h"
#include "pedtrack/text.h"
#include "plot.h"
#include "report_format.h"

namespace pedtrack::cli {
namespace {

using mrpt::format;

std::string bandName(const eval::RangeBand& b) {
  return std::isfinite(b.to) ? format("%g - %g", b.from, b.to) : format("%g - inf", b.from);
}

double finiteOr(double v) {
  return std::isfinite(v) ? v : std::nan("");
}

/// Mean of finite values, with their min and max.
struct Stats {
  std::size_t n = 0;
  double sum = 0, min = INFINITY, max = -INFINITY;
  void add(double v) {
    if (!std::isfinite(v)) return;
    ++n, sum += v, min = std::min(min, v), max = std::max(max, v);
  }
  double mean() const { return n ? sum / double(n) : std::nan(""); }
};

std::string referenceLabel(const char* what, const Stats& s) {
  if (s.max - s.min < 1e-3) return format("true %s %.3f m", what, s.mean());
  return format("true %s mean %.3f m (%.3f-%.3f)", what, s.mean(), s.min, s.max);
}

}  // namespace

std::vector<double> parseRangeEdges(const std::string& text, const std::string& option) {
  std::vector<double> edges;
  for (const auto& item : splitFields(text, ',')) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(v) || v < 0)
      throw ConfigError("pedtrack eval: " + option + ": '" + item +
                        "' is not a distance >= 0 m (expected e.g. 0,10,20,30)");
    if (!edges.empty() && v <= edges.back())
      throw ConfigError("pedtrack eval: " + option + ": the edges must increase ('" + text + "')");
    edges.push_back(v);
  }
  return edges;
}

void ModelProbs::add(const ObjectTable& table) {
  const auto col = std::find(table.columns.begin(), table.columns.end(), "model_probs");
  if (col == table.columns.end()) return;
  const std::size_t c = std::size_t(col - table.columns.begin());
  std::ifstream in(table.path);
  if (!in) throw ConfigError(table.path + ": cannot open (no such file?)");
  std::string line;
  std::getline(in, line);  // the header
  long line_no = 1;
  std::size_t row = 0;
  // The data lines as readObjectTable counts them: blank lines are skipped.
  while (std::getline(in, line) && row < table.rows.size()) {
    ++line_no;
    if (trim(line).empty()) continue;
    const std::vector<std::string> f = splitFields(line, ',');
    const ObjectRow& r = table.rows[row++];
    if (c >= f.size() || f[c].empty()) continue;
    std::vector<double> p;
    for (const auto& item : splitFields(f[c], ';')) {
      char* end = nullptr;
      const double v = std::strtod(item.c_str(), &end);
      if (item.empty() || *end != '\0' || !std::isfinite(v))
        throw ConfigError(table.path + ":" + std::to_string(line_no) + ": column 'model_probs': '" +
                          f[c] + "' is not a ';'-separated list of numbers");
      p.push_back(v);
    }
    probs_[&r] = std::move(p);
  }
}

const std::vector<double>* ModelProbs::of(const ObjectRow& row) const {
  const auto it = probs_.find(&row);
  return it == probs_.end() ? nullptr : &it->second;
}

std::vector<std::string> modelColumns(const std::vector<std::string>& names, std::size_t models) {
  std::vector<std::string> out = names;
  for (std::size_t k = out.size(); k < models; ++k) out.push_back(format("prob_%zu", k + 1));
  return out;
}

std::string rangeBandsText(const eval::RangeBandReport& r, const std::vector<std::string>& names) {
  const std::vector<std::string> cols = modelColumns(names, r.models);
  std::size_t banded = 0;
  for (const auto& b : r.bands) banded += b.errors.pairs;
  std::string o = format(
      "\nBy distance from the sensor (the track row's sensor_x, sensor_y; %zu of %zu matches in a "
      "band)\n",
      banded, banded + r.unbanded);
  o += "  alpha, beta: mean, min and max of the matched track rows (m)\n";
  if (!cols.empty())
    o += "  model probabilities: mean over the matched track rows that have them\n";
  o += format("  %-12s %7s %10s %12s %8s %7s %7s %8s %7s %7s", "range (m)", "pairs", "RMSE (m)",
              "heading RMSE", "alpha", "min", "max", "beta", "min", "max");
  for (const auto& c : cols) o += format(" %9s", c.c_str());
  o += "\n";
  for (const auto& b : r.bands) {
    const auto& e = b.errors;
    o += format("  %-12s %7zu %10s %8s rad %8s %7s %7s %8s %7s %7s", bandName(b).c_str(), e.pairs,
                fixed(e.rmse()).c_str(), fixed(e.headingRmse()).c_str(),
                fixed(b.alphaMean(), 3).c_str(), fixed(finiteOr(b.alpha_min), 3).c_str(),
                fixed(finiteOr(b.alpha_max), 3).c_str(), fixed(b.betaMean(), 3).c_str(),
                fixed(finiteOr(b.beta_min), 3).c_str(), fixed(finiteOr(b.beta_max), 3).c_str());
    for (std::size_t k = 0; k < cols.size(); ++k) o += format(" %9s", fixed(b.probMean(k)).c_str());
    o += "\n";
  }
  return o;
}

std::string rangeBandsJson(const eval::RangeBandReport& r, const std::vector<std::string>& names) {
  const std::vector<std::string> cols = modelColumns(names, r.models);
  std::string models = "[", bands = "[";
  for (std::size_t k = 0; k < cols.size(); ++k)
    models += (k ? ", \"" : "\"") + jsonEscape(cols[k]) + "\"";
  for (std::size_t i = 0; i < r.bands.size(); ++i) {
    const auto& b = r.bands[i];
    const auto& e = b.errors;
    std::string probs = "{";
    for (std::size_t k = 0; k < cols.size(); ++k) {
      const double v = b.probMean(k);
      probs += (k ? ", \"" : "\"") + jsonEscape(cols[k]) +
               "\": " + (std::isfinite(v) ? format("%.10g", v) : std::string("null"));
    }
    Json j;
    j.num("from_m", b.from)
        .num("to_m", b.to)  // null: no upper edge
        .count("pairs", e.pairs)
        .num("position_rmse_m", e.rmse())
        .count("heading_pairs", e.heading_pairs)
        .num("heading_rmse_rad", e.headingRmse())
        .count("shape_rows", b.shape_rows)
        .num("alpha_mean_m", b.alphaMean())
        .num("alpha_min_m", finiteOr(b.alpha_min))
        .num("alpha_max_m", finiteOr(b.alpha_max))
        .num("beta_mean_m", b.betaMean())
        .num("beta_min_m", finiteOr(b.beta_min))
        .num("beta_max_m", finiteOr(b.beta_max))
        .count("prob_rows", b.prob_rows.empty() ? 0 : b.prob_rows[0])
        .raw("model_probs", probs + "}");
    bands += (i ? ",\n    " : "\n    ") + j.str();
  }
  Json top;
  top.count("unbanded", r.unbanded)
      .raw("models", models + "]")
      .raw("bands", bands + (r.bands.empty() ? "]" : "\n  ]"));
  return top.str();
}

std::size_t drawShapePlot(const std::string& png, const std::vector<eval::MatchedPair>& pairs,
                          const ShapeBounds& bounds) {
  std::vector<double> range, alpha, beta, all_y;
  Stats true_alpha, true_beta;
  for (const auto& p : pairs) {
    const ObjectRow* r = p.estimate.row;
    if (!r || !r->hasShape()) continue;
    const double d = std::hypot(r->sensor_x, r->sensor_y);
    if (!std::isfinite(d)) continue;
    range.push_back(d);
    alpha.push_back(r->alpha);
    beta.push_back(r->beta);
    if (p.truth.row && p.truth.row->hasShape())
      true_alpha.add(p.truth.row->alpha), true_beta.add(p.truth.row->beta);
  }
  all_y = alpha;
  all_y.insert(all_y.end(), beta.begin(), beta.end());
  for (double v : {true_alpha.mean(), true_beta.mean()}) all_y.push_back(v);
  if (bounds.given)
    for (double v : {bounds.alpha_min, bounds.alpha_max, bounds.beta_min, bounds.beta_max})
      all_y.push_back(v);
  plot::Plot p(900, 520, plot::fitAxis("distance from the sensor (m)", range, false, true),
               plot::fitAxis("semi-axis (m)", all_y, false, true),
               format("torso semi-axes of %zu matched track rows vs distance", range.size()));
  const cv::Scalar alpha_c = plot::kBlue, beta_c = plot::kRed;
  p.scatter(range, alpha, alpha_c, 2, "alpha (across the shoulders)");
  p.scatter(range, beta, beta_c, 2, "beta (front to back)");
  if (true_alpha.n)
    p.hline(true_alpha.mean(), alpha_c, 2, false, referenceLabel("alpha", true_alpha));
  if (true_beta.n) p.hline(true_beta.mean(), beta_c, 2, false, referenceLabel("beta", true_beta));
  if (bounds.given) {
    p.hline(bounds.alpha_min, alpha_c, 1, true,
            format("alpha bounds %.3f-%.3f m", bounds.alpha_min, bounds.alpha_max));
    p.hline(bounds.alpha_max, alpha_c, 1, true);
    p.hline(bounds.beta_min, beta_c, 1, true,
            format("beta bounds %.3f-%.3f m", bounds.beta_min, bounds.beta_max));
    p.hline(bounds.beta_max, beta_c, 1, true);
  }
  if (range.empty())
    p.note("no matched track row has alpha, beta and sensor_x, sensor_y", plot::kBlack);
  p.legend();
  if (!p.write(png)) throw DataError("cannot write '" + png + "'");
  return range.size();
}

}  // namespace pedtrack::cli
