// `knn`: P2's appearance classifier (§3.3, §5.2). Each cluster's feature vector (by the model's
// feature names: [h, w, d, v, λ, ρ] after voxel_ccl, the segment features after scan_segments)
// goes to the k nearest prototypes of the model under the Mahalanobis metric of eq. 5; their
// weighted votes give the quality Q = W_P / (W_P + W_P̄), and a cluster with Q ≥ Q_P becomes a
// detection whose score is Q.
#include "pedtrack/classify/knn.h"

#include <optional>

#include "pedtrack/classify/cluster_scoring.h"
#include "pedtrack/classify/model_file.h"
#include "pedtrack/errors.h"
#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"

namespace pedtrack::knnplugin {
namespace {

using namespace pedtrack::classify;

struct KnnParams {
  std::string model;
  int k = 0;                              // 0: the model's
  std::optional<KnnMetric> metric;        // none: the model's
  int minkowski_p = 0;                    // 0: the model's
  std::optional<KnnWeighting> weighting;  // none: the model's
  double q_person = 0.5;                  // P2: Q_P
  DetectionShapeParams output;
};

const ParamTable<KnnParams>& table() {
  using P = KnnParams;
  static const auto t =
      ParamTable<P>()
          .inputFile(&P::model, "model", "k-NN model file (`pedtrack train knn`; models/*.yml)")
          .integer(&P::k, "k", "", 0, 1000, "neighbours (0: the model's; P2: 5)")
          .choice(&P::metric, "metric",
                  {{"model", std::nullopt},
                   {"mahalanobis", KnnMetric::Mahalanobis},
                   {"minkowski", KnnMetric::Minkowski}},
                  "distance: mahalanobis with Σ = (Σ_P + Σ_P̄)/2 (P2 eq. 5) or minkowski with "
                  "each feature scaled to σ = 1 (eq. 22); model: as trained")
          .integer(&P::minkowski_p, "minkowski_p", "", 0, 2,
                   "Minkowski level l: 1 Manhattan, 2 Euclidean (0: the model's)")
          .choice(&P::weighting, "weighting",
                  {{"model", std::nullopt},
                   {"inverse_distance", KnnWeighting::InverseDistance},
                   {"squared_distance", KnnWeighting::SquaredDistance},
                   {"unit", KnnWeighting::Unit}},
                  "votes per neighbour: inverse_distance 1/d, squared_distance d² (P2 eq. 6 as "
                  "printed), unit 1; model: as trained")
          .real(&P::q_person, "q_person", "", 0, 1,
                "a cluster with quality Q ≥ this is a person detection (P2: Q_P = 0.5)")
          .include(&P::output, detectionShapeTable());
  return t;
}

KnnClassifier load(const KnnParams& p) {
  LoadedKnn m = loadKnnModel(p.model);
  KnnOptions o = m.options;
  if (p.k > 0) o.k = p.k;
  if (p.metric) o.metric = *p.metric;
  if (p.minkowski_p > 0) o.minkowski_p = p.minkowski_p;
  if (p.weighting) o.weighting = *p.weighting;
  return KnnClassifier(std::move(m.prototypes), std::move(m.stats), o);
}

class Knn : public ScoringClassifier {
 public:
  explicit Knn(const PluginContext& ctx) : Knn(table().read(ctx.params)) {}
  explicit Knn(const KnnParams& p) : Knn(p, load(p)) {}

 protected:
  void score(const double* rows, std::size_t n, std::vector<double>& out) override {
    out.resize(n);
    for (std::size_t r = 0; r < n; ++r) out[r] = knn_.quality(rows + r * knn_.dims());
  }

 private:
  Knn(const KnnParams& p, KnnClassifier knn)
      : ScoringClassifier(p.model, knn.prototypes().features, p.q_person, p.output.shape),
        knn_(std::move(knn)) {}
  KnnClassifier knn_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Classifier;
  d.doc = "k-NN person classifier (P2): Mahalanobis metric, weighted votes, quality Q";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<Knn>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::knnplugin

PEDTRACK_PLUGIN("knn", pedtrack::knnplugin::describe)
