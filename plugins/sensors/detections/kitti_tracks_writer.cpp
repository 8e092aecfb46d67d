#include "kitti_tracks_writer.h"

#include <cmath>
#include <cstdio>

#include "pedtrack/errors.h"
#include "pedtrack/kitti_calib.h"

namespace pedtrack::detections {

KittiTracksWriter::KittiTracksWriter(const std::string& path, const KittiCalib& calib,
                                     double mount_z, std::string type)
    : out_(path), path_(path), calib_(calib), mount_z_(mount_z), type_(std::move(type)) {
  if (!out_) throw DataError(path + ": cannot open for writing");
}

void KittiTracksWriter::write(long kitti_frame, const Frame& f) {
  char buf[512];
  for (const Track& tr : f.tracks) {
    const bool box = tr.box.known();
    // Fixed frame -> robot frame (on the road under the scanner) -> Velodyne -> camera.
    double rx = 0, ry = 0, rz = 0;
    f.robot_pose.inverseComposePoint(tr.x, tr.y, box ? tr.box.z : f.robot_pose.z(), rx, ry, rz);
    const Eigen::Vector3d rect = calib_.rectFromVelo({rx, ry, rz - mount_z_});
    KittiCameraBox b;
    b.h = box ? tr.box.h : default_.h;
    b.w = box ? tr.box.w : default_.w;
    b.l = box ? tr.box.l : default_.l;
    b.x = rect.x(), b.y = rect.y(), b.z = rect.z();
    b.ry = rotationYFromVeloYaw(tr.yaw - f.robot_pose.yaw());
    std::array<double, 4> img{};
    if (!std::isfinite(b.x + b.y + b.z + b.ry + tr.score) || !kittiImageBox(calib_, b, img)) {
      ++out_of_view_;
      continue;
    }
    const int n = std::snprintf(
        buf, sizeof buf,
        "%ld %ld %s 0 0 %.6f %.2f %.2f %.2f %.2f %.4f %.4f %.4f %.4f %.4f %.4f %.6f %.6f\n",
        kitti_frame, tr.id, type_.c_str(), kittiAlpha(b), img[0], img[1], img[2], img[3], b.h, b.w,
        b.l, b.x, b.y, b.z, b.ry, tr.score);
    if (n > 0 && std::size_t(n) < sizeof buf) out_.write(buf, n);
  }
}

void KittiTracksWriter::close() {
  out_.flush();
  if (!out_) throw DataError(path_ + ": write failed");
  out_.close();
}

}  // namespace pedtrack::detections
