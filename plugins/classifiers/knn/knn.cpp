// `knn`: P2's appearance classifier (§3.3, §5.2). Each cluster's feature vector (by the model's
// feature names: [h, w, d, v, λ, ρ] after voxel_ccl, the segment features after scan_segments)
// goes to the k nearest prototypes of the model under the Mahalanobis metric of eq. 5; their
// weighted votes give the quality Q = W_P / (W_P + W_P̄), and a cluster with Q ≥ Q_P becomes a
// detection whose score is Q.
#include "pedtrack/classify/knn.h"

#include "pedtrack/classify/cluster_scoring.h"
#include "pedtrack/classify/model_file.h"
#include "pedtrack/errors.h"
#include "pedtrack/plugin.h"

namespace pedtrack::knnplugin {
namespace {

using namespace pedtrack::classify;

KnnClassifier load(const PluginContext& ctx) {
  const std::string path = ctx.params.getString("model");
  LoadedKnn m = loadKnnModel(path);
  KnnOptions o = m.options;
  try {
    if (ctx.params.getInt("k") > 0) o.k = int(ctx.params.getInt("k"));
    if (ctx.params.getString("metric") != "model")
      o.metric = parseKnnMetric(ctx.params.getString("metric"));
    if (ctx.params.getInt("minkowski_p") > 0) o.minkowski_p = int(ctx.params.getInt("minkowski_p"));
    if (ctx.params.getString("weighting") != "model")
      o.weighting = parseKnnWeighting(ctx.params.getString("weighting"));
  } catch (const ConfigError& e) {
    throw ConfigError(ctx.params.where("model") + ": " + e.what());
  }
  return KnnClassifier(std::move(m.prototypes), std::move(m.stats), o);
}

class Knn : public ScoringClassifier {
 public:
  explicit Knn(const PluginContext& ctx) : Knn(ctx, load(ctx)) {}

 protected:
  void score(const double* rows, std::size_t n, std::vector<double>& out) override {
    out.resize(n);
    for (std::size_t r = 0; r < n; ++r) out[r] = knn_.quality(rows + r * knn_.dims());
  }

 private:
  Knn(const PluginContext& ctx, KnnClassifier knn)
      : ScoringClassifier(ctx.params.getString("model"), knn.prototypes().features,
                          ctx.params.getDouble("q_person"),
                          parseDetectionShape(ctx.params.getString("shape"))),
        knn_(std::move(knn)) {}
  KnnClassifier knn_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Classifier;
  d.doc = "k-NN person classifier (P2): Mahalanobis metric, weighted votes, quality Q";
  d.params = {
      ParamSpec::inputFile("model", "k-NN model file (`pedtrack train knn`; models/*.yml)"),
      ParamSpec::integer("k", 0, "", 0, 1000, "neighbours (0: the model's; P2: 5)"),
      ParamSpec::choice("metric", "model", {"model", "mahalanobis", "minkowski"},
                        "distance: mahalanobis with Σ = (Σ_P + Σ_P̄)/2 (P2 eq. 5) or minkowski "
                        "with each feature scaled to σ = 1 (eq. 22); model: as trained"),
      ParamSpec::integer("minkowski_p", 0, "", 0, 2,
                         "Minkowski level l: 1 Manhattan, 2 Euclidean (0: the model's)"),
      ParamSpec::choice(
          "weighting", "model", {"model", "inverse_distance", "squared_distance", "unit"},
          "votes per neighbour: inverse_distance 1/d, squared_distance d² (P2 eq. 6 as "
          "printed), unit 1; model: as trained"),
      ParamSpec::real("q_person", 0.5, "", 0, 1,
                      "a cluster with quality Q ≥ this is a person detection (P2: Q_P = 0.5)"),
      detectionShapeParam(),
  };
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<Knn>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::knnplugin

PEDTRACK_PLUGIN("knn", pedtrack::knnplugin::describe)
