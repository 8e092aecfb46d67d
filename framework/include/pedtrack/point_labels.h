#pragma once
// Per-point label files: one int32 label for every point of Frame::cloud(), frame by frame, in
// the cloud's order. Two kinds share the container:
//   truth (`truth_points.bin`, written by the simulator): what each return hit;
//   run   (`point_labels.bin`, written by `pedtrack run --out`): what the stages made of it.
// `pedtrack eval` scores a run's labels against the truth point by point; `pedtrack render`
// colours points by them.
//
// Format (README "Outputs"): a gzip stream, little-endian. File header: 8 bytes "PTLABEL1",
// uint32 kind (1 truth, 2 run). Then per frame: uint64 frame index, float64 t (UNIX s),
// uint8 plane_valid, float64 nx, ny, nz, d (the frame's ground plane in the robot frame:
// truth = the true ground, run = the ground stage's estimate), uint32 n, then n int32 labels,
// then uint32 m and m × (int32 person id, float32 clearance m): truth files list every person
// the scan hit with the distance from its returns to the nearest return of anything else but
// the ground (capped at kClearanceCap); run files write m = 0.
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "pedtrack/frame.h"

namespace pedtrack {

enum class LabelKind : std::uint32_t { Truth = 1, Run = 2 };

/// Truth labels: what a simulated return hit.
namespace truth_label {
constexpr std::int32_t kGround = 0;
/// A person's id (> 0) is its own label; an object's id k (>= 1) is labelled -k.
inline std::int32_t object(int id) {
  return -id;
}
inline bool isPerson(std::int32_t l) {
  return l > 0;
}
inline bool isObject(std::int32_t l) {
  return l < 0;
}
}  // namespace truth_label

/// Run labels: what the stages made of a point. A cluster's index (>= 0) labels its points.
namespace run_label {
constexpr std::int32_t kUnclustered = -1;  ///< kept, but in no cluster
constexpr std::int32_t kGround = -2;       ///< PointLabel::Ground
constexpr std::int32_t kRemoved = -3;      ///< PointLabel::Removed
}  // namespace run_label

/// Truth files: how far a person is from everything else the scan hit.
struct PersonClearance {
  std::int32_t id = 0;
  float clearance = 0;  ///< m, 3D, between the true surfaces hit; at most kClearanceCap
};
constexpr double kClearanceCap = 1.0;

struct LabelFrame {
  std::uint64_t index = 0;
  double t = 0;
  GroundPlane plane;
  std::vector<std::int32_t> labels;
  std::vector<PersonClearance> people;  ///< truth files only
};

/// A run's labels of one processed frame: point_labels, then each cluster's index on its points.
LabelFrame runLabels(const Frame& frame);

/// Streams a label file; the data reaches the disk once a second of the frames' time (and at
/// least every 100 frames) and on close, so an interrupted run keeps what it produced. The same
/// frames always give the same bytes.
class LabelFileWriter {
 public:
  LabelFileWriter(const std::string& path, LabelKind kind);  ///< throws DataError
  ~LabelFileWriter();
  LabelFileWriter(const LabelFileWriter&) = delete;
  LabelFileWriter& operator=(const LabelFileWriter&) = delete;
  void write(const LabelFrame& f);
  void close();

 private:
  void put(const void* data, unsigned bytes);
  std::string path_;
  void* gz_ = nullptr;         // gzFile
  double last_flush_t_ = NAN;  // frame time of the last flush
  int unflushed_ = 0;          // frames written since
};

class LabelFileReader {
 public:
  /// Throws ConfigError when the file is missing or not a label file.
  explicit LabelFileReader(const std::string& path);
  ~LabelFileReader();
  LabelFileReader(const LabelFileReader&) = delete;
  LabelFileReader& operator=(const LabelFileReader&) = delete;
  LabelKind kind() const { return kind_; }
  /// The next frame, or false at the end. Throws DataError for a truncated frame.
  bool next(LabelFrame& f);

 private:
  bool get(void* data, unsigned bytes, bool eof_ok);
  std::string path_;
  void* gz_ = nullptr;
  LabelKind kind_ = LabelKind::Run;
  std::size_t frames_ = 0;
};

}  // namespace pedtrack
