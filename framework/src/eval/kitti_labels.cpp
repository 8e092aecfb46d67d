#include "pedtrack/eval/kitti_labels.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "pedtrack/errors.h"

namespace pedtrack::eval {
namespace {

// The object from a label line's values from `type` on (type truncated occluded alpha x1 y1 x2
// y2 h w l x y z rotation_y).
KittiObject fromFields(const std::vector<std::string>& f, std::size_t at, const KittiCalib& c,
                       const std::string& where) {
  if (f.size() < at + 15)
    throw DataError(where + ": expected " + std::to_string(at + 15) + " values, got " +
                    std::to_string(f.size()));
  std::vector<double> v;
  for (std::size_t i = at + 1; i < at + 15; ++i) {
    char* end = nullptr;
    v.push_back(std::strtod(f[i].c_str(), &end));
    if (end == f[i].c_str() || *end) throw DataError(where + ": '" + f[i] + "' is not a number");
  }
  KittiObject o;
  o.type = f[at];
  if (!(v[1] >= -1 && v[1] <= 3))
    throw DataError(where + ": occluded '" + f[at + 2] + "' is out of KITTI's range (-1 ... 3)");
  o.truncated = v[0];
  o.occluded = int(v[1]);
  o.h = v[7], o.w = v[8], o.l = v[9];
  const Eigen::Vector3d p = c.veloFromRect({v[10], v[11], v[12]});
  o.x = p.x(), o.y = p.y(), o.z = p.z();
  o.yaw = veloYawFromRotationY(v[13]);
  return o;
}

std::vector<std::string> split(const std::string& line) {
  std::istringstream is(line);
  std::vector<std::string> f;
  std::string s;
  while (is >> s) f.push_back(s);
  return f;
}

}  // namespace

bool KittiObject::contains(double px, double py, double margin) const {
  const double c = std::cos(yaw), s = std::sin(yaw);
  const double dx = px - x, dy = py - y;
  const double along = c * dx + s * dy, across = -s * dx + c * dy;
  return std::abs(along) <= l / 2 + margin && std::abs(across) <= w / 2 + margin;
}

namespace {

// Every non-empty line of a label file, split into its values, with "FILE: line N" for errors.
template <class Fn>
std::vector<KittiObject> readLabelLines(const std::string& path, Fn&& object) {
  std::ifstream f(path);
  if (!f) throw DataError(path + ": cannot open");
  std::vector<KittiObject> out;
  std::string line;
  for (int n = 1; std::getline(f, line); ++n) {
    const auto fields = split(line);
    if (!fields.empty()) out.push_back(object(fields, path + ": line " + std::to_string(n)));
  }
  return out;
}

}  // namespace

std::vector<KittiObject> readKittiObjectLabels(const std::string& path, const KittiCalib& calib,
                                               long frame) {
  return readLabelLines(path,
                        [&](const std::vector<std::string>& fields, const std::string& where) {
                          KittiObject o = fromFields(fields, 0, calib, where);
                          o.frame = frame;
                          return o;
                        });
}

std::vector<KittiObject> readKittiTrackingLabels(const std::string& path, const KittiCalib& calib) {
  return readLabelLines(
      path, [&](const std::vector<std::string>& fields, const std::string& where) {
        if (fields.size() < 2) throw DataError(where + ": expected frame track_id type ...");
        KittiObject o = fromFields(fields, 2, calib, where);
        char* end = nullptr;
        o.frame = std::strtol(fields[0].c_str(), &end, 10);
        if (*end || o.frame < 0)
          throw DataError(where + ": frame '" + fields[0] + "' is not a frame");
        o.track = std::strtol(fields[1].c_str(), &end, 10);
        if (*end) throw DataError(where + ": track id '" + fields[1] + "' is not a number");
        return o;
      });
}

std::map<long, KittiScanLabels> readKittiObjectDir(const std::string& dir) {
  namespace fs = std::filesystem;
  const fs::path labels = fs::path(dir) / "label_2", calibs = fs::path(dir) / "calib";
  if (!fs::is_directory(labels))
    throw DataError(labels.string() + ": no such folder (the KITTI object benchmark's labels)");
  std::map<long, KittiScanLabels> out;
  for (const auto& e : fs::directory_iterator(labels)) {
    const std::string stem = e.path().stem().string();
    if (e.path().extension() != ".txt" || stem.empty() || stem.size() > 18 ||
        !std::all_of(stem.begin(), stem.end(), [](char c) { return c >= '0' && c <= '9'; }))
      continue;
    const long n = std::stol(stem);
    const fs::path calib = calibs / e.path().filename();
    if (!fs::is_regular_file(calib))
      throw DataError(calib.string() + ": missing (the calibration of " + e.path().string() + ")");
    KittiScanLabels& s = out[n];
    s.calib = readKittiCalib(calib.string());
    s.objects = readKittiObjectLabels(e.path().string(), s.calib, n);
  }
  if (out.empty()) throw DataError(labels.string() + ": no label files (NNNNNN.txt)");
  return out;
}

}  // namespace pedtrack::eval

namespace pedtrack::eval {

KittiFrameMatch matchKittiFrame(long frame, std::vector<KittiObject> objects,
                                const KittiCalib& calib, std::vector<KittiCalled> called,
                                double margin) {
  KittiFrameMatch m;
  m.frame = frame;
  m.objects = std::move(objects);
  m.called = std::move(called);
  m.detected_by.assign(m.objects.size(), -1);
  for (std::size_t c = 0; c < m.called.size(); ++c) {
    KittiCalled& k = m.called[c];
    // The cluster's centroid sits at about half a person's height; the camera's view is tested
    // at the road (the box's bottom) and at that height alike.
    k.in_view = calib.inCameraView({k.x, k.y, -1.0}) || calib.inCameraView({k.x, k.y, 0.0});
    for (int pass = 0; pass < 2 && k.object < 0; ++pass)
      for (std::size_t i = 0; i < m.objects.size(); ++i) {
        const KittiObject& o = m.objects[i];
        if (o.dontCare() || o.person() != (pass == 0)) continue;
        if (o.contains(k.x, k.y, margin)) {
          k.object = int(i);
          break;
        }
      }
    if (k.object >= 0) {
      int& best = m.detected_by[std::size_t(k.object)];
      if (best < 0 || m.called[std::size_t(best)].score < k.score) best = int(c);
    }
  }
  return m;
}

}  // namespace pedtrack::eval
