#include "pedtrack/eval/pair_errors.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

namespace pedtrack::eval {
namespace {

double ratio(double sum, std::size_t n) {
  return n ? sum / double(n) : std::nan("");
}

bool finite2(double a, double b) {
  return std::isfinite(a) && std::isfinite(b);
}

}  // namespace

double wrapAngle(double a) {
  return mrpt::math::wrapToPi(a);  // ]−π, π]
}

double PairErrors::rmse() const {
  return std::sqrt(ratio(sq_sum, pairs));
}
double PairErrors::mae() const {
  return ratio(abs_sum, pairs);
}
double PairErrors::rmseX() const {
  return std::sqrt(ratio(sq_x, pairs));
}
double PairErrors::rmseY() const {
  return std::sqrt(ratio(sq_y, pairs));
}
double PairErrors::headingMae() const {
  return ratio(heading_sum, heading_pairs);
}
double PairErrors::majorMae() const {
  return ratio(major_sum, shape_pairs);
}
double PairErrors::minorMae() const {
  return ratio(minor_sum, shape_pairs);
}
double PairErrors::speedMae() const {
  return ratio(speed_sum, speed_pairs);
}
double PairErrors::velocityRmse() const {
  return std::sqrt(ratio(velocity_sq_sum, speed_pairs));
}

PairErrors& PairErrors::operator+=(const PairErrors& o) {
  pairs += o.pairs;
  sq_sum += o.sq_sum;
  abs_sum += o.abs_sum;
  sq_x += o.sq_x;
  sq_y += o.sq_y;
  heading_pairs += o.heading_pairs;
  heading_sum += o.heading_sum;
  shape_pairs += o.shape_pairs;
  major_sum += o.major_sum;
  minor_sum += o.minor_sum;
  speed_pairs += o.speed_pairs;
  speed_sum += o.speed_sum;
  velocity_sq_sum += o.velocity_sq_sum;
  return *this;
}

PairErrors pairErrors(const std::vector<MatchedPair>& pairs) {
  PairErrors e;
  for (const MatchedPair& p : pairs) {
    const double dx = p.estimate.x - p.truth.x, dy = p.estimate.y - p.truth.y;
    ++e.pairs;
    e.sq_x += dx * dx;
    e.sq_y += dy * dy;
    e.sq_sum += dx * dx + dy * dy;
    e.abs_sum += std::hypot(dx, dy);
    const ObjectRow* r = p.estimate.row;
    const ObjectRow* t = p.truth.row;
    if (!r || !t) continue;
    if (std::isfinite(r->yaw) && std::isfinite(t->yaw)) {
      ++e.heading_pairs;
      e.heading_sum += std::fabs(wrapAngle(r->yaw - t->yaw));
    }
    if (r->hasShape() && t->hasShape()) {
      ++e.shape_pairs;
      e.major_sum += std::fabs(std::max(r->alpha, r->beta) - std::max(t->alpha, t->beta));
      e.minor_sum += std::fabs(std::min(r->alpha, r->beta) - std::min(t->alpha, t->beta));
    }
    if (finite2(r->vx, r->vy) && finite2(t->vx, t->vy)) {
      ++e.speed_pairs;
      e.speed_sum += std::fabs(std::hypot(r->vx, r->vy) - std::hypot(t->vx, t->vy));
      e.velocity_sq_sum += std::pow(r->vx - t->vx, 2) + std::pow(r->vy - t->vy, 2);
    }
  }
  return e;
}

}  // namespace pedtrack::eval
