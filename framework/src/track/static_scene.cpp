#include "pedtrack/track/static_scene.h"

#include <mrpt/containers/yaml.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/filesystem.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "pedtrack/errors.h"

namespace pedtrack::track {

using mrpt::maps::COccupancyGridMap2D;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr int kBearingBins = 1440;  // updatePoints: a clearing ray per 0.25° of bearing (mean)

// MRPT exception texts span several lines (with a call stack); a ConfigError is one line.
std::string firstLine(const std::string& s) {
  const auto nl = s.find('\n');
  return nl == std::string::npos ? s : s.substr(0, nl);
}

bool endsWith(std::string s, const std::string& suffix) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::unique_ptr<COccupancyGridMap2D> loadRosMap(const std::string& file) {
  // MRPT's own loader does the work; it only says true/false (and prints why to stderr), so the
  // usual faults are found here first to name them in the error.
  mrpt::containers::yaml y;
  try {
    y = mrpt::containers::yaml::FromFile(file);
  } catch (const std::exception& e) {
    throw ConfigError("prior map " + file + ": not valid YAML (" + firstLine(e.what()) + ")");
  }
  if (!y.isMap())
    throw ConfigError("prior map " + file + ": not a ROS map_server map (expected a YAML map)");
  for (const char* key :
       {"image", "resolution", "origin", "negate", "occupied_thresh", "free_thresh"})
    if (!y.has(key)) throw ConfigError("prior map " + file + ": missing key '" + key + "'");
  std::string image;
  double resolution = 0;
  std::size_t origin_size = 0;
  try {
    image = y["image"].as<std::string>();
    resolution = y["resolution"].as<double>();
    origin_size = y["origin"].asSequence().size();
  } catch (const std::exception& e) {
    throw ConfigError("prior map " + file + ": bad image, resolution or origin (" +
                      firstLine(e.what()) + ")");
  }
  if (!(resolution > 0)) throw ConfigError("prior map " + file + ": resolution must be > 0");
  if (origin_size < 2) throw ConfigError("prior map " + file + ": origin must be [x, y, yaw]");
  const std::string image_path =
      mrpt::system::pathJoin({mrpt::system::extractFileDirectory(file), image});
  if (!mrpt::system::fileExists(image_path))
    throw ConfigError("prior map " + file + ": image " + image_path + " not found");
  auto grid = std::make_unique<COccupancyGridMap2D>();
  if (!grid->loadFromROSMapServerYAML(file))
    throw ConfigError("prior map " + file + ": cannot be read as a ROS map (image " + image_path +
                      " unreadable or a value of the wrong type)");
  return grid;
}

std::unique_ptr<COccupancyGridMap2D> loadMrptMap(const std::string& file) {
  try {
    mrpt::io::CFileGZInputStream in(file);  // reads plain files as well as gzipped ones
    auto obj = mrpt::serialization::archiveFrom(in).ReadObject();
    if (auto g = std::dynamic_pointer_cast<COccupancyGridMap2D>(obj))
      return std::make_unique<COccupancyGridMap2D>(*g);
    if (auto mm = std::dynamic_pointer_cast<mrpt::maps::CMultiMetricMap>(obj))
      if (auto g = mm->mapByClass<COccupancyGridMap2D>())
        return std::make_unique<COccupancyGridMap2D>(*g);
    throw std::runtime_error(std::string("it holds a ") +
                             (obj ? obj->GetRuntimeClass()->className : "null object"));
  } catch (const std::exception& e) {
    throw ConfigError("prior map " + file +
                      ": not a ROS map .yaml nor a serialized MRPT COccupancyGridMap2D (" +
                      firstLine(e.what()) + ")");
  }
}

}  // namespace

std::unique_ptr<COccupancyGridMap2D> StaticScene::loadMap(const std::string& file) {
  if (!mrpt::system::fileExists(file)) throw ConfigError("prior map " + file + ": no such file");
  if (endsWith(file, ".yaml") || endsWith(file, ".yml")) return loadRosMap(file);
  return loadMrptMap(file);
}

