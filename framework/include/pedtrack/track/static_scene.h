#pragma once
// Static-scene suppression: which places in the fixed frame are walls, furniture or pillars, so
// that a tracker starts no person track there (the ghost tracks leg trackers are known for).
//
// A local occupancy grid of the fixed frame (MRPT's COccupancyGridMap2D, like leg_tracker's
// local grid) is built from the range returns that are NOT near a tracked person: every ray
// clears the cells it crosses and marks the cell it ends in. A cell is static once its
// occupancy has been seen over at least `persist` seconds: the span from the first hit of its
// current occupied run to its latest hit (a run ends when rays clear the cell, or when it goes
// max_gap without a hit before it is static). A person who stands still while tracked is
// excluded, so gets no hits, so never becomes static however long they stand; legs that only
// pass a cell give it a span far below `persist`. An optional prior map (a ROS map_server map
// or an MRPT grid map) marks its occupied cells static from the start. 2D scans go through
// update(), any other sensor's obstacle points (a 3D pipeline's, ground removed) through
// updatePoints(), optionally with their heights: each cell then keeps the height span of its
// run's hits, and isStatic() can ask whether a return at a given height belongs to it (the grid
// is 2D; a person beside a bench back is not the bench).
#include <mrpt/maps/COccupancyGridMap2D.h>

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "pedtrack/frame.h"

namespace pedtrack::track {

class StaticScene {
 public:
  struct Options {
    /// Grid cell size (m). 5 cm, as leg_tracker's local grid: a leg is 10-15 cm across, so a
    /// wall 20 cm behind a person does not spill into the person's cell.
    double cell = 0.05;
    /// Half-width of the local grid around the robot (m): the grid is 2·extent square (600² cells
    /// of 1 byte plus 8 bytes of run times each, 3.2 MB) and is re-centred on the robot (cells
    /// aligned, contents kept) once the max_range disc round it would leave the grid (at most
    /// every extent/4 of travel), so memory and cost stay fixed however far the robot drives.
    double extent = 15.0;
    /// Rays are used up to this range (m): nearer returns mark their cell, farther ones only
    /// clear the first max_range metres. People are tracked well inside 10 m, and the cost of a
    /// scan grows with ray length.
    double max_range = 10.0;
    /// A cell is occupied when its occupancy probability is at least this.
    double occupied = 0.7;
    /// Probability of a hit (a return in the cell) and of a pass (a ray through it), MRPT's
    /// Bayesian log-odds update. One hit makes an unknown cell occupied; a pass undoes a fifth
    /// of a hit, so a wall cell hit every other scan stays occupied, and a cell a person left
    /// is clear again after about five passes per hit it got (at most ~20, log-odds saturate).
    double p_hit = 0.85;
    double p_pass = 0.6;
    /// Seconds a cell's occupancy must have been observed (first to latest hit) before it
    /// counts as static. Longer than a walking person's stance (≤ 1 s) and than the time a
    /// tracker takes to confirm a new track (whose position is then excluded), so neither a
    /// passer-by nor a person who stops is absorbed; short enough that walls are known a few
    /// seconds after they are first seen.
    double persist = 3.0;
    /// An occupied run that is not yet static ends when its cell goes this long (s) without a
    /// hit. Where nothing lies behind a passer-by, no ray clears the cells they left, and the
    /// next person there must not inherit their age; shorter than persist, longer than the
    /// gaps between the hits a wall gets. A static cell stays static through any occlusion.
    double max_gap = 1.5;
    /// Returns within this distance (m) of a given person position are not marked: a walking
    /// person's feet are up to ~0.35 m from the track, a standing person's legs ~0.15 m plus
    /// the track's own error.
    double exclusion_radius = 0.4;
    /// Clearing stops this far (m) short of each return, so rays that graze a wall do not erase
    /// the wall cells their neighbours hit.
    double clear_margin = 0.1;
    /// Insert every Nth update() / updatePoints() call only (1 = every call). For replay far
    /// faster than real time on a slow machine; persistence is measured in sensor time, so it
    /// is unaffected.
    int update_every = 1;
    /// Clear along every Nth beam of a scan, starting at a beam that advances by one each scan
    /// (1 = every beam). Every beam still marks its hit; a still robot clears along all beams
    /// over N scans. Clearing is nearly all of the cost of a scan; 4 keeps a 768-beam scan at
    /// 5 cm cells to a few tens of µs, and a 40 Hz scanner still clears each beam at 10 Hz.
    int clear_every = 4;
    /// Scans whose plane is tilted more than this from horizontal (deg) are not used: their
    /// returns may be the floor.
    double max_tilt_deg = 5.0;
    /// Optional prior map of the fixed frame: a ROS map_server `.yaml` (with its .pgm/.png) or
    /// a serialized MRPT COccupancyGridMap2D (`.gridmap`, gzipped or not). Its cells with
    /// occupancy ≥ `occupied` are static. Empty = none. The map must be in the frame the robot
    /// poses are in (e.g. poses from a localizer on that map).
    std::string prior_map;
  };

