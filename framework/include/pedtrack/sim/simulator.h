#pragma once
// Steps a scenario frame by frame: moves robot and people, ray-casts the scan, and returns the
// MRPT observations (odometry + scan) a real robot would log, with the ground truth.
#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose3D.h>

#include <random>
#include <vector>

#include "pedtrack/outputs.h"
#include "pedtrack/point_labels.h"
#include "pedtrack/sim/raycast.h"
#include "pedtrack/sim/scenario.h"

namespace pedtrack::sim {

/// One person at one frame (truth.csv row).
struct TruthRow {
  int id = 0;
  /// Torso centre (m) in the odometry frame: the fixed frame a pipeline tracks in, which is the
  /// world frame when odometry is exact and drifts from it with odometry noise.
  double x = 0, y = 0;
  double world_x = 0, world_y = 0;    ///< torso centre in the world frame
  double sensor_x = 0, sensor_y = 0;  ///< torso centre in the true sensor frame
  double yaw = 0;                     ///< facing, rad, odometry frame
  double vx = 0, vy = 0;              ///< m/s, odometry frame
  double alpha = 0, beta = 0, height = 0;
  int visible_points = 0;  ///< returns the scan produced on this person
  double left_leg_x = 0, left_leg_y = 0, right_leg_x = 0, right_leg_y = 0;  ///< odometry frame
};

struct SimFrame {
  std::size_t index = 0;
  double t = 0;  ///< UNIX s
  mrpt::poses::CPose3D robot_true, robot_odometry, sensor_true;
  std::vector<mrpt::obs::CObservation::Ptr> observations;  ///< CObservationOdometry, then scan
  std::vector<TruthRow> truth;
  /// Who each return of the scan hit, in Frame::cloud() order (point_labels.h truth labels).
  std::vector<std::int32_t> point_truth;
  /// The true ground plane in the robot frame (the robot's true pose).
  GroundPlane ground;
  /// Every person the scan hit, with its clearance from everything else hit (sim/clearance.h).
  std::vector<PersonClearance> clearance;
};

class Simulator {
 public:
  explicit Simulator(Scenario scenario);
  std::size_t frameCount() const { return frames_; }
  /// Produces the next frame; false after the last.
  bool next(SimFrame& out);
  /// Whether frames carry point_truth and clearance (on by default; ~15 % of a VLP-16 frame's
  /// cost, so a run that writes no truth turns it off).
  void setPointTruth(bool on) { point_truth_ = on; }
  const Scenario& scenario() const { return s_; }
  /// The bodies of the people present in the last frame, posed as the rays met them (tests).
  const std::vector<Primitive>& posedPeople() const { return people_; }

 private:
  Scenario s_;
  RayTable rays_;
  RayCaster caster_;
  ObservationMaker maker_;
  std::size_t frames_ = 0, k_ = 0;
  std::mt19937_64 rng_;
  std::vector<GaitClock> gaits_;
  mrpt::poses::CPose3D odometry_, last_true_;
  RangeImage image_;
  std::vector<Primitive> people_;  // this frame's posed bodies, reused
  bool point_truth_ = true;
};

/// The per-point truth of a frame as a truth label record (truth_points.bin).
LabelFrame pointTruth(const SimFrame& f);

/// Streams truth.csv: `t,frame,id,x,y,sensor_x,sensor_y,yaw,vx,vy,alpha,beta,height,
/// visible_points,left_leg_x,left_leg_y,right_leg_x,right_leg_y,world_x,world_y`.
class TruthCsvWriter : public CsvStream {
 public:
  explicit TruthCsvWriter(const std::string& path) : CsvStream(path, header()) {}
  void write(const SimFrame& f);
  static const char* header();
};

}  // namespace pedtrack::sim