StaticScene::StaticScene() : StaticScene(Options()) {}

StaticScene::StaticScene(const Options& o) : opt_(o) {
  auto check = [](bool ok, const char* what) {
    if (!ok) throw ConfigError(std::string("static scene: ") + what);
  };
  check(opt_.cell > 0.005, "cell must be > 0.005 m");
  check(opt_.extent > 0 && opt_.extent / opt_.cell <= 10000,
        "extent must be > 0 and at most 10000 cells");
  check(opt_.max_range > 0, "max_range must be > 0");
  check(opt_.occupied > 0.5 && opt_.occupied < 1, "occupied must be in (0.5, 1)");
  check(opt_.p_hit > 0.5 && opt_.p_hit < 1, "p_hit must be in (0.5, 1)");
  check(opt_.p_pass > 0.5 && opt_.p_pass < 1, "p_pass must be in (0.5, 1)");
  check(opt_.persist >= 0, "persist must be >= 0");
  check(opt_.max_gap > 0, "max_gap must be > 0");
  check(opt_.exclusion_radius >= 0, "exclusion_radius must be >= 0");
  check(opt_.clear_margin >= 0, "clear_margin must be >= 0");
  check(opt_.update_every >= 1, "update_every must be >= 1");
  check(opt_.clear_every >= 1, "clear_every must be >= 1");
  // MRPT cells hold the log-odds of being FREE (positive = free), 8 or 16 bits.
  l_hit_ = std::max<Cell>(1, COccupancyGridMap2D::p2l(float(opt_.p_hit)));
  l_pass_ = std::max<Cell>(1, COccupancyGridMap2D::p2l(float(opt_.p_pass)));
  l_occupied_ = COccupancyGridMap2D::p2l(float(1 - opt_.occupied));
  if (!opt_.prior_map.empty()) prior_ = loadMap(opt_.prior_map);
}

void StaticScene::forget() {
  if (!started_) return;
  started_ = false;
  grid_ = COccupancyGridMap2D();
  runs_.clear();
}

bool StaticScene::beginUpdate(double t, double sensor_x, double sensor_y) {
  if (calls_++ % opt_.update_every != 0) return false;
  if (!started_) {
    started_ = true;
    t0_ = t;
    recentre(sensor_x, sensor_y);
    return true;
  }
  // Re-centre once the max_range disk round the sensor would leave the grid (but not more often
  // than every extent/4 of travel, when max_range is about the extent).
  const double cx = 0.5 * (grid_.getXMin() + grid_.getXMax());
  const double cy = 0.5 * (grid_.getYMin() + grid_.getYMax());
  const double slack = std::max(opt_.extent - opt_.max_range, 0.25 * opt_.extent);
  if (std::abs(sensor_x - cx) > slack || std::abs(sensor_y - cy) > slack)
    recentre(sensor_x, sensor_y);
  return true;
}

void StaticScene::recentre(double x, double y) {
  // Cell-aligned with the old grid (both on multiples of the cell size), so cells copy 1:1.
  const double res = opt_.cell;
  const long half = std::lround(opt_.extent / res);
  const double x0 = (std::lround(x / res) - half) * res, y0 = (std::lround(y / res) - half) * res;
  COccupancyGridMap2D g;
  g.setSize(float(x0), float(x0 + 2 * half * res), float(y0), float(y0 + 2 * half * res),
            float(res), 0.5f);
  const int w = int(g.getSizeX()), h = int(g.getSizeY());
  std::vector<Run> runs(std::size_t(w) * h, Run{kNaN, kNaN, kNaN, kNaN});
  if (!runs_.empty()) {
    const int ow = int(grid_.getSizeX()), oh = int(grid_.getSizeY());
    const int dx = int(std::lround((g.getXMin() - grid_.getXMin()) / res));
    const int dy = int(std::lround((g.getYMin() - grid_.getYMin()) / res));
    const int i0 = std::max(0, -dx), i1 = std::min(w, ow - dx);
    for (int j = std::max(0, -dy); j < std::min(h, oh - dy) && i0 < i1; ++j) {
      std::copy(grid_.getRow(j + dy) + i0 + dx, grid_.getRow(j + dy) + i1 + dx, g.getRow(j) + i0);
      std::copy(runs_.begin() + (std::size_t(j + dy) * ow + i0 + dx),
                runs_.begin() + (std::size_t(j + dy) * ow + i1 + dx),
                runs.begin() + (std::size_t(j) * w + i0));
    }
  }
  grid_ = std::move(g);
  runs_ = std::move(runs);
}

