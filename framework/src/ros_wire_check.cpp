#include "pedtrack/ros_wire_check.h"

#include <cstring>

namespace pedtrack {
namespace {

// A walk over a serialized message: each step checks the bytes left, the first fault is kept.
class Wire {
 public:
  Wire(const std::uint8_t* p, std::size_t n) : p_(p), left_(n) {}
  const std::string& problem() const { return problem_; }
  bool ok() const { return problem_.empty(); }

  void skip(std::size_t n, const char* what) {
    if (!ok()) return;
    if (n > left_) {
      fail(std::string(what) + " (" + std::to_string(n) + " bytes) past the message's end");
      return;
    }
    p_ += n;
    left_ -= n;
  }
  std::uint32_t u32(const char* what) {
    std::uint32_t v = 0;
    if (ok() && left_ >= 4) std::memcpy(&v, p_, 4);  // ROS1 is little-endian, as this host
    skip(4, what);
    return v;
  }
  void string(const char* what) { skip(u32(what), what); }
  // An array's count, each element at least `min_bytes` long: checked before anyone sizes by it.
  std::uint32_t count(const char* what, std::size_t min_bytes) {
    const std::uint32_t n = u32(what);
    if (ok() && min_bytes > 0 && n > left_ / min_bytes) {
      fail(std::string(what) + " count " + std::to_string(n) + " does not fit in the " +
           std::to_string(left_) + " bytes left");
      return 0;
    }
    return n;
  }
  void fail(std::string why) {
    if (ok()) problem_ = std::move(why);
  }

 private:
  const std::uint8_t* p_;
  std::size_t left_;
  std::string problem_;
};

void header(Wire& w) {
  w.skip(4 + 8, "header seq and stamp");
  w.string("header frame_id");
}

void laserScan(Wire& w) {
  header(w);
  w.skip(7 * 4, "scan angles, times and range limits");
  w.skip(std::size_t(w.count("ranges", 4)) * 4, "ranges");
  w.skip(std::size_t(w.count("intensities", 4)) * 4, "intensities");
}

void pointCloud2(Wire& w) {
  header(w);
  w.skip(8, "cloud height and width");
  // A field: name (4-byte length at least), offset, datatype, count.
  const std::uint32_t fields = w.count("fields", 4 + 4 + 1 + 4);
  for (std::uint32_t i = 0; i < fields && w.ok(); ++i) {
    w.string("field name");
    w.skip(4 + 1 + 4, "field offset, datatype and count");
  }
  w.skip(1 + 4 + 4, "cloud is_bigendian, point_step and row_step");
  w.skip(w.count("data", 1), "cloud data");
  w.skip(1, "cloud is_dense");
}

constexpr std::size_t kPoseBytes = 7 * 8;  // position and orientation quaternion, float64

void tfMessage(Wire& w) {
  // A transform: header (12 bytes and a frame_id), child_frame_id, translation and rotation.
  const std::uint32_t n = w.count("transforms", 12 + 4 + 4 + kPoseBytes);
  for (std::uint32_t i = 0; i < n && w.ok(); ++i) {
    header(w);
    w.string("child_frame_id");
    w.skip(kPoseBytes, "transform");
  }
}

void odometry(Wire& w) {
  header(w);
  w.string("child_frame_id");
  w.skip(kPoseBytes + 36 * 8, "pose with covariance");
  w.skip(6 * 8 + 36 * 8, "twist with covariance");
}

void poseArray(Wire& w) {
  header(w);
  w.skip(std::size_t(w.count("poses", kPoseBytes)) * kPoseBytes, "poses");
}

}  // namespace

std::string rosWireProblem(const std::string& datatype, const std::uint8_t* data,
                           std::size_t size) {
  Wire w(data, size);
  if (datatype == "sensor_msgs/LaserScan")
    laserScan(w);
  else if (datatype == "sensor_msgs/PointCloud2")
    pointCloud2(w);
  else if (datatype == "tf2_msgs/TFMessage")
    tfMessage(w);
  else if (datatype == "nav_msgs/Odometry")
    odometry(w);
  else if (datatype == "geometry_msgs/PoseArray")
    poseArray(w);
  // Bytes after the last field are left alone, as roscpp leaves them.
  return w.problem();
}

}  // namespace pedtrack
