#include "pedtrack/point_labels.h"

#include <zlib.h>

#include <cmath>
#include <cstring>

#include "pedtrack/errors.h"

namespace pedtrack {
namespace {

constexpr char kMagic[8] = {'P', 'T', 'L', 'A', 'B', 'E', 'L', '1'};

// Flushed once the data's own clock moved a second (either way: a clock reset) or this many
// frames went by (timestamps that never advance).
constexpr int kFlushFrames = 100;

}  // namespace

LabelFrame runLabels(const Frame& frame) {
  LabelFrame out;
  out.index = frame.index;
  out.t = frame.t;
  out.plane = frame.ground;
  const std::size_t n = frame.cloud().size();
  out.labels.assign(n, run_label::kUnclustered);
  if (frame.point_labels.size() == n)
    for (std::size_t i = 0; i < n; ++i) {
      if (frame.point_labels[i] == PointLabel::Ground) out.labels[i] = run_label::kGround;
      if (frame.point_labels[i] == PointLabel::Removed) out.labels[i] = run_label::kRemoved;
    }
  for (std::size_t c = 0; c < frame.clusters.size(); ++c)
    for (std::uint32_t i : frame.clusters[c].indices)
      if (i < n) out.labels[i] = static_cast<std::int32_t>(c);
  return out;
}

LabelFileWriter::LabelFileWriter(const std::string& path, LabelKind kind) : path_(path) {
  gzFile f = gzopen(path.c_str(), "wb1");  // fastest level: labels compress well anyway
  if (!f) throw DataError(path + ": cannot open for writing");
  gz_ = f;
  put(kMagic, sizeof kMagic);
  const auto k = static_cast<std::uint32_t>(kind);
  put(&k, sizeof k);
}

LabelFileWriter::~LabelFileWriter() {
  try {
    close();
  } catch (const std::exception&) {  // a destructor must not throw; close() reports it
  }
}

void LabelFileWriter::put(const void* data, unsigned bytes) {
  if (bytes && gzwrite(static_cast<gzFile>(gz_), data, bytes) != int(bytes))
    throw DataError(path_ + ": write failed");
}

void LabelFileWriter::write(const LabelFrame& f) {
  const std::uint8_t valid = f.plane.valid ? 1 : 0;
  const double plane[4] = {f.plane.nx, f.plane.ny, f.plane.nz, f.plane.d};
  const auto n = static_cast<std::uint32_t>(f.labels.size());
  put(&f.index, sizeof f.index);
  put(&f.t, sizeof f.t);
  put(&valid, 1);
  put(plane, sizeof plane);
  put(&n, sizeof n);
  put(f.labels.data(), n * sizeof(std::int32_t));
  const auto m = static_cast<std::uint32_t>(f.people.size());
  put(&m, sizeof m);
  for (const PersonClearance& p : f.people) {
    put(&p.id, sizeof p.id);
    put(&p.clearance, sizeof p.clearance);
  }
  // By the frames' time, not the wall clock: a replay then writes the same bytes however fast
  // the machine (two runs of one simulation compare equal), and a live run, whose frames come
  // at the sensor's pace, still reaches the disk about once a second.
  if (std::isnan(last_flush_t_)) last_flush_t_ = f.t;
  if (std::abs(f.t - last_flush_t_) >= 1.0 || ++unflushed_ >= kFlushFrames) {
    gzflush(static_cast<gzFile>(gz_), Z_SYNC_FLUSH);
    last_flush_t_ = f.t;
    unflushed_ = 0;
  }
}

void LabelFileWriter::close() {
  if (!gz_) return;
  const int rc = gzclose(static_cast<gzFile>(gz_));
  gz_ = nullptr;
  if (rc != Z_OK) throw DataError(path_ + ": writing failed when closing (disk full?)");
}

LabelFileReader::LabelFileReader(const std::string& path) : path_(path) {
  gzFile f = gzopen(path.c_str(), "rb");
  if (!f) throw ConfigError(path + ": cannot open");
  gz_ = f;
  char header[12] = {};  // magic, then the kind
  std::uint32_t kind = 0;
  const bool whole = gzread(f, header, sizeof header) == int(sizeof header);
  std::memcpy(&kind, header + 8, sizeof kind);
  if (!whole || std::memcmp(header, kMagic, sizeof kMagic) != 0 || (kind != 1 && kind != 2)) {
    // The destructor does not run for a constructor that throws (LeakSanitizer found it).
    gzclose(f);
    gz_ = nullptr;
    throw ConfigError(path +
                      ": not a pedtrack point label file (truth_points.bin or "
                      "point_labels.bin)");
  }
  kind_ = static_cast<LabelKind>(kind);
}

LabelFileReader::~LabelFileReader() {
  if (gz_) gzclose(static_cast<gzFile>(gz_));
}

bool LabelFileReader::get(void* data, unsigned bytes, bool eof_ok) {
  const int got = gzread(static_cast<gzFile>(gz_), data, bytes);
  if (got == int(bytes)) return true;
  if (got == 0 && eof_ok) return false;
  throw DataError(path_ + ": frame " + std::to_string(frames_) + " truncated");
}

bool LabelFileReader::next(LabelFrame& f) {
  if (!get(&f.index, sizeof f.index, true)) return false;
  std::uint8_t valid = 0;
  double plane[4];
  std::uint32_t n = 0;
  get(&f.t, sizeof f.t, false);
  get(&valid, 1, false);
  get(plane, sizeof plane, false);
  get(&n, sizeof n, false);
  if (n > (1u << 28))
    throw DataError(path_ + ": frame " + std::to_string(frames_) + ": " + std::to_string(n) +
                    " points is not plausible");
  f.plane.valid = valid != 0;
  f.plane.nx = plane[0];
  f.plane.ny = plane[1];
  f.plane.nz = plane[2];
  f.plane.d = plane[3];
  f.labels.resize(n);
  if (n) get(f.labels.data(), n * sizeof(std::int32_t), false);
  std::uint32_t m = 0;
  get(&m, sizeof m, false);
  if (m > (1u << 24))
    throw DataError(path_ + ": frame " + std::to_string(frames_) + ": " + std::to_string(m) +
                    " people is not plausible");
  f.people.resize(m);
  for (PersonClearance& p : f.people) {
    get(&p.id, sizeof p.id, false);
    get(&p.clearance, sizeof p.clearance, false);
  }
  ++frames_;
  return true;
}

}  // namespace pedtrack