void StaticScene::setPeople(const std::vector<Eigen::Vector2d>& people) {
  people_lo_ = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  people_hi_ = -people_lo_;
  for (const auto& p : people) {
    people_lo_ = people_lo_.cwiseMin(p);
    people_hi_ = people_hi_.cwiseMax(p);
  }
  people_lo_.array() -= opt_.exclusion_radius;
  people_hi_.array() += opt_.exclusion_radius;
}

bool StaticScene::nearPerson(double x, double y, const std::vector<Eigen::Vector2d>& people) const {
  // Most returns are nowhere near anyone: one box test for all of them.
  if (x < people_lo_.x() || y < people_lo_.y() || x > people_hi_.x() || y > people_hi_.y())
    return false;
  const double r2 = opt_.exclusion_radius * opt_.exclusion_radius;
  for (const auto& p : people)
    if ((p.x() - x) * (p.x() - x) + (p.y() - y) * (p.y() - y) < r2) return true;
  return false;
}

void StaticScene::update(const Frame& f, const std::vector<Eigen::Vector2d>& people_fixed) {
  const auto scans = [&] {
    std::vector<const mrpt::obs::CObservation2DRangeScan*> v;
    for (const auto& o : f.observations)
      if (auto s = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(o.get())) v.push_back(s);
    return v;
  }();
  if (scans.empty() || !beginUpdate(f.t, f.robot_pose.x(), f.robot_pose.y())) return;
  setPeople(people_fixed);
  const double cos_tilt = std::cos(opt_.max_tilt_deg * M_PI / 180);
  for (const auto* scan : scans) {
    const mrpt::poses::CPose3D pose = f.robot_pose + scan->sensorPose;
    const auto R = pose.getRotationMatrix();
    if (std::abs(R(2, 2)) < cos_tilt) continue;
    const std::size_t n = scan->getScanSize();
    if (n == 0) continue;
    // Beam directions by rotating the first one step by step: no trigonometry per beam.
    const double a0 = scan->getScanAngle(0);
    const double da = n > 1 ? scan->getScanAngle(1) - a0 : 0.0;
    double c = std::cos(a0), s = std::sin(a0);
    const double cd = std::cos(da), sd = std::sin(da);
    const double sx = pose.x(), sy = pose.y();
    const double no_return = std::min<double>(scan->maxRange, 1e9);
    // Beams clear_every apart clear, from a first beam that advances by one each scan.
    int skip = int(scans_++ % opt_.clear_every);
    clear_to_.clear();
    hits_.clear();
    hit_z_.clear();
    const Eigen::Vector2d sensor(sx, sy);
    for (std::size_t i = 0; i < n; ++i) {
      // Packed 2-vectors throughout: built from two scalars, the points cost a stalled
      // store-to-load forward each when appended.
      const Eigen::Vector2d u(R(0, 0) * c + R(0, 1) * s, R(1, 0) * c + R(1, 1) * s);
      const double cn = c * cd - s * sd;
      s = s * cd + c * sd;
      c = cn;
      const bool clear = skip-- == 0;
      if (clear) skip = opt_.clear_every - 1;
      if (!scan->getScanRangeValidity(i)) continue;  // no echo says nothing reliable
      const double r = scan->getScanRange(i);
      if (!(r > 0)) continue;
      const bool in_range = r < opt_.max_range && r < no_return;
      const Eigen::Vector2d hit = sensor + r * u;
      if (in_range && !nearPerson(hit.x(), hit.y(), people_fixed)) hits_.push_back(hit);
      const double rc = in_range ? r - opt_.clear_margin : std::min(r, opt_.max_range);
      if (clear && rc > 0) clear_to_.push_back(sensor + rc * u);
    }
    castRays(sx, sy, f.t);
  }
}

