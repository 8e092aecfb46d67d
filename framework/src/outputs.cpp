#include "pedtrack/outputs.h"

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>

#include "pedtrack/errors.h"
#include "pedtrack/version.h"

namespace pedtrack {

static double monotonicSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// A fixed-frame point seen from the sensor at time t (at the sensor's own height, so a level
// sensor gives the exact planar coordinates).
static void toSensorFrame(const Frame& f, double x, double y, double& sx, double& sy) {
  double sz = 0;
  f.sensor_pose.inverseComposePoint(x, y, f.sensor_pose.z(), sx, sy, sz);
}

// snprintf's count, clamped to what fits the buffer (an absurd value must not read past it).
static void writeClamped(std::ofstream& out, const char* buf, int n, std::size_t size) {
  if (n > 0) out.write(buf, std::min<std::streamsize>(n, std::streamsize(size) - 1));
}

// The z,h,w,l columns: a 3D box when one is known, else four empty fields.
static void writeBox(std::ofstream& out, const Box3& b) {
  if (!b.known() || !std::isfinite(b.z + b.h + b.w + b.l)) {
    out << ",,,,";
    return;
  }
  char buf[128];
  writeClamped(out, buf, std::snprintf(buf, sizeof buf, ",%.4f,%.4f,%.4f,%.4f", b.z, b.h, b.w, b.l),
               sizeof buf);
}

// Rows reach the disk at least once a second, so an interrupted run keeps what it produced.
CsvStream::CsvStream(const std::string& path, const char* header) : out_(path), path_(path) {
  if (!out_) throw DataError(path + ": cannot open for writing");
  out_ << header << '\n';
  out_.flush();
  last_flush_ = monotonicSeconds();
}

CsvStream::~CsvStream() {
  close();
}

void CsvStream::frameWritten() {
  const double now = monotonicSeconds();
  if (now - last_flush_ > 1.0) {
    out_.flush();
    last_flush_ = now;
  }
}

void CsvStream::close() {
  if (out_.is_open()) {
    out_.flush();
    out_.close();
  }
}

const char* TracksCsvWriter::header() {
  return "t,frame,track,x,y,sensor_x,sensor_y,yaw,vx,vy,alpha,beta,cov_xx,cov_xy,cov_yy,score,"
         "model_probs,status,nis,cluster,z,h,w,l";
}

void TracksCsvWriter::write(const Frame& f) {
  char buf[512];
  for (const Track& tr : f.tracks) {
    const bool finite = std::isfinite(tr.x) && std::isfinite(tr.y) && std::isfinite(tr.vx) &&
                        std::isfinite(tr.vy) && std::isfinite(tr.yaw) && std::isfinite(tr.score) &&
                        (!tr.has_shape || (std::isfinite(tr.alpha) && std::isfinite(tr.beta))) &&
                        (!tr.has_cov || (std::isfinite(tr.cov_xx) && std::isfinite(tr.cov_xy) &&
                                         std::isfinite(tr.cov_yy)));
    if (!finite) {
      ++nonfinite_;
      continue;
    }
    double sx = 0, sy = 0;
    toSensorFrame(f, tr.x, tr.y, sx, sy);
    int n = std::snprintf(buf, sizeof buf, "%.6f,%zu,%ld,%.4f,%.4f,%.4f,%.4f,%.5f,%.4f,%.4f,", f.t,
                          f.index, tr.id, tr.x, tr.y, sx, sy, tr.yaw, tr.vx, tr.vy);
    writeClamped(out_, buf, n, sizeof buf);
    if (tr.has_shape) {
      n = std::snprintf(buf, sizeof buf, "%.4f,%.4f,", tr.alpha, tr.beta);
      writeClamped(out_, buf, n, sizeof buf);
    } else {
      out_ << ",,";
    }
    if (tr.has_cov) {
      n = std::snprintf(buf, sizeof buf, "%.6g,%.6g,%.6g,", tr.cov_xx, tr.cov_xy, tr.cov_yy);
      writeClamped(out_, buf, n, sizeof buf);
    } else {
      out_ << ",,,";
    }
    n = std::snprintf(buf, sizeof buf, "%.4f,", tr.score);
    writeClamped(out_, buf, n, sizeof buf);
    for (std::size_t i = 0; i < tr.model_probs.size(); ++i) {
      n = std::snprintf(buf, sizeof buf, "%s%.4f", i ? ";" : "", tr.model_probs[i]);
      writeClamped(out_, buf, n, sizeof buf);
    }
    out_ << ',' << tr.status << ',';
    if (std::isfinite(tr.nis)) {
      n = std::snprintf(buf, sizeof buf, "%.6g", tr.nis);
      writeClamped(out_, buf, n, sizeof buf);
    }
    out_ << ',';
    if (tr.cluster >= 0) out_ << tr.cluster;
    writeBox(out_, tr.box);
    out_ << '\n';
  }
  frameWritten();
}

const char* DetectionsCsvWriter::header() {
  return "t,frame,x,y,sensor_x,sensor_y,score,yaw,alpha,beta,cluster,z,h,w,l";
}

void DetectionsCsvWriter::write(const Frame& f) {
  char buf[256];
  for (const Detection& d : f.detections) {
    double sx = 0, sy = 0;
    toSensorFrame(f, d.x, d.y, sx, sy);
    int n = std::snprintf(buf, sizeof buf, "%.6f,%zu,%.4f,%.4f,%.4f,%.4f,%.4f,", f.t, f.index, d.x,
                          d.y, sx, sy, d.score);
    writeClamped(out_, buf, n, sizeof buf);
    // Detection marks an unknown shape with alpha = beta = 0 and no box; its yaw then means
    // nothing either.
    if (d.alpha > 0 || d.beta > 0 || d.box.known()) {
      n = std::snprintf(buf, sizeof buf, "%.5f,%.4f,%.4f,", d.yaw, d.alpha, d.beta);
      writeClamped(out_, buf, n, sizeof buf);
    } else {
      out_ << ",,,";
    }
    if (d.cluster >= 0) out_ << d.cluster;
    writeBox(out_, d.box);
    out_ << '\n';
  }
  frameWritten();
}

const char* ClustersCsvWriter::header() {
  return "t,frame,cluster,points,x,y,z,sensor_x,sensor_y,size_x,size_y,size_z,pair";
}

static std::vector<std::string> featureNames(const Frame& f) {
  return f.cluster_feature_names ? *f.cluster_feature_names : std::vector<std::string>();
}

static std::string clustersHeader(const Frame& first) {
  std::string h = ClustersCsvWriter::header();
  for (const auto& name : featureNames(first)) h += "," + name;
  return h;
}

ClustersCsvWriter::ClustersCsvWriter(const std::string& path, const Frame& first)
    : CsvStream(path, clustersHeader(first).c_str()), features_(featureNames(first)) {}

void ClustersCsvWriter::write(const Frame& f) {
  char buf[512];
  // A later frame's features go under the header's names (by name, empty where absent); the
  // mapping is made again only when the frame's list of names is another one.
  const std::vector<std::string>* names = f.cluster_feature_names.get();
  if (!mapped_ || names != mapped_names_) {
    column_.assign(features_.size(), -1);
    for (std::size_t k = 0; k < features_.size(); ++k)
      if (names)
        for (std::size_t j = 0; j < names->size(); ++j)
          if ((*names)[j] == features_[k]) column_[k] = int(j);
    mapped_names_ = names;
    mapped_ = true;
  }
  const std::vector<int>& column = column_;
  for (std::size_t c = 0; c < f.clusters.size(); ++c) {
    const Cluster& cl = f.clusters[c];
    double x = 0, y = 0, z = 0, sx = 0, sy = 0;
    f.robot_pose.composePoint(cl.cx, cl.cy, cl.cz, x, y, z);
    toSensorFrame(f, x, y, sx, sy);
    int n = std::snprintf(
        buf, sizeof buf, "%.6f,%zu,%zu,%zu,%.4f,%.4f,%.4f,%.4f,%.4f,%.3f,%.3f,%.3f,%d", f.t,
        f.index, c, cl.indices.size(), x, y, z, sx, sy, cl.size_x, cl.size_y, cl.size_z, cl.pair);
    writeClamped(out_, buf, n, sizeof buf);
    for (int j : column) {
      if (j >= 0 && j < int(cl.features.size())) {
        n = std::snprintf(buf, sizeof buf, ",%.6g", cl.features[j]);
        writeClamped(out_, buf, n, sizeof buf);
      } else {
        out_ << ',';
      }
    }
    out_ << '\n';
  }
  frameWritten();
}

std::string jsonEscape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '"':
        o += "\\\"";
        break;
      case '\\':
        o += "\\\\";
        break;
      case '\n':
        o += "\\n";
        break;
      case '\t':
        o += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char b[8];
          std::snprintf(b, sizeof b, "\\u%04x", c);
          o += b;
        } else {
          o += c;
        }
    }
  }
  return o;
}

