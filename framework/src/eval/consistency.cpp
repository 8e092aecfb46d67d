#include "pedtrack/eval/consistency.h"

#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <map>

namespace pedtrack::eval {

ChiSquareBounds chiSquareBounds(int dof, std::size_t n, double confidence) {
  if (dof <= 0 || n == 0) return {std::nan(""), std::nan("")};
  const boost::math::chi_squared dist(double(dof) * double(n));
  const double tail = (1 - confidence) / 2;
  return {boost::math::quantile(dist, tail) / double(n),
          boost::math::quantile(dist, 1 - tail) / double(n)};
}

double normalizedSquare(double dx, double dy, double pxx, double pxy, double pyy) {
  const double det = pxx * pyy - pxy * pxy;
  if (!(pxx > 0) || !(det > 0)) return std::nan("");
  // Inverse of a symmetric 2×2 matrix, written out.
  return (pyy * dx * dx - 2 * pxy * dx * dy + pxx * dy * dy) / det;
}

std::vector<ConsistencySample> neesSamples(const std::vector<MatchedPair>& pairs) {
  std::vector<ConsistencySample> out;
  for (const MatchedPair& p : pairs) {
    const ObjectRow* e = p.estimate.row;
    const ObjectRow* t = p.truth.row;
    if (!e || !t || !e->hasCov()) continue;
    const double v = normalizedSquare(e->x - t->x, e->y - t->y, e->cov_xx, e->cov_xy, e->cov_yy);
    if (std::isfinite(v)) out.push_back({p.truth.id, p.frame, v});
  }
  return out;
}

std::vector<ConsistencySample> nisSamples(const std::vector<MatchedPair>& pairs) {
  std::vector<ConsistencySample> out;
  for (const MatchedPair& p : pairs)
    if (p.estimate.row && std::isfinite(p.estimate.row->nis))
      out.push_back({p.truth.id, p.frame, p.estimate.row->nis});
  return out;
}

ConsistencyReport consistency(const std::vector<ConsistencySample>& samples, int dof,
                              std::size_t runs, double confidence) {
  ConsistencyReport r;
  r.dof = dof;
  r.runs = runs;
  r.samples = samples.size();
  r.nominal_bounds = chiSquareBounds(dof, runs, confidence);
  r.mean_bounds = chiSquareBounds(dof, samples.size(), confidence);
  std::map<std::pair<long, std::size_t>, std::pair<double, std::size_t>> acc;  // sum, count
  double total = 0;
  for (const ConsistencySample& s : samples) {
    auto& a = acc[{s.truth_id, s.frame}];
    a.first += s.value;
    a.second += 1;
    total += s.value;
  }
  r.mean = samples.empty() ? std::nan("") : total / double(samples.size());
  std::size_t inside = 0;
  std::map<long, ConsistencyReport::PerTruth> per;
  for (const auto& [key, a] : acc) {
    ConsistencyPoint p;
    p.truth_id = key.first;
    p.frame = key.second;
    p.n = a.second;
    p.mean = a.first / double(a.second);
    p.bounds = chiSquareBounds(dof, p.n, confidence);
    p.inside = p.mean >= p.bounds.lower && p.mean <= p.bounds.upper;
    inside += p.inside;
    auto& pt = per[p.truth_id];
    pt.id = p.truth_id;
    pt.points += 1;
    pt.mean += p.mean;
    pt.fraction_inside += p.inside;
    r.points.push_back(p);
  }
  r.fraction_inside = r.points.empty() ? std::nan("") : double(inside) / double(r.points.size());
  for (auto& [id, pt] : per) {
    pt.mean /= double(pt.points);
    pt.fraction_inside /= double(pt.points);
    r.per_truth.push_back(pt);
  }
  return r;
}

}  // namespace pedtrack::eval
