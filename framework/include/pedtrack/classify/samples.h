#pragma once
// Labelled feature vectors: what `pedtrack train` collects from recordings and simulations and
// what a classifier learns from.
#include <cstddef>
#include <string>
#include <vector>

namespace pedtrack::classify {

/// One class per sample: a person (or a person's leg) or anything else.
enum class Label : int { NonPerson = 0, Person = 1 };

struct SampleSet {
  std::vector<std::string> features;  ///< names, one per column
  std::vector<double> x;              ///< row-major, size() × dims()
  std::vector<Label> y;

  std::size_t size() const { return y.size(); }
  std::size_t dims() const { return features.size(); }
  const double* row(std::size_t i) const { return x.data() + i * dims(); }
  void add(const double* v, Label label) {
    x.insert(x.end(), v, v + dims());
    y.push_back(label);
  }
  std::size_t count(Label l) const;
  /// Every sample of `other` (same feature names, else ConfigError).
  void append(const SampleSet& other);
  /// The columns named `names`, in that order (ConfigError naming a missing one).
  SampleSet select(const std::vector<std::string>& names) const;
  /// At most `max` samples drawn at random (seeded): up to half from each class, the rest of
  /// the budget from whichever class has more.
  SampleSet subsample(std::size_t max, unsigned long seed) const;
};

/// Per-feature mean and standard deviation (1 where a feature is constant).
struct Standardizer {
  std::vector<double> mean, scale;
  static Standardizer fit(const SampleSet& s);
  void apply(const double* in, double* out) const {
    for (std::size_t j = 0; j < mean.size(); ++j) out[j] = (in[j] - mean[j]) / scale[j];
  }
};

}  // namespace pedtrack::classify
