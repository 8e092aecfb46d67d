#include "detection_files.h"

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "pedtrack/errors.h"
#include "pedtrack/text.h"

namespace pedtrack::detections {
namespace {

double number(const std::string& s, const std::string& where, const char* what) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end == s.c_str() || *end || !std::isfinite(v))
    throw DataError(where + ": " + what + " '" + s + "' is not a finite number");
  return v;
}

long frameNumber(const std::string& s, const std::string& where) {
  const double v = number(s, where, "frame");
  if (v < 0 || v != std::floor(v) || v > 1e6)
    throw DataError(where + ": frame '" + s + "' is not a frame number (0 ... 1,000,000)");
  return long(v);
}

std::string className(const std::string& type) {
  if (type == "1") return "Pedestrian";
  if (type == "2") return "Car";
  if (type == "3") return "Cyclist";
  return type;
}

// A detector's box must be one: its sizes in (0, 100) m.
void checkBox(const KittiCameraBox& b, const std::string& where) {
  if (!(b.h > 0 && b.w > 0 && b.l > 0 && b.h < 100 && b.w < 100 && b.l < 100))
    throw DataError(where + ": box size h w l must lie in (0, 100) m");
}

}  // namespace

std::map<long, std::vector<KittiDetection>> readKittiDetections(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw DataError(path + ": cannot open");
  std::map<long, std::vector<KittiDetection>> out;
  std::string line;
  for (long n = 1; std::getline(f, line); ++n) {
    if (trim(line).empty()) continue;
    // KITTI tracking's own layout (labels, a tracker's results): read as `pedtrack eval` reads it.
    if (line.find(',') == std::string::npos) {
      for (const KittiTrackRow& r : readKittiTrackFile(path)) {
        if (r.type == "dontcare") continue;
        checkBox(r.box, path + ": frame " + std::to_string(r.frame));
        out[r.frame].push_back({r.type, r.box, r.has_score ? r.score : 1});
      }
      return out;
    }
    const std::string where = path + ": line " + std::to_string(n);
    const auto v = splitFields(line, ',');
    if (v.size() != 15)
      throw DataError(where +
                      ": expected 15 comma-separated values (frame,type,x1,y1,x2,y2,"
                      "score,h,w,l,x,y,z,rotation_y,alpha), got " +
                      std::to_string(v.size()));
    KittiDetection d;
    d.type = className(v[1]);
    d.score = number(v[6], where, "score");
    KittiCameraBox& b = d.box;
    b.h = number(v[7], where, "h");
    b.w = number(v[8], where, "w");
    b.l = number(v[9], where, "l");
    b.x = number(v[10], where, "x");
    b.y = number(v[11], where, "y");
    b.z = number(v[12], where, "z");
    b.ry = number(v[13], where, "rotation_y");
    checkBox(b, where);
    out[frameNumber(v[0], where)].push_back(d);
  }
  return out;
}

std::map<long, CsvFrame> readDetectionsCsv(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw DataError(path + ": cannot open");
  std::string line;
  if (!std::getline(f, line)) throw DataError(path + ": empty (no header line)");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const auto header = splitFields(line, ',');
  const auto col = [&](const char* name) -> int {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return int(i);
    return -1;
  };
  const int t = col("t"), fr = col("frame"), x = col("x"), y = col("y"), score = col("score"),
            yaw = col("yaw"), alpha = col("alpha"), beta = col("beta"), z = col("z"), h = col("h"),
            w = col("w"), l = col("l");
  for (const auto& [c, name] :
       {std::pair{t, "t"}, {fr, "frame"}, {x, "x"}, {y, "y"}, {score, "score"}})
    if (c < 0) throw DataError(path + ": line 1: no column '" + name + "' (not a detections.csv)");
  if (col("track") >= 0)
    throw DataError(path + ": line 1: a 'track' column: a tracks.csv, not a detections.csv");
  std::map<long, CsvFrame> out;
  for (long n = 2; std::getline(f, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (trim(line).empty()) continue;
    const std::string where = path + ": line " + std::to_string(n);
    const auto v = splitFields(line, ',');
    if (v.size() != header.size())
      throw DataError(where + ": " + std::to_string(v.size()) + " values for " +
                      std::to_string(header.size()) + " columns");
    const auto get = [&](int c, const char* name, double fallback) {
      return c < 0 || v[std::size_t(c)].empty() ? fallback : number(v[std::size_t(c)], where, name);
    };
    Detection d;
    d.x = number(v[std::size_t(x)], where, "x");
    d.y = number(v[std::size_t(y)], where, "y");
    d.score = number(v[std::size_t(score)], where, "score");
    d.yaw = get(yaw, "yaw", 0);
    d.alpha = get(alpha, "alpha", 0);
    d.beta = get(beta, "beta", 0);
    d.box.z = get(z, "z", 0);
    d.box.h = get(h, "h", 0);
    d.box.w = get(w, "w", 0);
    d.box.l = get(l, "l", 0);
    CsvFrame& frame = out[frameNumber(v[std::size_t(fr)], where)];
    frame.t = number(v[std::size_t(t)], where, "t");
    frame.detections.push_back(d);
  }
  // detections.csv has no rows for a frame without detections, but a tracker must see it (a
  // miss): the numbers between two frames come back empty, their times interpolated.
  std::map<long, CsvFrame> filled;
  for (auto it = out.begin(); it != out.end(); ++it) {
    filled[it->first] = it->second;
    const auto next = std::next(it);
    if (next == out.end()) break;
    const double step = (next->second.t - it->second.t) / double(next->first - it->first);
    // Beyond a minute at 100 Hz the gap is a break in the recording, not frames to replay.
    if (next->first - it->first > 6000) continue;
    for (long k = it->first + 1; k < next->first; ++k)
      filled[k].t = it->second.t + step * double(k - it->first);
  }
  return filled;
}

}  // namespace pedtrack::detections
