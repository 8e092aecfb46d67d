#pragma once
// existence.csv, a tracker's side output (P4 Fig. 22): every track's existence probability and
// LLR each frame, tentative ones included, with the confirmation and deletion thresholds.
// Columns: t,frame,track,existence,llr,llr_confirm,llr_delete,status.
#include "pedtrack/outputs.h"

namespace pedtrack::track {

class ExistenceLog : public CsvStream {
 public:
  explicit ExistenceLog(const std::string& path) : CsvStream(path, header()) {}
  static const char* header();
  void row(double t, std::size_t frame, long track, double existence, double llr_confirm,
           double llr_delete, const char* status);
  /// After the rows of a frame.
  void endFrame() { frameWritten(); }
};

}  // namespace pedtrack::track