void StaticScene::updatePoints(double t, const Eigen::Vector2d& sensor_xy_fixed,
                               const std::vector<Eigen::Vector2d>& points_fixed,
                               const std::vector<Eigen::Vector2d>& people_fixed,
                               const std::vector<float>* heights) {
  if (!beginUpdate(t, sensor_xy_fixed.x(), sensor_xy_fixed.y())) return;
  if (heights && heights->size() != points_fixed.size()) heights = nullptr;
  setPeople(people_fixed);
  const double sx = sensor_xy_fixed.x(), sy = sensor_xy_fixed.y();
  // Unlike a 2D scan, points are no rays: many share a bearing at different heights. Clearing
  // only up to the nearest of each bearing keeps a table top from being erased by the wall
  // behind it, and bounds the cost by the bins rather than by the points.
  bin_range_.assign(kBearingBins, std::numeric_limits<float>::infinity());
  bin_pt_.assign(kBearingBins, 0);
  clear_to_.clear();
  hits_.clear();
  hit_z_.clear();
  const double max2 = opt_.max_range * opt_.max_range;
  for (std::size_t k = 0; k < points_fixed.size(); ++k) {
    const double dx = points_fixed[k].x() - sx, dy = points_fixed[k].y() - sy;
    const double r2 = dx * dx + dy * dy;  // squared: no root per point
    if (!(r2 > 1e-6)) continue;
    // The "diamond angle", monotonic in bearing, in [0, 4): no atan2 per point, for bins
    // between 0.18° and 0.35° wide.
    const double ax = std::abs(dx), ay = std::abs(dy);
    const double d = dy >= 0 ? (dx >= 0 ? ay / (ax + ay) : 2 - ay / (ax + ay))
                             : (dx < 0 ? 2 + ay / (ax + ay) : 4 - ay / (ax + ay));
    const int b = std::min(kBearingBins - 1, int(d * (kBearingBins / 4)));
    if (r2 < bin_range_[b]) {
      bin_range_[b] = float(r2);
      bin_pt_[b] = std::uint32_t(k);
    }
    if (r2 < max2 && !nearPerson(points_fixed[k].x(), points_fixed[k].y(), people_fixed)) {
      hits_.push_back(points_fixed[k]);
      if (heights) hit_z_.push_back((*heights)[k]);
    }
  }
  for (int b = 0; b < kBearingBins; ++b) {
    if (!std::isfinite(bin_range_[b])) continue;
    const auto& p = points_fixed[bin_pt_[b]];
    const double r = std::hypot(p.x() - sx, p.y() - sy);
    const double rc = r < opt_.max_range ? r - opt_.clear_margin : opt_.max_range;
    if (rc <= 0) continue;
    clear_to_.emplace_back(sx + (p.x() - sx) * rc / r, sy + (p.y() - sy) * rc / r);
  }
  castRays(sx, sy, t);
}

