#include "pedtrack/track/shape_tracker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "pedtrack/track/gnn.h"
#include "pedtrack/track/kalman.h"

namespace pedtrack::track {
namespace {

Imm makeImm(const ShapeTrackerParams& p, const std::shared_ptr<const ShapeUnicycle>& motion) {
  if (p.models.empty()) throw std::invalid_argument("a shape tracker needs an observation model");
  const std::size_t n = p.models.size();
  Eigen::MatrixXd pi = p.transition;
  if (pi.size() == 0 && n == 1) pi = Eigen::MatrixXd::Identity(1, 1);
  if (std::size_t(pi.rows()) != n || std::size_t(pi.cols()) != n)
    throw std::invalid_argument(std::to_string(n) + " observation models need a " +
                                std::to_string(n) + " x " + std::to_string(n) +
                                " transition matrix");
  return Imm(std::vector<std::shared_ptr<const MotionModel>>(n, motion), pi);
}

// θ → θ + π, v → −v: the same motion. The covariance transforms with J = diag(1, 1, 1, −1, 1, 1).
void flipHeading(Gaussian& g) {
  g.x(2) = wrapAngle(g.x(2) + M_PI);
  g.x(3) = -g.x(3);
  g.P.row(3) *= -1;
  g.P.col(3) *= -1;
}

}  // namespace

ShapeTrackerParams::ShapeTrackerParams() {
  // P1 Table I lists Q per 0.1 s frame; the heading and speed random walks get its unit
  // entries, the semi-axes its 10⁻⁴ (see README "Torso shape tracking").
  q_rates = (Eigen::VectorXd(6) << 0, 0, 10, 10, 1e-3, 1e-3).finished();
  transition = (Eigen::MatrixXd(3, 3) << 0.99, 0.005, 0.005, 0.005, 0.99, 0.005, 0.005, 0.005, 0.99)
                   .finished();
}

ShapeTracker::ShapeTracker(ShapeTrackerParams params)
    : p_(std::move(params)),
      motion_(std::make_shared<ShapeUnicycle>(p_.q_rates)),
      imm_(makeImm(p_, motion_)),
      rng_(p_.seed) {
  accept_.q_person = p_.q_person;
  accept_.q_min = p_.q_min;
}

std::vector<ShapeTracker::Candidate> ShapeTracker::candidates(const Frame& f) const {
  std::vector<Candidate> out;
  const auto& cloud = f.cloud();
  const auto& xs = cloud.getPointsBufferRef_x();
  const auto& ys = cloud.getPointsBufferRef_y();
  const Eigen::Vector2d origin(f.sensor_pose.x(), f.sensor_pose.y());
  const double c = std::cos(f.robot_pose.yaw()), s = std::sin(f.robot_pose.yaw());
  const double rx = f.robot_pose.x(), ry = f.robot_pose.y();
  for (std::size_t i = 0; i < f.detections.size(); ++i) {
    const Detection& d = f.detections[i];
    if (!accept_.accepts(d.score, true)) continue;
    Candidate cand;
    cand.detection = int(i);
    cand.cluster = d.cluster;
    cand.score = d.score;
    cand.cloud.origin = origin;
    if (d.cluster >= 0 && std::size_t(d.cluster) < f.clusters.size()) {
      // The torso band (P0 drops the legs below 0.6 m). A cluster with no point in it (a low
      // box, a kerb, the top of a hedge) has no torso: it is no person, whatever its score.
      for (std::uint32_t k : f.clusters[d.cluster].indices) {
        if (k >= xs.size()) continue;
        const double h = f.heightOf(k);
        if (h < p_.fit_min_height || h > p_.fit_max_height) continue;
        // Robot frame → fixed frame (the robot's planar pose; its tilt is the ground stage's).
        cand.cloud.points.emplace_back(rx + c * xs[k] - s * ys[k], ry + s * xs[k] + c * ys[k]);
      }
      if (cand.cloud.points.empty()) continue;
    } else {
      cand.cloud.points.emplace_back(d.x, d.y);  // a detection without points: its position
    }
    cand.position = fit::centroidBehindSurface(cand.cloud.points, origin, p_.cog_beta);
    out.push_back(std::move(cand));
  }
  return out;
}

// Every mode's heading on the same branch as the most probable mode's, so mixing and combining
// average nearby angles: a mode facing the other way is the same motion with θ + π and −v.
void ShapeTracker::align(ImmState& s) const {
  Eigen::Index best = 0;
  s.mu.maxCoeff(&best);
  const double ref = wrapAngle(s.modes[best].x(2));
  for (Gaussian& g : s.modes) {
    double d = wrapAngle(g.x(2) - ref);
    if (std::abs(d) > M_PI / 2) {
      flipHeading(g);
      d = wrapAngle(g.x(2) - ref);
    }
    g.x(2) = ref + d;
  }
}

ShapeTracker::ShapeTrack ShapeTracker::birth(const Candidate& c) {
  ShapeFits fits(c.cloud, {}, p_.observation, rng_);
  Gaussian g;
  g.x = Eigen::VectorXd::Zero(6);
  const Eigen::Vector2d to_sensor = c.cloud.origin - c.position;
  g.x << c.position.x(), c.position.y(), std::atan2(to_sensor.y(), to_sensor.x()), 0, p_.cog_alpha,
      p_.cog_beta;
  // The first model (in the tracker's order) that measures the full shape sets it; else the
  // first that measures a position sets that.
  bool have_position = false;
  for (ShapeModel model : p_.models) {
    const auto m = fits.measure(model);
    if (!m) continue;
    const Eigen::MatrixXd& H = m->model.H;
    const Eigen::VectorXd x = H.transpose() * m->z;  // the observed states (H selects them)
    if (m->z.size() == 5) {
      for (int k : {0, 1, 2, 4, 5}) g.x(k) = x(k);
      break;
    }
    if (!have_position) g.x.head<2>() = x.head<2>();
    if (model == ShapeModel::Circle) g.x(4) = g.x(5) = m->z(2);
    have_position = true;
  }
  // Facing direction unknown: a walker seen from behind ends up with v < 0 and is turned round
  // by align(); the shape fixes θ modulo π well.
  const Eigen::VectorXd r = p_.observation.r_ellipse;
  g.P = Eigen::MatrixXd::Zero(6, 6);
  g.P(0, 0) = g.P(1, 1) = p_.observation.r_cog(0);
  g.P(2, 2) = r(2);
  g.P(3, 3) = p_.init_speed_sigma * p_.init_speed_sigma;
  g.P(4, 4) = g.P(5, 5) = 0.05 * 0.05;
  ShapeTrack t{ids_.next(), imm_.init(g), MOfN(p_.confirm_hits, p_.confirm_window, p_.max_misses)};
  t.life.step(true);
  t.score = c.score;
  t.cluster = c.cluster;
  return t;
}

void ShapeTracker::update(ShapeTrack& t, const Candidate& c) {
  ShapeFits fits(c.cloud, Imm::combine(t.imm).x, p_.observation, rng_);
  Eigen::VectorXd ll(p_.models.size());
  for (std::size_t j = 0; j < p_.models.size(); ++j) {
    ll(j) = -std::numeric_limits<double>::infinity();
    Gaussian& g = t.imm.modes[j];
    if (auto m = fits.measure(p_.models[j])) ll(j) = kalmanUpdate(g, m->model, m->z).log_likelihood;
    if (p_.models[j] == ShapeModel::Cog) {
      // P1 §II-D: the COG model does not estimate the size; it keeps P1's fixed semi-axes.
      g.x(4) = p_.cog_alpha;
      g.x(5) = p_.cog_beta;
    }
    g.x(4) = std::max(g.x(4), 0.01);
    g.x(5) = std::max(g.x(5), 0.01);
  }
  Imm::updateProbabilities(t.imm, ll);
  align(t.imm);
  // The shapes fix θ modulo π only; the motion says which way the person faces. Once the person
  // walks backwards faster than flip_speed, every mode turns round (θ + π, −v: the same motion).
  if (Imm::combine(t.imm).x(3) < -p_.flip_speed)
    for (Gaussian& g : t.imm.modes) flipHeading(g);
  t.life.step(true);
  t.misses = 0;
  t.score = c.score;
  t.cluster = c.cluster;
}

void ShapeTracker::process(Frame& f) {
  const double dt = clock_.step(f.t);
  for (ShapeTrack& t : tracks_) {
    align(t.imm);
    imm_.predict(t.imm, dt);
  }
  const std::vector<Candidate> cands = candidates(f);
  std::vector<Eigen::Vector2d> predicted;
  for (const ShapeTrack& t : tracks_) predicted.push_back(Imm::combine(t.imm).x.head<2>());
  const Assignment a = gnnAssociate(
      int(tracks_.size()), int(cands.size()),
      [&](int r, int i) { return (cands[i].position - predicted[r]).norm(); }, p_.gate);
  std::vector<char> taken(cands.size(), 0);
  std::vector<ShapeTrack> kept;
  for (std::size_t k = 0; k < tracks_.size(); ++k) {
    ShapeTrack& t = tracks_[k];
    const int i = a.row_to_col[k];
    if (i >= 0) {
      taken[i] = 1;
      update(t, cands[i]);
    } else {
      ++t.misses;
      t.cluster = -1;
      if (t.life.step(false) == TrackStatus::Deleted) continue;
    }
    kept.push_back(std::move(t));
  }
  tracks_ = std::move(kept);
  for (std::size_t i = 0; i < cands.size(); ++i)
    if (!taken[i] && cands[i].score >= p_.q_person &&
        int(cands[i].cloud.points.size()) >= p_.birth_points)
      tracks_.push_back(birth(cands[i]));
  report(f);
}

void ShapeTracker::report(Frame& f) {
  for (ShapeTrack& t : tracks_) {
    const bool confirmed = t.life.status() == TrackStatus::Confirmed;
    if (!confirmed && !p_.report_tentative) continue;
    align(t.imm);
    const Gaussian g = Imm::combine(t.imm);
    Track row = trackRow(t.id, g, *motion_);
    row.yaw = wrapAngle(g.x(2));  // the facing direction, also when standing still
    row.alpha = g.x(4);
    row.beta = g.x(5);
    row.has_shape = true;
    row.score = t.score;
    row.model_probs.assign(t.imm.mu.data(), t.imm.mu.data() + t.imm.mu.size());
    row.status = !confirmed ? "tentative" : t.misses ? "coasting" : "confirmed";
    row.cluster = t.cluster;
    f.tracks.push_back(std::move(row));
  }
}

}  // namespace pedtrack::track
