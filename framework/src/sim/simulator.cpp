#include "pedtrack/sim/simulator.h"

#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <cstdio>

#include "pedtrack/sim/clearance.h"

namespace pedtrack::sim {
namespace {

// The world's ground plane z = gx·x + gy·y seen from the robot: n_r = Rᵀ n_w, d_r = n_w · t.
GroundPlane groundInRobotFrame(const Ground& g, const mrpt::poses::CPose3D& robot) {
  const Eigen::Vector3d nw = Eigen::Vector3d(-g.gx, -g.gy, 1.0).normalized();
  const Eigen::Matrix3d R = robot.getRotationMatrix().asEigen();
  const Eigen::Vector3d nr = R.transpose() * nw;
  GroundPlane p;
  p.valid = true;
  p.nx = nr.x();
  p.ny = nr.y();
  p.nz = nr.z();
  p.d = nw.dot(Eigen::Vector3d(robot.x(), robot.y(), robot.z()));
  return p;
}

}  // namespace

Simulator::Simulator(Scenario scenario)
    : s_(std::move(scenario)),
      rays_(s_.sensor),
      caster_(rays_, s_.seed),
      maker_(s_.sensor, s_.seed),
      rng_(s_.seed) {
  frames_ = static_cast<std::size_t>(std::floor(s_.duration * s_.sensor.rate + 1e-9));
  gaits_.resize(s_.people.size());
}

bool Simulator::next(SimFrame& f) {
  if (k_ >= frames_) return false;
  f = SimFrame();
  f.index = k_;
  const double tr = k_ / s_.sensor.rate;
  f.t = s_.start_time + tr;

  // Robot: true pose on its path, odometry integrating noisy increments of it.
  const MotionSample rs = s_.robot.path.at(tr);
  f.robot_true = mrpt::poses::CPose3D(rs.x, rs.y, s_.ground.height(rs.x, rs.y), rs.yaw, 0, 0);
  if (k_ == 0) {
    odometry_ = mrpt::poses::CPose3D(rs.x, rs.y, 0, rs.yaw, 0, 0);
  } else {
    const mrpt::poses::CPose2D a(last_true_), b(f.robot_true);
    const mrpt::poses::CPose2D d = b - a;
    // Odometry errors are random walks: their variance grows with the distance travelled and
    // the angle turned, whatever the frame rate.
    const double dist = std::hypot(d.x(), d.y()), turn = std::abs(d.phi());
    std::normal_distribution<double> n01(0, 1);
    const double ex = n01(rng_), ey = n01(rng_), eyaw = n01(rng_);
    const double s_xy = s_.robot.odometry_noise * std::sqrt(dist / 2);  // per axis
    const double s_yaw = std::sqrt(std::pow(s_.robot.odometry_yaw_noise, 2) * turn +
                                   std::pow(s_.robot.odometry_yaw_drift, 2) * dist);
    const mrpt::poses::CPose2D noisy(d.x() + ex * s_xy, d.y() + ey * s_xy, d.phi() + eyaw * s_yaw);
    odometry_ = odometry_ + mrpt::poses::CPose3D(noisy);
  }
  last_true_ = f.robot_true;
  f.robot_odometry = odometry_;
  f.sensor_true = f.robot_true + s_.sensor.mount;

  // Scene: the static objects plus every person present, posed at this instant. Truth goes to
  // the odometry frame through the robot: what a perfect tracker on this odometry reports.
  const mrpt::poses::CPose2D robot2d(f.robot_true), odom2d(f.robot_odometry);
  const double dyaw = odom2d.phi() - robot2d.phi();
  auto toOdometry = [&](double wx, double wy, double& ox, double& oy) {
    double rx = 0, ry = 0;
    robot2d.inverseComposePoint(wx, wy, rx, ry);
    odom2d.composePoint(rx, ry, ox, oy);
  };
  people_.clear();
  std::vector<TruthRow> rows;
  for (std::size_t i = 0; i < s_.people.size(); ++i) {
    const PersonSpec& p = s_.people[i];
    if (tr + 1e-9 < p.appear) continue;
    MotionSample ms = p.path.at(tr - p.appear);
    gaits_[i].advance(ms, p.body);
    // The body the beam meets: posed when the sweep passes its bearing (sweep_motion), else at
    // the stamp. The truth row stays at the stamp either way.
    MotionSample seen = ms;
    if (s_.sensor.sweep_motion) {
      double sx = 0, sy = 0, sz = 0;
      f.sensor_true.inverseComposePoint(ms.x, ms.y, f.sensor_true.z(), sx, sy, sz);
      const double dt = sweepTime(s_.sensor, std::atan2(sy, sx));
      seen = p.path.at(tr + dt - p.appear);
    }
    const double gz = s_.ground.height(seen.x, seen.y);
    BodyPose pose = poseBody(p.body, seen, gaits_[i], gz, s_.leg_height, p.id);
    people_.insert(people_.end(), pose.parts.begin(), pose.parts.end());
    if (s_.sensor.sweep_motion)  // truth legs at the stamp
      pose = poseBody(p.body, ms, gaits_[i], s_.ground.height(ms.x, ms.y), s_.leg_height, p.id);
    TruthRow r;
    r.id = p.id;
    r.world_x = ms.x;
    r.world_y = ms.y;
    toOdometry(ms.x, ms.y, r.x, r.y);
    double sz = 0;
    f.sensor_true.inverseComposePoint(ms.x, ms.y, f.sensor_true.z(), r.sensor_x, r.sensor_y, sz);
    r.yaw = mrpt::math::wrapToPi(ms.yaw + dyaw);
    r.vx = std::cos(dyaw) * ms.vx - std::sin(dyaw) * ms.vy;
    r.vy = std::sin(dyaw) * ms.vx + std::cos(dyaw) * ms.vy;
    r.alpha = p.body.alpha;
    r.beta = p.body.beta;
    r.height = p.body.height;
    toOdometry(pose.left_leg.x(), pose.left_leg.y(), r.left_leg_x, r.left_leg_y);
    toOdometry(pose.right_leg.x(), pose.right_leg.y(), r.right_leg_x, r.right_leg_y);
    rows.push_back(r);
  }

  caster_.cast(f.sensor_true, {&s_.objects, &people_}, s_.ground, s_.sensor.max_range, image_);
  maker_.applyReturnPhysics(image_);
  ReturnTruth returns;
  returns.record_owners = point_truth_;
  returns.per_person.assign(s_.people.size() + 1, 0);
  auto odo = mrpt::obs::CObservationOdometry::Create();
  odo->sensorLabel = "ODOMETRY";
  odo->timestamp = mrpt::Clock::fromDouble(f.t);
  odo->odometry = mrpt::poses::CPose2D(odometry_);
  f.observations.push_back(odo);
  f.observations.push_back(maker_.make(image_, f.t, rng_, returns));
  for (auto& r : rows) r.visible_points = returns.per_person[r.id];
  f.truth = std::move(rows);
  f.point_truth = std::move(returns.owners);
  if (point_truth_) f.clearance = personClearance(image_, rays_, kClearanceCap);
  f.ground = groundInRobotFrame(s_.ground, f.robot_true);
  ++k_;
  return true;
}

LabelFrame pointTruth(const SimFrame& f) {
  LabelFrame out;
  out.index = f.index;
  out.t = f.t;
  out.plane = f.ground;
  out.labels = f.point_truth;
  out.people = f.clearance;
  return out;
}

const char* TruthCsvWriter::header() {
  return "t,frame,id,x,y,sensor_x,sensor_y,yaw,vx,vy,alpha,beta,height,visible_points,"
         "left_leg_x,left_leg_y,right_leg_x,right_leg_y,world_x,world_y";
}

void TruthCsvWriter::write(const SimFrame& f) {
  char buf[512];
  for (const TruthRow& r : f.truth) {
    const int n = std::snprintf(
        buf, sizeof buf,
        "%.6f,%zu,%d,%.4f,%.4f,%.4f,%.4f,%.5f,%.4f,%.4f,%.4f,%.4f,%.3f,%d,%.4f,%.4f,%.4f,%.4f,"
        "%.4f,%.4f\n",
        f.t, f.index, r.id, r.x, r.y, r.sensor_x, r.sensor_y, r.yaw, r.vx, r.vy, r.alpha, r.beta,
        r.height, r.visible_points, r.left_leg_x, r.left_leg_y, r.right_leg_x, r.right_leg_y,
        r.world_x, r.world_y);
    out_.write(buf, n);
  }
  frameWritten();
}

}  // namespace pedtrack::sim
