#include "pedtrack/track/heading_hypotheses.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "pedtrack/track/gaussian.h"

namespace pedtrack::track {
namespace {

constexpr double kTwoPi = 2 * M_PI;

// Gaussian density of the angle a about mu (wrapped difference), rad⁻¹.
double angleDensity(double a, double mu, double sigma) {
  const double z = wrapAngle(a - mu) / sigma;
  return std::exp(-0.5 * z * z) / (sigma * std::sqrt(kTwoPi));
}

// A child whose readings were all clutter (legs merged, a leg taken from someone or something
// else): this share of scans, explained by any heading alike.
constexpr double kClutterShare = 0.05;

void sortByWeight(std::vector<HeadingHypotheses::Hypothesis>& h) {
  std::sort(h.begin(), h.end(),
            [](const HeadingHypotheses::Hypothesis& a, const HeadingHypotheses::Hypothesis& b) {
              return a.log_w > b.log_w;
            });
}

double logSumExp(double a, double b) {
  const double m = std::max(a, b);
  return m + std::log(std::exp(a - m) + std::exp(b - m));
}

}  // namespace

std::vector<HeadingReading> legHeadingReadings(const Eigen::Vector2d& d, double w0,
                                               double sigma_leg, double floor, double sigma_other) {
  std::vector<HeadingReading> out;
  const double rho = d.norm();
  if (!(w0 > 0) || rho < 0.5 * w0) return out;
  const double beta = std::atan2(d.y(), d.x());
  // The difference of two leg positions.
  const double sd =
      sigma_other >= 0 ? std::hypot(sigma_leg, sigma_other) : std::sqrt(2.0) * sigma_leg;
  const double s_dir = sd / rho;  // the direction of d
  auto add = [&](double yaw, double sigma, bool sideways) {
    for (double flip : {0.0, M_PI})  // d, and −d (left and right the other way round)
      out.push_back({wrapAngle(yaw + flip), std::max(sigma, floor), sideways, 0.0, flip != 0});
  };
  // d = R(θ)·(L, W₀), |L| = √(ρ² − W₀²): θ = β − atan2(W₀, ±|L|).
  const double L = std::sqrt(std::max(0.0, rho * rho - w0 * w0));
  if (L <= 2 * sd) {
    // The legs passing each other: both branches are d's perpendicular, off by up to
    // atan(|L| / W₀) (|L| itself uncertain by sd).
    add(beta - M_PI / 2, std::hypot(s_dir, (L + sd) / w0), false);
    return out;
  }
  const double a = std::asin(w0 / rho);
  // θ's spread: d's direction, and asin's slope times ρ's error, dρ·W₀ / (ρ·|L|).
  const double s_branch = std::hypot(s_dir, w0 * sd / (rho * L));
  add(beta - a, s_branch, false);         // the left leg ahead (L > 0)
  add(beta - M_PI + a, s_branch, false);  // the right leg ahead (L < 0)
  add(beta - M_PI / 2, s_dir, true);      // legs opened side by side (L = 0, frontal > W₀)
  return out;
}

std::vector<HeadingReading> hiddenLegHeadingBound(const Eigen::Vector2d& d, double spread,
                                                  double softness) {
  if (d.squaredNorm() == 0) return {};
  const double perp = std::atan2(d.y(), d.x()) - M_PI / 2;
  HeadingReading r{wrapAngle(perp), softness, false, spread};
  HeadingReading mirror = r;
  mirror.yaw = wrapAngle(perp + M_PI);
  mirror.mirrored = true;
  return {r, mirror};
}

void HeadingHypotheses::capRateVariance(Eigen::Matrix3d& P) const {
  // Unseen, the rate's and the acceleration's variances would grow without bound, and after a
  // few scans of hidden legs a hypothesis could take any reading, its mirror image's too.
  const double caps[2] = {p_.rate_sigma_max, p_.accel_sigma_max};
  for (int i = 1; i < 3; ++i) {
    const double cap = caps[i - 1];
    if (!(cap > 0) || P(i, i) <= cap * cap) continue;
    const double k = cap / std::sqrt(P(i, i));
    P.row(i) *= k;
    P.col(i) *= k;
  }
}

void HeadingHypotheses::start(const Eigen::Vector3d& x, const Eigen::Matrix3d& P) {
  h_.assign(1, Hypothesis{x, P, 0.0, false, false, 0.0});
}

void HeadingHypotheses::start(std::vector<Hypothesis> hypotheses) {
  h_ = std::move(hypotheses);
  sortByWeight(h_);
}

void HeadingHypotheses::predict(double dt, double var_a, double max_rate, bool coast) {
  if (coast)
    for (Hypothesis& h : h_) h.x(2) = 0;
  if (!(dt > 0)) return;
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  F(0, 1) = F(1, 2) = dt;
  F(0, 2) = 0.5 * dt * dt;
  if (p_.turn_tau > 0) {
    // The turn rate reverts to zero: people turn in bursts.
    const double e = std::exp(-dt / p_.turn_tau);
    F(1, 1) = e;
    F(2, 2) = e;
  }
  const Eigen::Vector3d g(0.5 * dt * dt, dt, 1);
  const Eigen::Matrix3d Q = var_a * g * g.transpose();
  for (Hypothesis& h : h_) {
    h.x = F * h.x;
    h.x(0) = wrapAngle(h.x(0));
    if (max_rate > 0) h.x(1) = std::clamp(h.x(1), -max_rate, max_rate);
    h.P = F * h.P * F.transpose() + Q;
    capRateVariance(h.P);
  }
}

double HeadingHypotheses::motionLogLikelihood(double yaw, bool sideways, bool backward,
                                              const Eigen::Vector2d& v, double spread,
                                              double dt) const {
  const double speed = v.norm();
  if (speed < p_.motion_speed) return sideways ? std::log(p_.still_sideways_prior) : 0.0;
  const double psi = std::atan2(v.y(), v.x()), s = spread;
  // Relative to a direction-blind model (density 1/2π): > 0 agrees, < 0 disagrees.
  if (sideways) {
    const double side =
        0.5 * (angleDensity(psi, yaw + M_PI / 2, s) + angleDensity(psi, yaw - M_PI / 2, s));
    return std::log(p_.sideways_weight * kTwoPi * side + (1 - p_.sideways_weight));
  }
  const double along = angleDensity(psi, backward ? yaw + M_PI : yaw, s);
  const double cost = backward ? p_.backward_per_metre * speed * dt : 0.0;
  return std::log(p_.walk_weight * kTwoPi * along + (1 - p_.walk_weight)) - cost;
}

void HeadingHypotheses::update(const std::vector<HeadingReading>& readings,
                               const Eigen::Vector2d& velocity, double velocity_sigma, double dt,
                               double max_rate, bool names_uncertain) {
  const double speed = velocity.norm();
  const double spread = std::hypot(p_.motion_sigma, speed > 0 ? velocity_sigma / speed : 0.0);
  if (readings.empty() || h_.empty()) return;
  std::vector<Hypothesis> children;
  children.reserve(h_.size() * (readings.size() + 1));
  const double log_clutter = std::log(kClutterShare / kTwoPi);
  const double log_real = std::log(1 - kClutterShare);
  const double log_stop = std::log(p_.stop_turn_prior), log_go = std::log(1 - p_.stop_turn_prior);
  const double log_switch = std::log(p_.mode_switch), log_stay = std::log(1 - p_.mode_switch);
  const bool moving = speed >= p_.motion_speed;
  const double swap = names_uncertain ? p_.label_swap_hidden : p_.label_swap;
  const bool names = swap > 0 && swap < 1;  // else the names are no evidence
  const double log_rename = names ? std::log(swap) : 0.0;
  const double log_same = names ? std::log(1 - swap) : 0.0;
  for (const Hypothesis& parent : h_) {
    // The parent as predicted; stopped turning (when it was turning at all); starting a turn
    // (the turn rate's variance opened: turns in place start within a step).
    Hypothesis variants[3] = {parent, parent, parent};
    int n_variants = 1;
    double log_keep = 0;
    const double rate_sigma = std::sqrt(std::max(parent.P(1, 1), 0.0));
    if (p_.stop_turn_prior > 0 && std::abs(parent.x(1)) > rate_sigma) {
      Hypothesis& stop = variants[n_variants++];
      stop.x(1) = stop.x(2) = 0;
      stop.log_w += log_stop;
      log_keep = log_go;
    }
    if (p_.start_turn_prior > 0 && p_.start_turn_rate > 0) {
      Hypothesis& start = variants[n_variants++];
      start.P(1, 1) += p_.start_turn_rate * p_.start_turn_rate;
      start.log_w += std::log(p_.start_turn_prior);
      log_keep += std::log(1 - p_.start_turn_prior);
    }
    variants[0].log_w += log_keep;
    for (int v = 0; v < n_variants; ++v) {
      const Hypothesis& h = variants[v];
      // Every reading clutter: the hypothesis as predicted.
      Hypothesis keep = h;
      keep.log_w +=
          log_clutter + motionLogLikelihood(keep.x(0), false, keep.backward, velocity, spread, dt);
      keep.innovation = 0;
      children.push_back(keep);
      for (const HeadingReading& r : readings) {
        const double nu = wrapAngle(r.yaw - h.x(0));
        // Not the mirror image (readings come in pairs π apart): turning the facing round is
        // the motion's and the facing check's to decide, not a wide gate's.
        if (std::abs(nu) > M_PI / 2) continue;
        const double log_names = r.mirrored != h.swapped ? log_rename : log_same;
        if (r.spread > 0) {
          Hypothesis c = h;
          if (p_.hidden_turn_tau > 0 && dt > 0) {
            const double e = std::exp(-dt / p_.hidden_turn_tau);
            c.x(1) *= e;
            c.x(2) *= e;
          }
          c.swapped = r.mirrored;
          c.log_w += log_names;
          const double out = std::max(0.0, std::abs(nu) - r.spread) / std::max(r.sigma, 1e-3);
          c.innovation = 0;
          c.log_w += log_real - 0.5 * out * out +
                     motionLogLikelihood(c.x(0), false, c.backward, velocity, spread, dt);
          children.push_back(c);
          continue;
        }
        const double S = h.P(0, 0) + r.sigma * r.sigma;
        if (nu * nu > p_.gate * p_.gate * S) continue;
        Hypothesis c = h;
        c.swapped = r.mirrored;
        c.log_w += log_names;
        const Eigen::Vector3d K = h.P.col(0) / S;
        c.x = h.x + K * nu;
        c.x(0) = wrapAngle(c.x(0));
        if (max_rate > 0) c.x(1) = std::clamp(c.x(1), -max_rate, max_rate);
        c.P = h.P - K * h.P.row(0);
        c.innovation = nu;
        c.log_w += log_real - 0.5 * (nu * nu / S + std::log(kTwoPi * S));
        const bool switchable = !r.sideways && moving && p_.mode_switch > 0;
        for (int sw = 0; sw < (switchable ? 2 : 1); ++sw) {
          Hypothesis m = c;
          if (switchable) m.log_w += sw ? log_switch : log_stay;
          if (sw) m.backward = !m.backward;
          m.log_w += motionLogLikelihood(m.x(0), r.sideways, m.backward, velocity, spread, dt);
          children.push_back(m);
        }
      }
    }
  }
  sortByWeight(children);
  h_.clear();
  const double best = children.front().log_w;
  for (Hypothesis& c : children) {
    if (c.log_w < best - p_.prune_log) break;
    bool merged = false;
    for (Hypothesis& k : h_) {
      if (c.backward == k.backward && c.swapped == k.swapped &&
          std::abs(wrapAngle(c.x(0) - k.x(0))) < p_.merge_angle &&
          std::abs(c.x(1) - k.x(1)) < 10 * p_.merge_angle) {
        k.log_w = logSumExp(k.log_w, c.log_w);  // the better's state, both's weight
        merged = true;
        break;
      }
    }
    if (merged) continue;
    if (int(h_.size()) >= std::max(1, p_.count)) continue;
    h_.push_back(c);
  }
  sortByWeight(h_);
  const double top = h_.front().log_w;
  for (Hypothesis& k : h_) k.log_w -= top;
}

void HeadingHypotheses::turnAround() {
  for (Hypothesis& h : h_) {
    h.x(0) = wrapAngle(h.x(0) + M_PI);
    h.x(1) = h.x(2) = 0;
    h.backward = !h.backward;  // the same motion, seen from the other facing
    h.swapped = !h.swapped;    // and the legs' names with it
  }
}

}  // namespace pedtrack::track
