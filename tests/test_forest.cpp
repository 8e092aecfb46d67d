// The random forest classifier: it learns a rule no single feature shows, its score is the share
// of trees voting person, and a saved model scores as the trained one; a model of another kind
// is refused naming the file.
#include <catch2/catch.hpp>
#include <random>

#include "pedtrack/classify/forest.h"
#include "pedtrack/classify/model_file.h"
#include "pedtrack/classify/roc.h"
#include "pedtrack/errors.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::classify;

namespace {

// Persons where x0 and x1 are both above 0.5 (an AND no single feature shows), three noise
// features beside them.
SampleSet andSet(int n, unsigned seed) {
  SampleSet s;
  s.features = {"x0", "x1", "n0", "n1", "n2"};
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < n; ++i) {
    const double v[5] = {u(g), u(g), u(g), u(g), u(g)};
    s.add(v, v[0] > 0.5 && v[1] > 0.5 ? Label::Person : Label::NonPerson);
  }
  return s;
}

}  // namespace

TEST_CASE("a forest learns a conjunction and scores the share of its trees", "[forest]") {
  const SampleSet train = andSet(2000, 1), test = andSet(1000, 2);
  ForestTraining t;
  t.trees = 50;
  const ForestClassifier f = ForestClassifier::train(train, t);
  std::vector<double> p;
  f.probability(test.x.data(), test.size(), p);
  std::size_t right = 0;
  for (std::size_t i = 0; i < test.size(); ++i) {
    REQUIRE(p[i] >= 0);
    REQUIRE(p[i] <= 1);
    right += (p[i] >= 0.5) == (test.y[i] == Label::Person);
  }
  CHECK(double(right) / test.size() > 0.95);
  // Far inside each class the trees agree.
  const double in[5] = {0.9, 0.9, 0.5, 0.5, 0.5}, out[5] = {0.1, 0.9, 0.5, 0.5, 0.5};
  f.probability(in, 1, p);
  CHECK(p[0] > 0.9);
  f.probability(out, 1, p);
  CHECK(p[0] < 0.1);
  // Saved and loaded, it scores the same; the same seed trains the same forest.
  const std::string dir = test::freshDir("forest_model");
  ModelInfo info;
  info.kind = "forest";
  info.features = train.features;
  info.command = "test";
  saveForestModel(dir + "/f.yml", info, f);
  const auto loaded = loadScorer(dir + "/f.yml");
  CHECK(loaded->info().kind == "forest");
  std::vector<double> a, b, c;
  f.probability(test.x.data(), 100, a);
  loaded->score(test.x.data(), 100, b);
  ForestClassifier::train(train, t).probability(test.x.data(), 100, c);
  CHECK(a == b);
  CHECK(a == c);
  CHECK_THROWS_WITH(loadForestModel(std::string(PEDTRACK_SOURCE_DIR) + "/models/person3d_svm.yml"),
                    Catch::Contains("person3d_svm.yml") && Catch::Contains("not 'forest'"));
  // One class only cannot be learnt.
  SampleSet one;
  one.features = {"a"};
  const double v[1] = {1};
  one.add(v, Label::Person);
  CHECK_THROWS_AS(ForestClassifier::train(one, t), DataError);
}