// run.json is small and flat; a JSON library would add a dependency for a dozen fields.
void writeRunJson(const std::string& path, const RunSummary& s) {
  FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw DataError(path + ": cannot open for writing");
  const double fps = s.wall_time_s > 0 ? s.frames_processed / s.wall_time_s : 0;
  std::fprintf(f, "{\n  \"pedtrack_version\": \"%s\",\n  \"api_version\": %d,\n", versionString(),
               kApiVersion);
  std::fprintf(f, "  \"pipeline\": \"%s\",\n  \"input\": \"%s\",\n", jsonEscape(s.pipeline).c_str(),
               jsonEscape(s.input).c_str());
  std::fprintf(f, "  \"status\": \"%s\",\n  \"error\": \"%s\",\n", s.status.c_str(),
               jsonEscape(s.error).c_str());
  std::fprintf(f,
               "  \"frames_read\": %zu,\n  \"frames_processed\": %zu,\n  \"frames_failed\": %zu,\n"
               "  \"frames_skipped\": %zu,\n  \"entries_skipped\": %zu,\n  \"wall_time_s\": %.6f,\n"
               "  \"frames_per_second\": %.1f,\n",
               s.frames_read, s.frames_processed, s.frames_failed, s.frames_skipped,
               s.entries_skipped, s.wall_time_s, fps);
  std::fprintf(f, "  \"input_warnings\": {");
  for (std::size_t c = 0; c < s.input_warnings.size(); ++c)
    std::fprintf(f, "%s\"%s\": %ld", c ? ", " : "", jsonEscape(s.input_warnings[c].first).c_str(),
                 s.input_warnings[c].second);
  std::fprintf(f, "},\n  \"nonfinite_track_rows\": %zu,\n", s.nonfinite_track_rows);
  std::fprintf(f,
               "  \"live\": %s,\n  \"frames_dropped\": %zu,\n  \"frames_recorded\": %zu,\n"
               "  \"latency_ms\": {\"frames\": %zu, \"mean\": %.6f, \"p50\": %.6f, \"p99\": %.6f, "
               "\"max\": %.6f},\n",
               s.live ? "true" : "false", s.frames_dropped, s.frames_recorded, s.latency.calls(),
               s.latency.mean(), s.latency.percentile(50), s.latency.percentile(99),
               s.latency.max());
  std::fprintf(f, "  \"stages\": [");
  for (std::size_t i = 0; i < s.stages.size(); ++i) {
    const StageStats& st = s.stages[i];
    std::fprintf(
        f,
        "%s\n    {\"name\": \"%s\", \"plugin\": \"%s\", \"calls\": %zu, \"mean_ms\": %.6f, "
        "\"p50_ms\": %.6f, \"p99_ms\": %.6f, \"max_ms\": %.6f",
        i ? "," : "", jsonEscape(st.name()).c_str(), jsonEscape(st.plugin()).c_str(), st.calls(),
        st.mean(), st.percentile(50), st.percentile(99), st.max());
    if (!st.counters.empty()) {
      std::fprintf(f, ", \"counters\": {");
      for (std::size_t c = 0; c < st.counters.size(); ++c)
        std::fprintf(f, "%s\"%s\": %ld", c ? ", " : "", jsonEscape(st.counters[c].first).c_str(),
                     st.counters[c].second);
      std::fprintf(f, "}");
    }
    std::fprintf(f, "}");
  }
  std::fprintf(f, "\n  ]\n}\n");
  std::fclose(f);
}

}  // namespace pedtrack
