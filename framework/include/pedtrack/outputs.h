#pragma once
// The output contract of DESIGN.md: tracks.csv and run.json.
#include <fstream>
#include <string>
#include <vector>

#include "pedtrack/frame.h"
#include "pedtrack/stage_stats.h"

namespace pedtrack {

/// Streams tracks.csv: one row per reported track per frame. Rows reach the disk at least once a
/// second and when the writer is closed, so an interrupted run keeps what it produced.
class TracksCsvWriter {
 public:
  explicit TracksCsvWriter(const std::string& path);
  ~TracksCsvWriter();
  void write(const Frame& frame);
  void close();
  static const char* header();

 private:
  std::ofstream out_;
  std::string path_;
  double last_flush_ = 0;
};

struct RunSummary {
  std::string pipeline;
  std::string input;
  std::size_t frames_read = 0;
  std::size_t frames_processed = 0;
  std::size_t frames_failed = 0;    ///< frames where a stage threw
  std::size_t entries_skipped = 0;  ///< bad input entries skipped by the source
  double wall_time_s = 0;
  std::string status = "ok";  ///< ok | error | interrupted
  std::string error;
  std::vector<StageStats> stages;
};

void writeRunJson(const std::string& path, const RunSummary& s);
std::string jsonEscape(const std::string& s);

}  // namespace pedtrack
