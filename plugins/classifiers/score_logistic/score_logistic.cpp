// score_logistic: turns a detector's scores into the probability that a detection is a person,
// P = 1 / (1 + exp(-(a s + b))), a logistic fit on labelled data (Platt scaling). A detector's
// own score (PointRCNN's runs from about -1 to 7) means nothing to a tracker that reads scores
// as probabilities; this stage, between the source and the tracker, calibrates it, and it stays
// in the pipeline whatever input replaces the source.
#include <cmath>
#include <memory>

#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"

namespace pedtrack::scorelogistic {
namespace {

struct Settings {
  double a = 1, b = 0;
};

const ParamTable<Settings>& table() {
  using P = Settings;
  static const auto t =
      ParamTable<P>()
          .real(&P::a, "a", "1/score", -1e3, 1e3, "slope of the logistic on the detector's score")
          .required()
          .real(&P::b, "b", "", -1e3, 1e3, "offset of the logistic")
          .required();
  return t;
}

class ScoreLogistic : public Classifier {
 public:
  explicit ScoreLogistic(const PluginContext& ctx) : s_(table().read(ctx.params)) {}
  void process(Frame& f) override {
    for (Detection& d : f.detections) d.score = 1 / (1 + std::exp(-(s_.a * d.score + s_.b)));
  }

 private:
  Settings s_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Classifier;
  d.doc = "Calibrates detection scores into probabilities: 1 / (1 + exp(-(a s + b)))";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<ScoreLogistic>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::scorelogistic

PEDTRACK_PLUGIN("score_logistic", pedtrack::scorelogistic::describe)
