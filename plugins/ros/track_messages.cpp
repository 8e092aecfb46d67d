#include "track_messages.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace pedtrack::ros_plugins {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// sqrt of the chi-square 95% quantile with 2 degrees of freedom: the covariance ellipse holds
// the person with 95% probability.
constexpr double kSigma95 = 2.4477;

geometry_msgs::Quaternion yawQuaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(yaw / 2);
  q.w = std::cos(yaw / 2);
  return q;
}

std_msgs::ColorRGBA color(double r, double g, double b, double a) {
  std_msgs::ColorRGBA c;
  c.r = static_cast<float>(r);
  c.g = static_cast<float>(g);
  c.b = static_cast<float>(b);
  c.a = static_cast<float>(a);
  return c;
}

// Status at a glance: confirmed blue, coasting orange, tentative grey, followed green.
std_msgs::ColorRGBA statusColor(StatusCode s, double alpha) {
  switch (s) {
    case StatusCode::Confirmed:
      return color(0.2, 0.4, 1.0, alpha);
    case StatusCode::Coasting:
      return color(1.0, 0.6, 0.1, alpha);
    case StatusCode::Following:
      return color(0.1, 0.9, 0.2, alpha);
    default:
      return color(0.6, 0.6, 0.6, alpha);
  }
}

geometry_msgs::Point point(double x, double y, double z) {
  geometry_msgs::Point p;
  p.x = x;
  p.y = y;
  p.z = z;
  return p;
}

}  // namespace

std::vector<OutTrack> expressIn(const std::vector<Track>& tracks,
                                const mrpt::poses::CPose3D& frame) {
  const double c = std::cos(frame.yaw()), s = std::sin(frame.yaw());
  std::vector<OutTrack> out;
  out.reserve(tracks.size());
  for (const Track& t : tracks) {
    OutTrack o;
    o.track = &t;
    frame.inverseComposePoint(t.x, t.y, 0.0, o.x, o.y, o.z);
    o.yaw = t.yaw - frame.yaw();
    // Vectors and covariances rotate by -yaw: v' = Rᵀv, C' = RᵀCR.
    o.vx = c * t.vx + s * t.vy;
    o.vy = -s * t.vx + c * t.vy;
    o.cov_xx = c * c * t.cov_xx + 2 * c * s * t.cov_xy + s * s * t.cov_yy;
    o.cov_yy = s * s * t.cov_xx - 2 * c * s * t.cov_xy + c * c * t.cov_yy;
    o.cov_xy = (c * c - s * s) * t.cov_xy + c * s * (t.cov_yy - t.cov_xx);
    out.push_back(o);
  }
  return out;
}

StatusCode statusCode(const std::string& status) {
  if (status == "tentative") return StatusCode::Tentative;
  if (status == "confirmed") return StatusCode::Confirmed;
  if (status == "coasting") return StatusCode::Coasting;
  if (status == "following") return StatusCode::Following;
  return StatusCode::Other;
}

geometry_msgs::PoseArray toPoseArray(const std::vector<OutTrack>& tracks,
                                     const std::string& frame_id, const ros::Time& stamp) {
  geometry_msgs::PoseArray msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame_id;
  for (const OutTrack& t : tracks) {
    geometry_msgs::Pose p;
    p.position = point(t.x, t.y, t.z);
    p.orientation = yawQuaternion(t.yaw);
    msg.poses.push_back(p);
  }
  return msg;
}

sensor_msgs::PointCloud2 toPeopleCloud(const std::vector<OutTrack>& tracks,
                                       const std::string& frame_id, const ros::Time& stamp) {
  using sensor_msgs::PointField;
  sensor_msgs::PointCloud2 msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame_id;
  const char* floats[] = {"vx",     "vy",     "yaw",    "alpha", "beta",
                          "cov_xx", "cov_xy", "cov_yy", "score"};
  std::uint32_t offset = 0;
  auto field = [&](const char* name, std::uint8_t type, std::uint32_t size) {
    PointField f;
    f.name = name;
    f.offset = offset;
    f.datatype = type;
    f.count = 1;
    msg.fields.push_back(f);
    offset += size;
  };
  for (const char* n : {"x", "y", "z"}) field(n, PointField::FLOAT32, 4);
  field("id", PointField::INT32, 4);
  for (const char* n : floats) field(n, PointField::FLOAT32, 4);
  field("status", PointField::UINT8, 1);
  msg.point_step = (offset + 3) / 4 * 4;
  msg.height = 1;
  msg.width = static_cast<std::uint32_t>(tracks.size());
  msg.row_step = msg.point_step * msg.width;
  msg.is_bigendian = false;
  msg.is_dense = true;
  msg.data.assign(msg.row_step, 0);
  for (std::size_t i = 0; i < tracks.size(); ++i) {
    const OutTrack& o = tracks[i];
    const Track& t = *o.track;
    std::uint8_t* p = msg.data.data() + i * msg.point_step;
    // Unknown shape or covariance: NaN, as ROS marks missing values.
    const double values[] = {o.x,
                             o.y,
                             o.z,
                             o.vx,
                             o.vy,
                             o.yaw,
                             t.has_shape ? t.alpha : kNaN,
                             t.has_shape ? t.beta : kNaN,
                             t.has_cov ? o.cov_xx : kNaN,
                             t.has_cov ? o.cov_xy : kNaN,
                             t.has_cov ? o.cov_yy : kNaN,
                             t.score};
    std::size_t v = 0;
    for (const PointField& f : msg.fields) {
      if (f.datatype == PointField::FLOAT32) {
        const float x = static_cast<float>(values[v++]);
        std::memcpy(p + f.offset, &x, 4);
      } else if (f.datatype == PointField::INT32) {
        const std::int32_t id = static_cast<std::int32_t>(t.id);
        std::memcpy(p + f.offset, &id, 4);
      } else {
        p[f.offset] = static_cast<std::uint8_t>(statusCode(t.status));
      }
    }
  }
  return msg;
}

