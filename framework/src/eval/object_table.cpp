#include "pedtrack/eval/object_table.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "pedtrack/errors.h"
#include "pedtrack/text.h"

namespace pedtrack {

bool ObjectTable::hasColumn(const std::string& name) const {
  return std::find(columns.begin(), columns.end(), name) != columns.end();
}

namespace {

ObjectTable readTable(const std::string& path, bool id_required) {
  std::ifstream in(path);
  if (!in) throw ConfigError(path + ": cannot open (no such file?)");
  ObjectTable table;
  table.path = path;
  std::string line;
  if (!std::getline(in, line)) throw ConfigError(path + ": empty file (expected a CSV header)");
  table.columns = splitFields(line);
  std::map<std::string, int> col;
  for (std::size_t i = 0; i < table.columns.size(); ++i) col[table.columns[i]] = int(i);
  auto index = [&](const char* name) { return col.count(name) ? col[name] : -1; };
  const int c_id = col.count("track") ? col["track"] : index("id");
  for (const char* req : {"t", "x", "y"})
    if (index(req) < 0) throw ConfigError(path + ": header lacks required column '" + req + "'");
  if (c_id < 0 && id_required)
    throw ConfigError(path + ": header lacks an id column ('track' or 'id')");

  long line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    if (trim(line).empty()) continue;
    const auto f = splitFields(line);
    auto where = [&](int c) {
      return path + ":" + std::to_string(line_no) + ": column '" + table.columns[c] + "'";
    };
    auto real = [&](int c, double& out, bool required) {
      if (c < 0 || c >= int(f.size()) || f[c].empty()) {
        if (required) throw ConfigError(where(c < 0 ? 0 : c) + ": value missing");
        return;
      }
      char* end = nullptr;
      const double v = std::strtod(f[c].c_str(), &end);
      if (end == f[c].c_str() || *end != '\0')
        throw ConfigError(where(c) + ": '" + f[c] + "' is not a number");
      if (!std::isfinite(v)) throw ConfigError(where(c) + ": '" + f[c] + "' is not finite");
      out = v;
    };
    auto integer = [&](int c, long& out, bool required) {
      double v = kNaN;
      real(c, v, required);
      if (std::isnan(v)) return;
      if (v != std::floor(v) || std::abs(v) > 9e15)
        throw ConfigError(where(c) + ": '" + f[c] + "' is not an integer");
      out = static_cast<long>(v);
    };
    if (f.size() != table.columns.size())
      throw ConfigError(path + ":" + std::to_string(line_no) + ": expected " +
                        std::to_string(table.columns.size()) + " columns, found " +
                        std::to_string(f.size()));
    ObjectRow r;
    real(index("t"), r.t, true);
    integer(index("frame"), r.frame, false);
    if (c_id >= 0) integer(c_id, r.id, true);
    real(index("x"), r.x, true);
    real(index("y"), r.y, true);
    real(index("sensor_x"), r.sensor_x, false);
    real(index("sensor_y"), r.sensor_y, false);
    real(index("yaw"), r.yaw, false);
    real(index("vx"), r.vx, false);
    real(index("vy"), r.vy, false);
    real(index("alpha"), r.alpha, false);
    real(index("beta"), r.beta, false);
    real(index("cov_xx"), r.cov_xx, false);
    real(index("cov_xy"), r.cov_xy, false);
    real(index("cov_yy"), r.cov_yy, false);
    real(index("nis"), r.nis, false);
    real(index("score"), r.score, false);
    real(index("height"), r.height, false);
    integer(index("visible_points"), r.visible_points, false);
    integer(index("cluster"), r.cluster, false);
    real(index("left_leg_x"), r.left_leg_x, false);
    real(index("left_leg_y"), r.left_leg_y, false);
    real(index("right_leg_x"), r.right_leg_x, false);
    real(index("right_leg_y"), r.right_leg_y, false);
    const int c_status = index("status");
    if (c_status >= 0 && c_status < int(f.size())) r.status = f[c_status];
    table.rows.push_back(std::move(r));
  }
  return table;
}

}  // namespace

ObjectTable readObjectTable(const std::string& path) {
  return readTable(path, true);
}

ObjectTable readDetectionTable(const std::string& path) {
  ObjectTable table = readTable(path, false);
  if (table.hasColumn("track") || table.hasColumn("id")) return table;
  // detections.csv writes each frame's detections together: number them within their frame.
  long next = 0;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    if (i > 0 && std::fabs(table.rows[i].t - table.rows[i - 1].t) > 1e-4) next = 0;
    table.rows[i].id = next++;
  }
  return table;
}

std::vector<TimeSlice> sliceByTime(const ObjectTable& table, double tolerance) {
  std::vector<const ObjectRow*> sorted;
  sorted.reserve(table.rows.size());
  for (const auto& r : table.rows) sorted.push_back(&r);
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const ObjectRow* a, const ObjectRow* b) { return a->t < b->t; });
  std::vector<TimeSlice> out;
  for (const ObjectRow* r : sorted) {
    if (out.empty() || r->t - out.back().t > tolerance) out.push_back({r->t, {}});
    out.back().rows.push_back(r);
  }
  return out;
}

}  // namespace pedtrack
