// `svm`: P4 §2.1's classifier. Each cluster's feature vector (by the model's feature names: P4's
// four torso features, or any segmenter's) is standardised and scored by the model's RBF SVM;
// the decision value is mapped to a calibrated probability (Platt), and a cluster whose
// probability reaches `threshold` becomes a detection whose score is that probability.
#include "pedtrack/classify/svm.h"

#include "pedtrack/classify/cluster_scoring.h"
#include "pedtrack/classify/model_file.h"
#include "pedtrack/plugin.h"

namespace pedtrack::svmplugin {
namespace {

using namespace pedtrack::classify;

class Svm : public Classifier {
 public:
  explicit Svm(const PluginContext& ctx)
      : svm_(loadSvmModel(ctx.params.getString("model")).svm),
        gather_(ctx.params.getString("model"), svm_->features()),
        threshold_(ctx.params.getDouble("threshold")),
        shape_(parseDetectionShape(ctx.params.getString("shape"))) {}

  void process(Frame& f) override {
    gather_.gather(f, rows_, cluster_of_);
    svm_->probability(rows_.data(), cluster_of_.size(), scores_);
    appendDetections(f, cluster_of_, scores_, threshold_, shape_);
  }

 private:
  std::unique_ptr<SvmClassifier> svm_;
  FeatureGather gather_;
  double threshold_;
  DetectionShape shape_;
  std::vector<double> rows_, scores_;
  std::vector<int> cluster_of_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Classifier;
  d.doc = "RBF SVM person classifier (P4) with a calibrated probability";
  d.params = {
      ParamSpec::inputFile("model", "SVM model file (`pedtrack train svm`; models/*.yml)"),
      ParamSpec::real("threshold", 0.5, "", 0, 1,
                      "a cluster whose calibrated person probability is ≥ this is a detection"),
      ParamSpec::choice("shape", "auto", {"auto", "none", "ellipse"},
                        "detection shape: ellipse = torso ellipse fitted to a 2D segment; auto: "
                        "ellipse for torso-height segments, none for legs and 3D clusters"),
  };
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<Svm>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::svmplugin

PEDTRACK_PLUGIN("svm", pedtrack::svmplugin::describe)
