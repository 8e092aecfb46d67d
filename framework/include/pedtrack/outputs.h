#pragma once
// The output contract (docs/outputs.md): tracks.csv, detections.csv, clusters.csv, run.json.
#include <fstream>
#include <string>
#include <vector>

#include "pedtrack/frame.h"
#include "pedtrack/stage_stats.h"

namespace pedtrack {

/// A CSV file streamed row by row: the header on open, rows on disk at least once a second and
/// when closed, so an interrupted run keeps what it produced.
class CsvStream {
 public:
  CsvStream(const std::string& path, const char* header);
  ~CsvStream();
  void close();
  /// Puts every row written so far on disk now (a live run, each frame).
  void flush() { out_.flush(); }

 protected:
  /// Call after the rows of a frame: flushes when a second has passed.
  void frameWritten();
  std::ofstream out_;

 private:
  std::string path_;
  double last_flush_ = 0;
};

/// Streams tracks.csv: one row per reported track per frame.
class TracksCsvWriter : public CsvStream {
 public:
  explicit TracksCsvWriter(const std::string& path) : CsvStream(path, header()) {}
  /// One row per track; a track whose position, velocity or covariance is not finite (a
  /// tracker that diverged) is left out and counted: no row ever holds a NaN or an infinity.
  void write(const Frame& frame);
  std::size_t nonfiniteRows() const { return nonfinite_; }
  static const char* header();

 private:
  std::size_t nonfinite_ = 0;
};

/// Streams detections.csv: one row per detection per frame (`header()`). The pipeline creates it
/// on the first frame with detections, so a pipeline without a classifier leaves no empty file.
class DetectionsCsvWriter : public CsvStream {
 public:
  explicit DetectionsCsvWriter(const std::string& path) : CsvStream(path, header()) {}
  void write(const Frame& frame);
  static const char* header();
};

/// Streams clusters.csv: one row per cluster per frame, `header()` then one column per feature
/// named by the first frame with clusters (Frame::cluster_feature_names). Created, like
/// detections.csv, on the first frame that has clusters.
class ClustersCsvWriter : public CsvStream {
 public:
  ClustersCsvWriter(const std::string& path, const Frame& first);
  void write(const Frame& frame);
  static const char* header();

 private:
  std::vector<std::string> features_;
  std::vector<int> column_;  // feature k of the header is value column_[k] of the frame's list
  const std::vector<std::string>* mapped_names_ = nullptr;
  bool mapped_ = false;
};

struct RunSummary {
  std::string pipeline;
  std::string input;
  std::size_t frames_read = 0;
  std::size_t frames_processed = 0;
  std::size_t frames_failed = 0;   ///< frames where a stage threw
  std::size_t frames_skipped = 0;  ///< frames the FrameGuard refused (time or pose unusable)
  /// What the FrameGuard found wrong in the input, every kind with its count.
  std::vector<std::pair<std::string, long>> input_warnings;
  std::size_t nonfinite_track_rows = 0;  ///< track rows left out of tracks.csv: not finite
  std::size_t entries_skipped = 0;       ///< bad input entries skipped by the source
  bool live = false;                     ///< the source was a live device, read on its own thread
  std::size_t frames_dropped = 0;        ///< live: frames dropped because the stages fell behind
  std::size_t frames_recorded = 0;       ///< frames written by --record
  /// Per processed frame: from the source handing it over to its outputs written (ms).
  StageStats latency{"latency", ""};
  double wall_time_s = 0;
  std::string status = "ok";  ///< ok | error | interrupted
  std::string error;
  std::vector<StageStats> stages;
};

void writeRunJson(const std::string& path, const RunSummary& s);
std::string jsonEscape(const std::string& s);

}  // namespace pedtrack