  /// Loads the prior map when one is given; throws ConfigError for a bad option or map file.
  explicit StaticScene(const Options& o);
  StaticScene();

  /// Inserts the frame's 2D range scans (each at f.robot_pose + its own sensorPose). Returns
  /// within exclusion_radius of a person (fixed frame) do not mark their cell; the free space
  /// in front of them is still cleared. Other observation types are ignored.
  void update(const Frame& f, const std::vector<Eigen::Vector2d>& people_fixed);

  /// The same for obstacle points of any sensor (fixed frame, projected to the ground plane,
  /// ground already removed), seen from `sensor_xy_fixed` at time t (s). Every point within
  /// max_range marks its cell unless near a person; space is cleared up to the nearest point
  /// in each ~0.25° of bearing (free space up to the first obstacle, as a 2D scan would see it).
  /// `heights` (one per point, m above the ground; ignored when of another size) are kept per
  /// cell for the height-aware isStatic().
  void updatePoints(double t, const Eigen::Vector2d& sensor_xy_fixed,
                    const std::vector<Eigen::Vector2d>& points_fixed,
                    const std::vector<Eigen::Vector2d>& people_fixed,
                    const std::vector<float>* heights = nullptr);

  /// True when the place (x, y) (fixed frame) is static at time t: its cell's occupancy was
  /// seen over ≥ persist seconds up to t, or the prior map has it occupied. With radius > 0,
  /// true when any cell within radius (m) is static (a leg-circle centre lies a few cm behind
  /// the surface it was fitted to).
  bool isStatic(double x, double y, double t, double radius = 0) const;
  /// The same for a return at height z: true when z lies within z_margin of the heights the
  /// static cells within radius were hit at, taken together (a person's head above a bench or
  /// a car bonnet is no part of it). A cell learned without heights holds any z; z NaN: 2D.
  bool isStatic(double x, double y, double z, double z_margin, double t, double radius) const;

  /// Forgets everything the grid learned (the prior map stays): the fixed frame moved by an
  /// unknown amount (Frame::motion_unknown), so what was learned may now lie anywhere.
  void forget();

  /// Occupancy probability of the local grid at (x, y) (0.5 = unknown, also outside the grid).
  double occupancy(double x, double y) const;

  /// The local grid (MRPT stores freeness: getCell() = 1 − occupancy), e.g. for rendering.
  const mrpt::maps::COccupancyGridMap2D& grid() const { return grid_; }
  /// The prior map, or null without one.
  const mrpt::maps::COccupancyGridMap2D* prior() const { return prior_.get(); }
  /// Writes the local grid as an image (format from the extension, e.g. .png); false on error.
  bool saveImage(const std::string& file) const { return grid_.saveAsBitmapFile(file); }

  const Options& options() const { return opt_; }

  /// Reads a ROS map_server `.yaml`/`.yml` or a serialized COccupancyGridMap2D; throws
  /// ConfigError naming the file and what is wrong with it.
  static std::unique_ptr<mrpt::maps::COccupancyGridMap2D> loadMap(const std::string& file);

 private:
  using Cell = mrpt::maps::COccupancyGridMap2D::cellType;
  /// When the current occupied run of a cell started and when it was last hit (s since t0_);
  /// NaN start = not in a run.
  struct Run {
    float since, last;
    float zlo, zhi;  ///< heights of the run's hits (NaN: learned without heights)
  };
  bool beginUpdate(double t, double sensor_x, double sensor_y);
  void recentre(double x, double y);
  /// Clears from the sensor (sx, sy) to each of clear_to_, then marks the cells of hits_, at
  /// time t (all fixed frame).
  void castRays(double sx, double sy, double t);
  void setPeople(const std::vector<Eigen::Vector2d>& people);
  bool nearPerson(double x, double y, const std::vector<Eigen::Vector2d>& people) const;
  bool cellStatic(int cx, int cy, float t_rel) const;
  /// Whether test(i, j) holds for the cell of g holding (x, y) or any cell with a part within
  /// radius of it (defined in the .cpp, its only user).
  template <class Test>
  static bool anyCell(double x, double y, double radius, const mrpt::maps::COccupancyGridMap2D& g,
                      Test&& test);

  Options opt_;
  mrpt::maps::COccupancyGridMap2D grid_;
  std::vector<Run> runs_;  ///< one per grid cell, row-major like the grid
  std::unique_ptr<mrpt::maps::COccupancyGridMap2D> prior_;
  Cell l_hit_ = 0, l_pass_ = 0, l_occupied_ = 0;  ///< log-odds increments and threshold
  double t0_ = 0;
  bool started_ = false;
  long calls_ = 0;
  long scans_ = 0;
  std::vector<Eigen::Vector2d> clear_to_, hits_;  ///< scratch, reused
  std::vector<float> hit_z_;                      ///< heights of hits_ (empty: none)
  Eigen::Vector2d people_lo_, people_hi_;         ///< box round this update's exclusion discs
  std::vector<float> bin_range_;                  ///< scratch for updatePoints
  std::vector<std::uint32_t> bin_pt_;             ///< scratch for updatePoints
};

}  // namespace pedtrack::track