void StaticScene::castRays(double sx, double sy, double t) {
  const double res = opt_.cell, xmin = grid_.getXMin(), ymin = grid_.getYMin();
  const int w = int(grid_.getSizeX()), h = int(grid_.getSizeY());
  const double gx0 = (sx - xmin) / res, gy0 = (sy - ymin) / res;
  if (!(gx0 >= 0.5 && gx0 < w - 0.5 && gy0 >= 0.5 && gy0 < h - 0.5)) return;  // off the grid
  Cell* const cells = grid_.getRow(0);
  constexpr int kMin = COccupancyGridMap2D::OCCGRID_CELLTYPE_MIN;
  constexpr int kMax = COccupancyGridMap2D::OCCGRID_CELLTYPE_MAX;

  // Free space first, then the hits: a ray that grazes a wall must not erase a hit of the same
  // scan. MRPT's insertObservation clears and marks the same way (integer ray walk, log-odds
  // saturating at the cell type's limits) but says nothing about which cells changed, and the
  // persistence clock needs each cell's change to occupied; hence this walk over its cells.
  for (const Eigen::Vector2d& to : clear_to_) {
    double gx1 = (to.x() - xmin) / res, gy1 = (to.y() - ymin) / res;
    // Clip the far end to the grid less half a cell (the sensor end is inside that too), so
    // the samples below, within half a cell of the line's ends, stay on the grid.
    double s = 1;
    const double ex = gx1 - gx0, ey = gy1 - gy0, hi_x = w - 0.5, hi_y = h - 0.5;
    if (gx1 < 0.5) s = std::min(s, (0.5 - gx0) / ex);
    if (gx1 > hi_x) s = std::min(s, (hi_x - gx0) / ex);
    if (gy1 < 0.5) s = std::min(s, (0.5 - gy0) / ey);
    if (gy1 > hi_y) s = std::min(s, (hi_y - gy0) / ey);
    gx1 = std::clamp(gx0 + s * ex, 0.5, hi_x);
    gy1 = std::clamp(gy0 + s * ey, 0.5, hi_y);
    // One cell per column (or row) of the longer axis, the one the exact line crosses at the
    // column's centre; the shorter axis in 32.32 fixed point, stepping by at most one cell.
    // Bresenham's cells without its mispredicted branch, and from the true sensor position:
    // lines between cell centres would all share a few slopes and leave cells on diagonals
    // nearly never crossed.
    const bool x_major = std::abs(gx1 - gx0) >= std::abs(gy1 - gy0);
    const double a0 = x_major ? gx0 : gy0, a1 = x_major ? gx1 : gy1;
    const double b0 = x_major ? gy0 : gx0, b1 = x_major ? gy1 : gx1;
    const int ia0 = int(a0), ia1 = int(a1), n = std::abs(ia1 - ia0), dir = ia1 >= ia0 ? 1 : -1;
    const double slope = a1 != a0 ? (b1 - b0) / (a1 - a0) : 0.0;
    constexpr double kOne = 4294967296.0;  // 2^32
    std::int64_t fb = std::llround((b0 + (ia0 + 0.5 - a0) * slope) * kOne);
    const std::int64_t inc = std::llround(dir * slope * kOne);
    const long major = x_major ? dir : dir * long(w), minor = x_major ? long(w) : 1;
    int ib = int(fb >> 32);
    Cell* p = cells + (x_major ? std::size_t(ib) * w + ia0 : std::size_t(ia0) * w + ib);
    for (int k = 0; k <= n; ++k) {
      *p = Cell(std::min(kMax, int(*p) + l_pass_));
      fb += inc;
      const int nb = int(fb >> 32);
      p += major + (nb - ib) * minor;
      ib = nb;
    }
  }
  const float tr = float(t - t0_), persist = float(opt_.persist), max_gap = float(opt_.max_gap);
  const bool with_z = hit_z_.size() == hits_.size();
  for (std::size_t n = 0; n < hits_.size(); ++n) {
    const Eigen::Vector2d& hit = hits_[n];
    const double gx = (hit.x() - xmin) / res, gy = (hit.y() - ymin) / res;
    if (!(gx >= 0 && gx < w && gy >= 0 && gy < h)) continue;
    const std::size_t k = std::size_t(int(gy)) * w + std::size_t(int(gx));
    Cell& c = cells[k];
    const bool was_occupied = c <= l_occupied_;
    c = Cell(std::max(kMin, int(c) - l_hit_));
    if (c > l_occupied_) continue;
    // A new occupied run starts when the cell was not occupied, or when a run that is not yet
    // static was not hit for max_gap: where nothing behind them clears the cells a passer-by
    // left, the next passer-by must not inherit their age. A static cell stays static through
    // any occlusion, until rays clear it.
    Run& run = runs_[k];
    const bool is_static = run.last - run.since >= persist;  // false while since is NaN
    const float z = with_z ? hit_z_[n] : kNaN;
    if (!was_occupied || std::isnan(run.since) || (!is_static && tr - run.last > max_gap)) {
      run.since = tr;
      run.zlo = run.zhi = z;
    } else if (!std::isnan(run.zlo)) {  // a run begun without heights stays without
      run.zlo = std::min(run.zlo, z);   // a hit without height (NaN) leaves them as they are
      run.zhi = std::max(run.zhi, z);
    }
    run.last = tr;
  }
}

