// `forest`: a random forest person classifier (classify/forest.h; ours). Each cluster's feature
// vector (by the model's feature names: P2's six and the shape features of voxel_ccl, or any
// segmenter's) is scored by the share of the model's trees voting "person", and a cluster whose
// share reaches `threshold` becomes a detection with that score.
#include "pedtrack/classify/forest.h"

#include "pedtrack/classify/cluster_scoring.h"
#include "pedtrack/classify/model_file.h"
#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"

namespace pedtrack::forestplugin {
namespace {

using namespace pedtrack::classify;

struct ForestParams {
  std::string model;
  double threshold = 0.5;  // share of trees voting person
  DetectionShapeParams output;
};

const ParamTable<ForestParams>& table() {
  using P = ForestParams;
  static const auto t =
      ParamTable<P>()
          .inputFile(&P::model, "model",
                     "random forest model file (`pedtrack train forest`; models/*.yml)")
          .real(&P::threshold, "threshold", "", 0, 1,
                "a cluster whose share of trees voting person is ≥ this is a detection")
          .include(&P::output, detectionShapeTable());
  return t;
}

class Forest : public ScoringClassifier {
 public:
  explicit Forest(const PluginContext& ctx) : Forest(table().read(ctx.params)) {}
  explicit Forest(const ForestParams& p) : Forest(p, loadForestModel(p.model)) {}

 protected:
  void score(const double* rows, std::size_t n, std::vector<double>& out) override {
    forest_->probability(rows, n, out);
  }

 private:
  Forest(const ForestParams& p, LoadedForest m)
      : ScoringClassifier(p.model, m.forest->features(), p.threshold, p.output.shape),
        forest_(std::move(m.forest)) {}
  std::unique_ptr<ForestClassifier> forest_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Classifier;
  d.doc = "Random forest person classifier (OpenCV RTrees): the share of trees voting person";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<Forest>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::forestplugin

PEDTRACK_PLUGIN("forest", pedtrack::forestplugin::describe)
