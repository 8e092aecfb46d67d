#include "pedtrack/classify/samples.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "pedtrack/errors.h"

namespace pedtrack::classify {

std::size_t SampleSet::count(Label l) const {
  return static_cast<std::size_t>(std::count(y.begin(), y.end(), l));
}

void SampleSet::append(const SampleSet& other) {
  if (features.empty() && y.empty()) features = other.features;
  if (other.features != features)
    throw ConfigError("samples with different features cannot be merged (" +
                      std::to_string(other.dims()) + " vs " + std::to_string(dims()) +
                      " features)");
  x.insert(x.end(), other.x.begin(), other.x.end());
  y.insert(y.end(), other.y.begin(), other.y.end());
}

SampleSet SampleSet::select(const std::vector<std::string>& names) const {
  std::vector<std::size_t> col;
  for (const auto& n : names) {
    const auto it = std::find(features.begin(), features.end(), n);
    if (it == features.end())
      throw ConfigError("feature '" + n + "' is not among the " + std::to_string(dims()) +
                        " the segmenters give");
    col.push_back(std::size_t(it - features.begin()));
  }
  SampleSet out;
  out.features = names;
  std::vector<double> v(names.size());
  for (std::size_t i = 0; i < size(); ++i) {
    for (std::size_t j = 0; j < col.size(); ++j) v[j] = row(i)[col[j]];
    out.add(v.data(), y[i]);
  }
  return out;
}

SampleSet SampleSet::subsample(std::size_t max, unsigned long seed) const {
  if (size() <= max) return *this;
  std::mt19937_64 rng(seed);
  // Each class gets half of `max`; what the smaller class does not use goes to the larger, so a
  // rare class (people among clutter) is never thinned while the common one is.
  const std::size_t np = count(Label::Person), nn = count(Label::NonPerson);
  const std::size_t keep_p = std::min(np, std::max(max / 2, max - std::min(nn, max)));
  const std::size_t keep_n = std::min(nn, max - keep_p);
  std::vector<std::size_t> chosen;
  for (Label l : {Label::NonPerson, Label::Person}) {
    std::vector<std::size_t> idx;
    for (std::size_t i = 0; i < size(); ++i)
      if (y[i] == l) idx.push_back(i);
    const std::size_t keep = l == Label::Person ? keep_p : keep_n;
    // A partial Fisher–Yates shuffle: the first `keep` are a uniform sample.
    for (std::size_t i = 0; i < keep && i < idx.size(); ++i) {
      std::uniform_int_distribution<std::size_t> pick(i, idx.size() - 1);
      std::swap(idx[i], idx[pick(rng)]);
    }
    idx.resize(std::min(keep, idx.size()));
    chosen.insert(chosen.end(), idx.begin(), idx.end());
  }
  // In the original order: samples stay grouped by input and time (contiguous folds rely on it).
  std::sort(chosen.begin(), chosen.end());
  SampleSet out;
  out.features = features;
  for (std::size_t i : chosen) out.add(row(i), y[i]);
  return out;
}

Standardizer Standardizer::fit(const SampleSet& s) {
  Standardizer z;
  const std::size_t d = s.dims(), n = s.size();
  z.mean.assign(d, 0);
  z.scale.assign(d, 1);
  if (n == 0) return z;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < d; ++j) z.mean[j] += s.row(i)[j] / double(n);
  for (std::size_t j = 0; j < d; ++j) {
    double v = 0;
    for (std::size_t i = 0; i < n; ++i) v += std::pow(s.row(i)[j] - z.mean[j], 2);
    const double sd = n > 1 ? std::sqrt(v / double(n - 1)) : 0;
    z.scale[j] = sd > 1e-12 ? sd : 1.0;
  }
  return z;
}

}  // namespace pedtrack::classify
