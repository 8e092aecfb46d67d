#pragma once
// The rows of tracks.csv, truth.csv or detections.csv, indexed for drawing: the rows of one
// frame, and each object's path in time order.
#include <map>
#include <vector>

#include "pedtrack/eval/object_table.h"

namespace pedtrack::render {

/// The rows that belong to one frame, and the table's own time for that frame.
struct FrameRows {
  std::vector<const ObjectRow*> rows;
  double t = kNaN;  ///< the rows' `t` (NaN when the frame has no rows)
};

class ObjectIndex {
 public:
  ObjectIndex() = default;
  explicit ObjectIndex(std::vector<ObjectRow> rows);
  ObjectIndex(const ObjectIndex&) = delete;  // rows are referenced by pointer
  ObjectIndex& operator=(const ObjectIndex&) = delete;

  /// Rows whose `t` is within `tolerance` of `t`; when none is, rows whose `frame` equals
  /// `frame` (files written on another clock, e.g. simulated time, still line up by index).
  FrameRows at(double t, long frame, double tolerance = 1e-4) const;
  /// Every object's rows in time order, by id.
  const std::map<long, std::vector<const ObjectRow*>>& paths() const { return paths_; }
  /// The rows of `path` with t in [t0, t1].
  static std::vector<const ObjectRow*> window(const std::vector<const ObjectRow*>& path, double t0,
                                              double t1);
  const std::vector<ObjectRow>& rows() const { return rows_; }
  bool empty() const { return rows_.empty(); }

 private:
  std::vector<ObjectRow> rows_;
  std::vector<const ObjectRow*> by_time_;
  std::multimap<long, const ObjectRow*> by_frame_;
  std::map<long, std::vector<const ObjectRow*>> paths_;
};

}  // namespace pedtrack::render
