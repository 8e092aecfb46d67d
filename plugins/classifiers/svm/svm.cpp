// `svm`: P4 §2.1's classifier. Each cluster's feature vector (by the model's feature names: P4's
// four torso features, or any segmenter's) is standardised and scored by the model's RBF SVM;
// the decision value is mapped to a calibrated probability (Platt), and a cluster whose
// probability reaches `threshold` becomes a detection whose score is that probability.
#include "pedtrack/classify/svm.h"

#include "pedtrack/classify/cluster_scoring.h"
#include "pedtrack/classify/model_file.h"
#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"

namespace pedtrack::svmplugin {
namespace {

using namespace pedtrack::classify;

struct SvmParams {
  std::string model;
  double threshold = 0.5;  // calibrated person probability
  DetectionShapeParams output;
};

const ParamTable<SvmParams>& table() {
  using P = SvmParams;
  static const auto t =
      ParamTable<P>()
          .inputFile(&P::model, "model", "SVM model file (`pedtrack train svm`; models/*.yml)")
          .real(&P::threshold, "threshold", "", 0, 1,
                "a cluster whose calibrated person probability is ≥ this is a detection")
          .include(&P::output, detectionShapeTable());
  return t;
}

class Svm : public ScoringClassifier {
 public:
  explicit Svm(const PluginContext& ctx) : Svm(table().read(ctx.params)) {}
  explicit Svm(const SvmParams& p) : Svm(p, loadSvmModel(p.model)) {}

 protected:
  void score(const double* rows, std::size_t n, std::vector<double>& out) override {
    svm_->probability(rows, n, out);
  }

 private:
  Svm(const SvmParams& p, LoadedSvm m)
      : ScoringClassifier(p.model, m.svm->features(), p.threshold, p.output.shape),
        svm_(std::move(m.svm)) {}
  std::unique_ptr<SvmClassifier> svm_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Classifier;
  d.doc = "RBF SVM person classifier (P4) with a calibrated probability";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<Svm>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::svmplugin

PEDTRACK_PLUGIN("svm", pedtrack::svmplugin::describe)
