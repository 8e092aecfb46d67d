#include "pedtrack/eval/frames.h"

#include <cmath>

#include "pedtrack/errors.h"

namespace pedtrack::eval {
namespace {

bool isScored(const ObjectRow& r, long min_visible) {
  return r.visible_points < 0 || r.visible_points >= min_visible;
}

}  // namespace

std::vector<TimedObjects> objectsByTime(const ObjectTable& table, CoordFrame frame,
                                        long min_visible, double tolerance) {
  const bool sensor = frame == CoordFrame::Sensor;
  if (sensor && !(table.hasColumn("sensor_x") && table.hasColumn("sensor_y")))
    throw ConfigError(table.path + ": --frame sensor needs the columns sensor_x and sensor_y");
  std::vector<TimedObjects> out;
  for (const TimeSlice& s : sliceByTime(table, tolerance)) {
    TimedObjects to{s.t, {}};
    for (const ObjectRow* r : s.rows) {
      Object o;
      o.id = r->id;
      o.x = sensor ? r->sensor_x : r->x;
      o.y = sensor ? r->sensor_y : r->y;
      if (!std::isfinite(o.x) || !std::isfinite(o.y))
        throw ConfigError(table.path + ": row at t=" + std::to_string(r->t) + ", id " +
                          std::to_string(r->id) +
                          (sensor ? ": sensor_x/sensor_y empty or not finite (--frame sensor)"
                                  : ": x/y not finite"));
      o.scored = isScored(*r, min_visible);
      o.row = r;
      o.range = std::hypot(r->sensor_x, r->sensor_y);
      to.objects.push_back(o);
    }
    out.push_back(std::move(to));
  }
  return out;
}

std::vector<TimedObjects> legsByTime(const ObjectTable& truth, long min_visible, double tolerance) {
  for (const char* c : {"left_leg_x", "left_leg_y", "right_leg_x", "right_leg_y"})
    if (!truth.hasColumn(c))
      throw ConfigError(truth.path + ": --legs needs the column '" + std::string(c) + "'");
  std::vector<TimedObjects> out;
  for (const TimeSlice& s : sliceByTime(truth, tolerance)) {
    TimedObjects to{s.t, {}};
    for (const ObjectRow* r : s.rows) {
      const double pts[2][2] = {{r->left_leg_x, r->left_leg_y}, {r->right_leg_x, r->right_leg_y}};
      for (int k = 0; k < 2; ++k) {
        if (!std::isfinite(pts[k][0]) || !std::isfinite(pts[k][1])) continue;
        Object o;
        o.id = 2 * r->id + k;
        o.x = pts[k][0];
        o.y = pts[k][1];
        o.scored = isScored(*r, min_visible);
        o.row = r;
        o.range = std::hypot(r->sensor_x, r->sensor_y);
        to.objects.push_back(o);
      }
    }
    out.push_back(std::move(to));
  }
  return out;
}

std::vector<EvalFrame> alignFrames(const std::vector<TimedObjects>& truths,
                                   const std::vector<TimedObjects>& estimates, double tolerance) {
  std::vector<EvalFrame> out;
  std::size_t i = 0, j = 0;
  while (i < truths.size() || j < estimates.size()) {
    const bool take_truth =
        i < truths.size() && (j == estimates.size() || truths[i].t <= estimates[j].t + tolerance);
    const bool take_est =
        j < estimates.size() && (i == truths.size() || estimates[j].t <= truths[i].t + tolerance);
    EvalFrame f;
    f.t = take_truth ? truths[i].t : estimates[j].t;
    if (take_truth) f.truths = truths[i++].objects;
    if (take_est) f.estimates = estimates[j++].objects;
    out.push_back(std::move(f));
  }
  return out;
}

double distance(const Object& a, const Object& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

}  // namespace pedtrack::eval
