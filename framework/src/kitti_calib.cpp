#include "pedtrack/kitti_calib.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "pedtrack/errors.h"

namespace pedtrack {
namespace {

// "KEY: v1 v2 ..." (or "KEY v1 v2 ...") lines of a calibration file, by key.
std::map<std::string, std::vector<double>> calibLines(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw DataError(path + ": cannot open");
  std::map<std::string, std::vector<double>> out;
  std::string line;
  int n = 0;
  while (std::getline(f, line)) {
    ++n;
    std::istringstream is(line);
    std::string key;
    if (!(is >> key)) continue;
    if (key.back() == ':') key.pop_back();
    std::vector<double> v;
    double d;
    while (is >> d) v.push_back(d);
    if (!is.eof())
      throw DataError(path + ": line " + std::to_string(n) + " (" + key + "): not a number");
    out[key] = std::move(v);
  }
  return out;
}

const std::vector<double>& need(const std::map<std::string, std::vector<double>>& lines,
                                const std::string& path, std::initializer_list<const char*> keys,
                                std::size_t count) {
  for (const char* k : keys) {
    const auto it = lines.find(k);
    if (it == lines.end()) continue;
    if (it->second.size() != count)
      throw DataError(path + ": " + k + ": expected " + std::to_string(count) + " numbers, got " +
                      std::to_string(it->second.size()));
    return it->second;
  }
  throw DataError(path + ": no " + std::string(*keys.begin()) + " line");
}

}  // namespace

Eigen::Vector3d KittiCalib::veloFromRect(const Eigen::Vector3d& rect) const {
  const Eigen::Vector3d cam = R0.inverse() * rect;
  const Eigen::Matrix3d R = velo_to_cam.leftCols<3>();
  return R.transpose() * (cam - velo_to_cam.col(3));
}

Eigen::Vector3d KittiCalib::rectFromVelo(const Eigen::Vector3d& velo) const {
  return R0 * (velo_to_cam.leftCols<3>() * velo + velo_to_cam.col(3));
}

bool KittiCalib::inCameraView(const Eigen::Vector3d& velo) const {
  const Eigen::Vector3d rect = rectFromVelo(velo);
  if (rect.z() <= 0.1) return false;
  const Eigen::Vector3d uvw = P2.leftCols<3>() * rect + P2.col(3);
  const double u = uvw.x() / uvw.z();
  return u >= 0 && u <= 2 * P2(0, 2);
}

KittiCalib readKittiCalib(const std::string& path) {
  const auto lines = calibLines(path);
  KittiCalib c;
  const auto& p2 = need(lines, path, {"P2"}, 12);
  const auto& r0 = need(lines, path, {"R0_rect", "R_rect"}, 9);
  const auto& tr = need(lines, path, {"Tr_velo_to_cam", "Tr_velo_cam"}, 12);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) {
      c.P2(i, j) = p2[std::size_t(4 * i + j)];
      c.velo_to_cam(i, j) = tr[std::size_t(4 * i + j)];
      if (j < 3) c.R0(i, j) = r0[std::size_t(3 * i + j)];
    }
  if (std::abs(c.R0.determinant() - 1) > 0.01 ||
      std::abs(c.velo_to_cam.leftCols<3>().determinant() - 1) > 0.01)
    throw DataError(path + ": R0_rect or Tr_velo_to_cam is not a rotation");
  return c;
}

std::array<Eigen::Vector3d, 8> kittiCorners(const KittiCameraBox& b) {
  const double c = std::cos(b.ry), s = std::sin(b.ry);
  // (along l, across w) of the four footprint corners; rotation_y turns x towards −z.
  const double u[4] = {b.l / 2, b.l / 2, -b.l / 2, -b.l / 2};
  const double v[4] = {b.w / 2, -b.w / 2, -b.w / 2, b.w / 2};
  std::array<Eigen::Vector3d, 8> out;
  for (int i = 0; i < 4; ++i) {
    const double x = b.x + c * u[i] + s * v[i], z = b.z - s * u[i] + c * v[i];
    out[std::size_t(i)] = {x, b.y, z};
    out[std::size_t(i + 4)] = {x, b.y - b.h, z};
  }
  return out;
}

bool kittiImageBox(const KittiCalib& c, const KittiCameraBox& b, std::array<double, 4>& xyxy) {
  double x1 = 1e18, y1 = 1e18, x2 = -1e18, y2 = -1e18;
  for (const auto& p : kittiCorners(b)) {
    if (p.z() <= 0.1) return false;
    const Eigen::Vector3d uvw = c.P2.leftCols<3>() * p + c.P2.col(3);
    const double u = uvw.x() / uvw.z(), v = uvw.y() / uvw.z();
    x1 = std::min(x1, u), y1 = std::min(y1, v), x2 = std::max(x2, u), y2 = std::max(y2, v);
  }
  xyxy = {std::clamp(x1, 0.0, c.image_width), std::clamp(y1, 0.0, c.image_height),
          std::clamp(x2, 0.0, c.image_width), std::clamp(y2, 0.0, c.image_height)};
  return xyxy[2] > xyxy[0] && xyxy[3] > xyxy[1];  // empty: wholly beside the image
}

double kittiAlpha(const KittiCameraBox& b) {
  return std::remainder(b.ry - std::atan2(b.x, b.z), 2 * M_PI);
}

std::string kittiCalibBeside(const std::string& file) {
  const std::filesystem::path p(file);
  const std::filesystem::path c = p.parent_path().parent_path() / "calib" / p.filename();
  std::error_code ec;
  return std::filesystem::is_regular_file(c, ec) ? c.string() : "";
}

double veloYawFromRotationY(double rotation_y) {
  return std::remainder(-rotation_y - M_PI / 2, 2 * M_PI);
}

double rotationYFromVeloYaw(double yaw) {
  return std::remainder(-yaw - M_PI / 2, 2 * M_PI);
}

}  // namespace pedtrack
