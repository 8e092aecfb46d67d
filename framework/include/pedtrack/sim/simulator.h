#pragma once
// Steps a scenario frame by frame: moves robot and people, ray-casts the scan, and returns the
// MRPT observations (odometry + scan) a real robot would log, with the ground truth.
#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose3D.h>

#include <ostream>
#include <random>
#include <vector>

#include "pedtrack/sim/scenario.h"

namespace pedtrack::sim {

/// One person at one frame (truth.csv row).
struct TruthRow {
  int id = 0;
  double x = 0, y = 0;                ///< torso centre, m, world (= odometry) frame
  double sensor_x = 0, sensor_y = 0;  ///< torso centre in the true sensor frame
  double yaw = 0;                     ///< facing, rad
  double vx = 0, vy = 0;              ///< m/s
  double alpha = 0, beta = 0, height = 0;
  int visible_points = 0;  ///< returns the scan produced on this person
  double left_leg_x = 0, left_leg_y = 0, right_leg_x = 0, right_leg_y = 0;
};

struct SimFrame {
  std::size_t index = 0;
  double t = 0;  ///< UNIX s
  mrpt::poses::CPose3D robot_true, robot_odometry, sensor_true;
  std::vector<mrpt::obs::CObservation::Ptr> observations;  ///< CObservationOdometry, then scan
  std::vector<TruthRow> truth;
  int static_points = 0, ground_points = 0;
};

class Simulator {
 public:
  explicit Simulator(Scenario scenario);
  std::size_t frameCount() const { return frames_; }
  /// Produces the next frame; false after the last.
  bool next(SimFrame& out);
  const Scenario& scenario() const { return s_; }

 private:
  Scenario s_;
  RayTable rays_;
  ObservationMaker maker_;
  std::size_t frames_ = 0, k_ = 0;
  std::mt19937_64 rng_;
  std::vector<GaitClock> gaits_;
  mrpt::poses::CPose3D odometry_, last_true_;
  RangeImage image_;
};

/// truth.csv: `t,frame,id,x,y,sensor_x,sensor_y,yaw,vx,vy,alpha,beta,height,visible_points,
/// left_leg_x,left_leg_y,right_leg_x,right_leg_y`.
const char* truthCsvHeader();
void writeTruthRows(std::ostream& out, const SimFrame& f);

}  // namespace pedtrack::sim
