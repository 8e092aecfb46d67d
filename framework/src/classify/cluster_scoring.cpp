#include "pedtrack/classify/cluster_scoring.h"

#include <algorithm>
#include <cmath>

#include "pedtrack/errors.h"
#include "pedtrack/fit/ellipse.h"

namespace pedtrack::classify {

FeatureGather::FeatureGather(std::string model_path, std::vector<std::string> model_features)
    : path_(std::move(model_path)), features_(std::move(model_features)) {}

void FeatureGather::gather(const Frame& f, std::vector<double>& rows,
                           std::vector<int>& cluster_of) {
  rows.clear();
  cluster_of.clear();
  if (f.clusters.empty()) return;
  if (!f.cluster_feature_names)
    throw ConfigError(path_ + ": the clusters carry no features (put a segmenter that computes " +
                      features_.front() + ", ... before the classifier)");
  // Bind model features to the segmenter's columns once per distinct name list.
  if (bound_to_ != f.cluster_feature_names.get()) {
    const auto& names = *f.cluster_feature_names;
    column_.clear();
    for (const auto& want : features_) {
      const auto it = std::find(names.begin(), names.end(), want);
      if (it == names.end())
        throw ConfigError(path_ + ": the model needs feature '" + want +
                          "', which the segmenter does not compute (it has " +
                          std::to_string(names.size()) + " features; see clusters.csv)");
      column_.push_back(std::size_t(it - names.begin()));
    }
    bound_to_ = f.cluster_feature_names.get();
  }
  rows.reserve(f.clusters.size() * features_.size());
  for (std::size_t c = 0; c < f.clusters.size(); ++c) {
    const auto& v = f.clusters[c].features;
    bool ok = true;
    for (std::size_t col : column_) ok = ok && col < v.size() && std::isfinite(v[col]);
    if (!ok) continue;  // a malformed cluster is never a detection, never a crash
    for (std::size_t col : column_) rows.push_back(v[col]);
    cluster_of.push_back(int(c));
  }
}

namespace {
bool has(const Frame& f, const char* name) {
  return f.clusterFeatureIndex(name) >= 0;
}
}  // namespace

void appendDetections(Frame& f, const std::vector<int>& cluster_of,
                      const std::vector<double>& scores, double threshold, DetectionShape shape) {
  if (shape == DetectionShape::Auto)
    shape = has(f, "ellipse_a") && !has(f, "leg_radius") ? DetectionShape::Ellipse
                                                         : DetectionShape::None;
  const double robot_yaw = f.robot_pose.yaw();
  fit::Points2 pts;
  for (std::size_t r = 0; r < cluster_of.size(); ++r) {
    if (!(scores[r] >= threshold)) continue;
    const Cluster& c = f.clusters[std::size_t(cluster_of[r])];
    Detection d;
    d.cluster = cluster_of[r];
    d.score = scores[r];
    double cx = c.cx, cy = c.cy;
    if (shape == DetectionShape::Ellipse && c.indices.size() >= 5) {
      const auto& cloud = f.cloud();
      const auto& xs = cloud.getPointsBufferRef_x();
      const auto& ys = cloud.getPointsBufferRef_y();
      pts.clear();
      for (std::uint32_t i : c.indices) pts.emplace_back(xs[i], ys[i]);
      fit::Ellipse e;
      // A torso is well under a metre across; a larger fit is a flat arc, not a shape.
      if (fit::fitEllipseDirect(pts, e) && e.a < 0.6 && std::isfinite(e.x) && std::isfinite(e.y)) {
        cx = e.x, cy = e.y;
        d.alpha = e.a;
        d.beta = e.b;
        d.yaw = std::remainder(robot_yaw + e.angle, 2 * M_PI);
      }
    }
    double gz = 0;
    f.robot_pose.composePoint(cx, cy, c.cz, d.x, d.y, gz);
    f.detections.push_back(d);
  }
}

const ParamTable<DetectionShapeParams>& detectionShapeTable() {
  static const auto t = ParamTable<DetectionShapeParams>().choice(
      &DetectionShapeParams::shape, "shape",
      {{"auto", DetectionShape::Auto},
       {"none", DetectionShape::None},
       {"ellipse", DetectionShape::Ellipse}},
      "detection shape: ellipse = torso ellipse fitted to a 2D segment; auto: ellipse for "
      "torso-height segments, none for legs and 3D clusters");
  return t;
}

ScoringClassifier::ScoringClassifier(const std::string& model_path,
                                     std::vector<std::string> model_features, double threshold,
                                     DetectionShape shape)
    : gather_(model_path, std::move(model_features)), threshold_(threshold), shape_(shape) {}

void ScoringClassifier::process(Frame& f) {
  gather_.gather(f, rows_, cluster_of_);
  score(rows_.data(), cluster_of_.size(), scores_);
  appendDetections(f, cluster_of_, scores_, threshold_, shape_);
}

}  // namespace pedtrack::classify
