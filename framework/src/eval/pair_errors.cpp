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
double PairErrors::headingRmse() const {
  return std::sqrt(ratio(heading_sq_sum, heading_pairs));
}
double PairErrors::axisRmse() const {
  return std::sqrt(ratio(axis_sq_sum, heading_pairs));
}
double PairErrors::sagittalMae() const {
  return ratio(sagittal_sum, body_pairs);
}
double PairErrors::frontalMae() const {
  return ratio(frontal_sum, body_pairs);
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
  heading_sq_sum += o.heading_sq_sum;
  axis_sq_sum += o.axis_sq_sum;
  body_pairs += o.body_pairs;
  sagittal_sum += o.sagittal_sum;
  frontal_sum += o.frontal_sum;
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
    if (std::isfinite(t->yaw)) {
      // The rows' fixed-frame positions, not the compared ones: yaw is a fixed-frame angle, and
      // with --frame sensor the compared error is rotated by the (unknown here) sensor heading.
      const double ex = r->x - t->x, ey = r->y - t->y;
      const double c = std::cos(t->yaw), s = std::sin(t->yaw);
      ++e.body_pairs;
      e.sagittal_sum += std::fabs(c * ex + s * ey);
      e.frontal_sum += std::fabs(-s * ex + c * ey);
    }
    if (std::isfinite(r->yaw) && std::isfinite(t->yaw)) {
      ++e.heading_pairs;
      const double d = wrapAngle(r->yaw - t->yaw);
      e.heading_sum += std::fabs(d);
      e.heading_sq_sum += d * d;
      const double a = d - M_PI * std::round(d / M_PI);  // modulo π: [−π/2, π/2]
      e.axis_sq_sum += a * a;
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

double RangeBand::alphaMean() const {
  return ratio(alpha_sum, shape_rows);
}
double RangeBand::betaMean() const {
  return ratio(beta_sum, shape_rows);
}
double RangeBand::probMean(std::size_t model) const {
  return model < prob_rows.size() ? ratio(prob_sum[model], prob_rows[model]) : std::nan("");
}

RangeBandReport rangeBands(const std::vector<MatchedPair>& pairs, const std::vector<double>& edges,
                           const ModelProbsOf& probs) {
  RangeBandReport rep;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    RangeBand b;
    b.from = edges[i];
    b.to = i + 1 < edges.size() ? edges[i + 1] : INFINITY;
    rep.bands.push_back(b);
  }
  for (const MatchedPair& p : pairs) {
    const ObjectRow* r = p.estimate.row;
    const double range = r ? std::hypot(r->sensor_x, r->sensor_y) : std::nan("");
    // The last band whose lower edge the range reaches.
    auto it = std::upper_bound(edges.begin(), edges.end(), range);
    if (!std::isfinite(range) || it == edges.begin()) {
      ++rep.unbanded;
      continue;
    }
    RangeBand& b = rep.bands[std::size_t(it - edges.begin()) - 1];
    b.errors += pairErrors({p});
    if (r->hasShape()) {
      ++b.shape_rows;
      b.alpha_sum += r->alpha;
      b.alpha_min = std::min(b.alpha_min, r->alpha);
      b.alpha_max = std::max(b.alpha_max, r->alpha);
      b.beta_sum += r->beta;
      b.beta_min = std::min(b.beta_min, r->beta);
      b.beta_max = std::max(b.beta_max, r->beta);
    }
    const std::vector<double>* pr = probs ? probs(*r) : nullptr;
    if (!pr) continue;
    if (b.prob_sum.size() < pr->size()) {
      b.prob_sum.resize(pr->size(), 0);
      b.prob_rows.resize(pr->size(), 0);
    }
    for (std::size_t m = 0; m < pr->size(); ++m)
      if (std::isfinite((*pr)[m])) b.prob_sum[m] += (*pr)[m], ++b.prob_rows[m];
    rep.models = std::max(rep.models, pr->size());
  }
  return rep;
}

}  // namespace pedtrack::eval