bool StaticScene::cellStatic(int cx, int cy, float t_rel) const {
  const int w = int(grid_.getSizeX()), h = int(grid_.getSizeY());
  if (cx < 0 || cy < 0 || cx >= w || cy >= h) return false;
  const std::size_t k = std::size_t(cy) * w + cx;
  if (grid_.getRow(cy)[cx] > l_occupied_) return false;
  const Run& run = runs_[k];
  return !std::isnan(run.since) && std::min(t_rel, run.last) - run.since >= float(opt_.persist);
}

template <class Test>
bool StaticScene::anyCell(double x, double y, double radius, const COccupancyGridMap2D& g,
                          Test&& test) {
  // The cell holding (x, y), and every cell with a part within radius of it (a prior map's
  // cells may be far larger than the radius).
  const double res = g.getResolution(), gx = (x - g.getXMin()) / res, gy = (y - g.getYMin()) / res;
  const int cx = int(std::floor(gx)), cy = int(std::floor(gy));
  if (test(cx, cy)) return true;
  const double rr = radius / res;
  const int k = int(std::ceil(rr));
  for (int j = cy - k; j <= cy + k; ++j)
    for (int i = cx - k; i <= cx + k; ++i) {
      const double ex = std::max({i - gx, 0.0, gx - (i + 1)});
      const double ey = std::max({j - gy, 0.0, gy - (j + 1)});
      if (ex * ex + ey * ey <= rr * rr && test(i, j)) return true;
    }
  return false;
}

bool StaticScene::isStatic(double x, double y, double t, double radius) const {
  return isStatic(x, y, kNaN, 0, t, radius);
}

bool StaticScene::isStatic(double x, double y, double z, double z_margin, double t,
                           double radius) const {
  if (prior_) {
    const float free_below = float(1 - opt_.occupied);
    // getCell() is 0.5 (unknown) off the map.
    if (anyCell(x, y, radius, *prior_,
                [&](int i, int j) { return prior_->getCell(i, j) <= free_below; }))
      return true;
  }
  if (!started_) return false;
  const float t_rel = float(t - t0_);
  const int w = int(grid_.getSizeX());
  if (std::isnan(z))
    return anyCell(x, y, radius, grid_, [&](int i, int j) { return cellStatic(i, j, t_rel); });
  // The heights the static cells round (x, y) were hit at, together (porous foliage hits each
  // cell on a ring or two only; the object spans them all).
  // The span only grows, so the first cell that brings z within it settles the answer.
  float lo = INFINITY, hi = -INFINITY;
  return anyCell(x, y, radius, grid_, [&](int i, int j) {
    if (!cellStatic(i, j, t_rel)) return false;
    const Run& run = runs_[std::size_t(j) * w + i];
    if (std::isnan(run.zlo)) return true;
    lo = std::min(lo, run.zlo);
    hi = std::max(hi, run.zhi);
    return z >= lo - z_margin && z <= hi + z_margin;
  });
}

double StaticScene::occupancy(double x, double y) const {
  if (!started_) return 0.5;
  return 1.0 - grid_.getPos(float(x), float(y));
}

}  // namespace pedtrack::track
