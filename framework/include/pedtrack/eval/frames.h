#pragma once
// What every evaluation metric walks: frames holding truths and estimates (tracks or
// detections) as planar points, aligned by time.
#include <cmath>
#include <string>
#include <vector>

#include "pedtrack/eval/object_table.h"

namespace pedtrack::eval {

/// A truth or an estimate in one evaluated frame.
struct Object {
  long id = 0;
  double x = 0, y = 0;  ///< the compared position (fixed or sensor frame, see CoordFrame)
  /// Truths only: false when the person is too occluded to be required (visible_points below
  /// --min-visible). Such a truth may absorb an estimate but is never a miss.
  bool scored = true;
  const ObjectRow* row = nullptr;  ///< the source row (optional columns), null when none
  /// Truths: distance from the sensor (m; a leg's is its person's), NaN when unknown.
  double range = std::nan("");
};

struct EvalFrame {
  double t = 0;
  std::vector<Object> truths;
  std::vector<Object> estimates;
};

/// Objects that share one time stamp.
struct TimedObjects {
  double t = 0;
  std::vector<Object> objects;
};

enum class CoordFrame { Fixed, Sensor };  ///< x,y columns or sensor_x,sensor_y columns

/// The rows of `table` grouped by time (sliceByTime with `tolerance`), positioned by `frame`.
/// A row with 0 ≤ visible_points < min_visible is unscored (rows without the column are scored).
/// Throws ConfigError when the sensor-frame columns are missing or empty.
std::vector<TimedObjects> objectsByTime(const ObjectTable& table, CoordFrame frame,
                                        long min_visible = 1, double tolerance = 1e-4);
/// The objects point into the table's rows: a temporary table would leave them dangling.
std::vector<TimedObjects> objectsByTime(ObjectTable&& table, CoordFrame frame, long min_visible = 1,
                                        double tolerance = 1e-4) = delete;

/// The leg points of truth.csv rows (left_leg_x/y, right_leg_x/y; fixed frame): ids 2·id (left)
/// and 2·id + 1 (right), scored as their person is. Legs with empty columns are skipped.
/// Throws ConfigError when the table lacks the leg columns.
std::vector<TimedObjects> legsByTime(const ObjectTable& truth, long min_visible = 1,
                                     double tolerance = 1e-4);
std::vector<TimedObjects> legsByTime(ObjectTable&& truth, long min_visible = 1,
                                     double tolerance = 1e-4) = delete;

/// One frame per distinct time of either list (each sorted by t): the union of truth and
/// estimate times, where two times within `tolerance` seconds are one frame.
std::vector<EvalFrame> alignFrames(const std::vector<TimedObjects>& truths,
                                   const std::vector<TimedObjects>& estimates,
                                   double tolerance = 1e-4);

/// Planar distance between two objects.
double distance(const Object& a, const Object& b);

}  // namespace pedtrack::eval
