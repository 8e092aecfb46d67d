#pragma once
// What the classifier plugins share: reading a model's features out of the frame's clusters (by
// name, so a model works after any segmenter that computes its features) and turning scored
// clusters into detections with the tracker's measurement.
#include <string>
#include <vector>

#include "pedtrack/frame.h"
#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"

namespace pedtrack::classify {

/// The feature rows of a frame's clusters in a model's feature order.
class FeatureGather {
 public:
  FeatureGather(std::string model_path, std::vector<std::string> model_features);
  /// Rows of every cluster of `f` (row-major, clusters × features) whose features are all
  /// finite; `cluster_of` maps each row to its cluster. Throws ConfigError naming the model and
  /// the feature when the frame's segmenter does not compute one the model needs.
  void gather(const Frame& f, std::vector<double>& rows, std::vector<int>& cluster_of);

 private:
  std::string path_;
  std::vector<std::string> features_;
  const std::vector<std::string>* bound_to_ = nullptr;
  std::vector<std::size_t> column_;
};

/// Which shape a detection carries.
enum class DetectionShape {
  None,     ///< position only
  Ellipse,  ///< a torso ellipse fitted to the cluster's points (2D segments)
  Auto,     ///< Ellipse for 2D segments with ellipse features that are not legs, else None
};

/// Appends to f.detections one detection per row whose score ≥ threshold: the cluster's position
/// (or fitted ellipse centre) in the fixed frame, the score and the shape.
void appendDetections(Frame& f, const std::vector<int>& cluster_of,
                      const std::vector<double>& scores, double threshold, DetectionShape shape);

/// The `shape` key every classifier plugin declares: include() it in the plugin's table.
struct DetectionShapeParams {
  DetectionShape shape = DetectionShape::Auto;
};
const ParamTable<DetectionShapeParams>& detectionShapeTable();

/// A classifier stage: each frame, the model's features of every cluster are scored by score()
/// and the clusters scoring at least `threshold` become detections. A plugin supplies score().
class ScoringClassifier : public Classifier {
 public:
  ScoringClassifier(const std::string& model_path, std::vector<std::string> model_features,
                    double threshold, DetectionShape shape);
  void process(Frame& f) override;

 protected:
  /// Scores of n feature vectors (row-major, n × model features), in [0, 1].
  virtual void score(const double* rows, std::size_t n, std::vector<double>& out) = 0;

 private:
  FeatureGather gather_;
  double threshold_;
  DetectionShape shape_;
  std::vector<double> rows_, scores_;
  std::vector<int> cluster_of_;
};

}  // namespace pedtrack::classify
