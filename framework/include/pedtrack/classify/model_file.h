#pragma once
// Classifier model files (models/*.yml): OpenCV FileStorage YAML that says what it is — format
// version, classifier kind, the feature names it reads (in order), its scaling, the command and
// data it was trained with — followed by the classifier itself (k-NN prototypes and metric, or
// the SVM and its calibration) and an end marker, so a truncated file is recognised as such.
//
// Every reading problem (missing file, not a model, other version, wrong kind, truncated,
// inconsistent sizes) is a ConfigError whose one line names the file.
#include <memory>
#include <string>
#include <vector>

#include "pedtrack/classify/forest.h"
#include "pedtrack/classify/knn.h"
#include "pedtrack/classify/svm.h"

namespace pedtrack::classify {

constexpr int kModelFormatVersion = 1;

/// What a model says about itself.
struct ModelInfo {
  std::string kind;                         ///< "knn", "svm" or "forest"
  std::vector<std::string> features;        ///< names, in the order the classifier reads them
  std::string command;                      ///< the command line that trained it
  std::string dataset;                      ///< the training data (files, parts, labelling)
  std::size_t persons = 0, nonpersons = 0;  ///< training samples per class
  std::string created;                      ///< UTC time of training
};

void saveKnnModel(const std::string& path, const ModelInfo& info, const KnnClassifier& knn);
void saveSvmModel(const std::string& path, const ModelInfo& info, const SvmClassifier& svm);
void saveForestModel(const std::string& path, const ModelInfo& info, const ForestClassifier& f);

struct LoadedKnn {
  ModelInfo info;
  SampleSet prototypes;
  KnnMetricStats stats;
  KnnOptions options;  ///< the options it was trained with
};
LoadedKnn loadKnnModel(const std::string& path);

struct LoadedSvm {
  ModelInfo info;
  std::unique_ptr<SvmClassifier> svm;
};
LoadedSvm loadSvmModel(const std::string& path);

struct LoadedForest {
  ModelInfo info;
  std::unique_ptr<ForestClassifier> forest;
};
LoadedForest loadForestModel(const std::string& path);

/// The kind a model file holds ("knn" or "svm"), checking format and version.
std::string modelKind(const std::string& path);

/// Any model, scoring feature vectors: Q for k-NN, the calibrated probability for SVM, the share
/// of trees voting person for a forest (all in [0, 1], a person at ≥ 0.5 by default).
class Scorer {
 public:
  virtual ~Scorer();
  virtual const ModelInfo& info() const = 0;
  /// Scores of n feature vectors (row-major, n × info().features.size()).
  virtual void score(const double* x, std::size_t n, std::vector<double>& out) const = 0;
};
/// Loads a model of either kind; `knn` (when given) replaces a k-NN model's trained options.
std::unique_ptr<Scorer> loadScorer(const std::string& path, const KnnOptions* knn = nullptr);

}  // namespace pedtrack::classify
