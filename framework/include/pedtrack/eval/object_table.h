#pragma once
// Reads the per-object CSV files of the output contract: tracks.csv (id column `track`) and the
// simulator's truth.csv (id column `id`). Columns are found by name, so optional columns may be
// absent or empty; a value that is present must parse, or the file is rejected with one line
// naming file, line and column (ConfigError, exit 2).
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace pedtrack {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// One row: an object (track or true person) at one time. Optional fields are NaN (or -1 for
/// integers) when the file lacks the column or leaves it empty.
struct ObjectRow {
  double t = 0;                                        ///< UNIX seconds
  long frame = -1;                                     ///< frame index, -1 when absent
  long id = 0;                                         ///< `track` in tracks.csv, `id` in truth.csv
  double x = 0, y = 0;                                 ///< m, fixed frame
  double sensor_x = kNaN, sensor_y = kNaN;             ///< m, sensor frame at t
  double yaw = kNaN;                                   ///< rad
  double vx = kNaN, vy = kNaN;                         ///< m/s
  double alpha = kNaN, beta = kNaN;                    ///< torso semi-axes, m
  double cov_xx = kNaN, cov_xy = kNaN, cov_yy = kNaN;  ///< position covariance, m²
  double nis = kNaN;  ///< normalized innovation squared of this frame's update
  double score = kNaN;
  std::string status;
  /// `cluster`: detections.csv / clusters.csv the cluster's index in its frame; tracks.csv the
  /// cluster whose detection updated the track that frame. -1 when absent or empty.
  long cluster = -1;
  // truth.csv only
  double height = kNaN;
  long visible_points = -1;
  double left_leg_x = kNaN, left_leg_y = kNaN, right_leg_x = kNaN, right_leg_y = kNaN;

  bool hasShape() const { return std::isfinite(alpha) && std::isfinite(beta); }
  bool hasCov() const {
    return std::isfinite(cov_xx) && std::isfinite(cov_xy) && std::isfinite(cov_yy);
  }
};

struct ObjectTable {
  std::string path;
  std::vector<std::string> columns;  ///< header names in file order
  std::vector<ObjectRow> rows;       ///< in file order
  bool hasColumn(const std::string& name) const;
};

/// Reads tracks.csv or truth.csv. Required columns: t, x, y and one of `track` / `id`.
/// Throws ConfigError on a missing file, missing required column or unparsable value.
ObjectTable readObjectTable(const std::string& path);

/// Reads detections.csv (header `t,frame,x,y,sensor_x,sensor_y,score,yaw,alpha,beta,cluster,...`):
/// like readObjectTable, but the id column is optional; without one, a row's id is its position
/// among the rows of its frame (consecutive rows with the same t).
ObjectTable readDetectionTable(const std::string& path);

/// Rows grouped by time: consecutive distinct `t` values (rows sorted by t first, stable).
/// Two times closer than `tolerance` seconds are the same frame.
struct TimeSlice {
  double t = 0;
  std::vector<const ObjectRow*> rows;
};
std::vector<TimeSlice> sliceByTime(const ObjectTable& table, double tolerance = 1e-4);

}  // namespace pedtrack