visualization_msgs::MarkerArray toMarkers(const std::vector<OutTrack>& tracks,
                                          const std::string& frame_id, const ros::Time& stamp,
                                          const MarkerStyle& style) {
  using visualization_msgs::Marker;
  visualization_msgs::MarkerArray out;
  Marker clear;
  clear.header.frame_id = frame_id;
  clear.header.stamp = stamp;
  clear.action = Marker::DELETEALL;
  out.markers.push_back(clear);
  for (const OutTrack& o : tracks) {
    const Track& t = *o.track;
    const StatusCode status = statusCode(t.status);
    auto marker = [&](const char* ns, int type) {
      Marker m;
      m.header.frame_id = frame_id;
      m.header.stamp = stamp;
      m.ns = ns;
      m.id = static_cast<std::int32_t>(t.id);
      m.type = type;
      m.action = Marker::ADD;
      m.pose.orientation.w = 1;
      return m;
    };
    // The torso: an elliptic column with the track's semi-axes (a 0.25 m circle when unknown).
    Marker torso = marker("torso", Marker::CYLINDER);
    torso.pose.position = point(o.x, o.y, o.z + style.person_height / 2);
    torso.pose.orientation = yawQuaternion(o.yaw);
    torso.scale.x = 2 * (t.has_shape && t.alpha > 0 ? t.alpha : 0.25);
    torso.scale.y = 2 * (t.has_shape && t.beta > 0 ? t.beta : 0.25);
    torso.scale.z = style.person_height;
    torso.color = statusColor(status, 0.5);
    out.markers.push_back(torso);

    Marker id = marker("id", Marker::TEXT_VIEW_FACING);
    id.pose.position = point(o.x, o.y, o.z + style.person_height + 0.25);
    id.scale.z = 0.3;
    id.color = color(1, 1, 1, 1);
    id.text = std::to_string(t.id) + (status == StatusCode::Following ? " (following)" : "");
    out.markers.push_back(id);

    if (std::hypot(o.vx, o.vy) > 1e-3) {
      Marker arrow = marker("velocity", Marker::ARROW);
      const double z = o.z + style.person_height / 2;
      arrow.points = {point(o.x, o.y, z),
                      point(o.x + o.vx * style.arrow_seconds, o.y + o.vy * style.arrow_seconds, z)};
      arrow.scale.x = 0.05;  // shaft diameter
      arrow.scale.y = 0.12;  // head diameter
      arrow.scale.z = 0.15;  // head length
      arrow.color = statusColor(status, 1.0);
      out.markers.push_back(arrow);
    }

    if (t.has_cov) {
      // Principal axes of the 2x2 covariance, drawn as the 95% ellipse on the ground.
      const double a = o.cov_xx, b = o.cov_xy, c = o.cov_yy;
      const double mean = (a + c) / 2, diff = std::hypot((a - c) / 2, b);
      const double l1 = std::max(0.0, mean + diff), l2 = std::max(0.0, mean - diff);
      const double angle = 0.5 * std::atan2(2 * b, a - c);
      Marker ellipse = marker("covariance", Marker::LINE_STRIP);
      const int n = 36;
      for (int k = 0; k <= n; ++k) {
        const double th = 2 * M_PI * k / n;
        const double u = kSigma95 * std::sqrt(l1) * std::cos(th);
        const double v = kSigma95 * std::sqrt(l2) * std::sin(th);
        ellipse.points.push_back(point(o.x + u * std::cos(angle) - v * std::sin(angle),
                                       o.y + u * std::sin(angle) + v * std::cos(angle),
                                       o.z + 0.02));
      }
      ellipse.scale.x = 0.02;  // line width
      ellipse.color = color(1.0, 1.0, 0.2, 0.9);
      out.markers.push_back(ellipse);
    }

    if (status == StatusCode::Following) {
      // The followed person: a bright ring on the ground around them.
      Marker ring = marker("following", Marker::LINE_STRIP);
      for (int k = 0; k <= 36; ++k) {
        const double th = 2 * M_PI * k / 36;
        ring.points.push_back(
            point(o.x + 0.6 * std::cos(th), o.y + 0.6 * std::sin(th), o.z + 0.02));
      }
      ring.scale.x = 0.08;
      ring.color = statusColor(status, 1.0);
      out.markers.push_back(ring);
    }
  }
  return out;
}

}  // namespace pedtrack::ros_plugins
