// Classifier cores (classify/): P2's Mahalanobis k-NN and quality Q, the RBF SVM and its Platt
// calibration, model files, ROC and AUC. Numbers are derived by hand in the comments.
#include <zlib.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>

#include "pedtrack/classify/knn.h"
#include "pedtrack/classify/model_file.h"
#include "pedtrack/classify/model_text.h"
#include "pedtrack/classify/roc.h"
#include "pedtrack/classify/svm.h"
#include "pedtrack/errors.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::classify;

namespace {

// An input fuzz_model once crashed or hung on (fuzz/regressions/fuzz_model/), "" for the folder.
std::string fuzzInput(const std::string& file) {
  return std::string(PEDTRACK_SOURCE_DIR) + "/fuzz/regressions/fuzz_model/" + file;
}

// Persons at the corners of a 2 m square around (1, 1); non-persons at the corners of a 4 m
// square around (12, 2). Per class the covariance is diag(4/3, 4/3) and diag(16/3, 16/3), so
// P2's Σ = (Σ_P + Σ_P̄)/2 = (10/3)·I and d² = 0.3·|x − x'|².
SampleSet twoSquares() {
  SampleSet s;
  s.features = {"a", "b"};
  for (auto [x, y] : {std::pair{0., 0.}, {2., 0.}, {0., 2.}, {2., 2.}}) {
    const double v[2] = {x, y};
    s.add(v, Label::Person);
  }
  for (auto [x, y] : {std::pair{10., 0.}, {14., 0.}, {10., 4.}, {14., 4.}}) {
    const double v[2] = {x, y};
    s.add(v, Label::NonPerson);
  }
  return s;
}

KnnClassifier knn(KnnWeighting w, KnnMetric m = KnnMetric::Mahalanobis) {
  const SampleSet s = twoSquares();
  KnnOptions o;
  o.k = 5;
  o.metric = m;
  o.weighting = w;
  return KnnClassifier(s, KnnMetricStats::fit(s), o);
}

}  // namespace

TEST_CASE("Mahalanobis metric uses the average of the two class covariances (P2 eq. 5)") {
  const SampleSet s = twoSquares();
  const KnnMetricStats st = KnnMetricStats::fit(s);
  CHECK(st.sigma(0, 0) == Approx(10.0 / 3));
  CHECK(st.sigma(1, 1) == Approx(10.0 / 3));
  CHECK(st.sigma(0, 1) == Approx(0).margin(1e-12));
  const auto k = knn(KnnWeighting::Unit);
  const double a[2] = {0, 0}, b[2] = {1, 2};
  CHECK(k.distanceSquared(a, b) == Approx(0.3 * 5));

  // A correlated Σ = [[2, 1], [1, 2]]: Σ⁻¹ = [[2, −1], [−1, 2]] / 3.
  KnnMetricStats corr;
  corr.sigma = (Eigen::Matrix2d() << 2, 1, 1, 2).finished();
  corr.stddev = Eigen::Vector2d(1, 1);
  const KnnClassifier c(s, corr, KnnOptions{});
  const double o[2] = {0, 0}, e1[2] = {1, 0}, d1[2] = {1, 1}, d2[2] = {1, -1};
  CHECK(c.distanceSquared(o, e1) == Approx(2.0 / 3));
  CHECK(c.distanceSquared(o, d1) == Approx(2.0 / 3));  // along the correlation: near
  CHECK(c.distanceSquared(o, d2) == Approx(2.0));      // across it: far
}

TEST_CASE("quality Q under each vote weighting on a hand-made two-class set") {
  // Query (1, 1): its 5 nearest are the 4 persons (d² = 0.3·2 = 0.6) and the non-person
  // (10, 0) (d² = 0.3·82 = 24.6).
  const double q[2] = {1, 1};
  const double dp = std::sqrt(0.6), dn = std::sqrt(24.6);
  CHECK(knn(KnnWeighting::Unit).quality(q) == Approx(0.8));
  CHECK(knn(KnnWeighting::InverseDistance).quality(q) == Approx((4 / dp) / (4 / dp + 1 / dn)));
  // P2 eq. 6 as printed: votes equal to d², so the far non-person outvotes four near persons.
  CHECK(knn(KnnWeighting::SquaredDistance).quality(q) == Approx(2.4 / (2.4 + 24.6)));
  // A query among the non-persons.
  const double far[2] = {12, 2};
  CHECK(knn(KnnWeighting::Unit).quality(far) == Approx(0.2));
  // Minkowski: each feature scaled by its σ over all prototypes.
  const auto mk = knn(KnnWeighting::Unit, KnnMetric::Minkowski);
  const double a[2] = {0, 0}, b[2] = {1, 0};
  const double sd = mk.stats().stddev[0];
  CHECK(mk.distanceSquared(a, b) == Approx(1 / (sd * sd)));
}

TEST_CASE("the KD-tree finds the same neighbours as a linear scan") {
  SampleSet s;
  s.features = {"a", "b", "c"};
  unsigned state = 7;
  auto rnd = [&] { return (state = state * 1103515245u + 12345u) / 4294967296.0; };
  for (int i = 0; i < 3000; ++i) {
    const double v[3] = {rnd(), rnd() * 3, rnd() + (i % 2)};
    s.add(v, Label(i % 2));
  }
  KnnOptions tree, scan;
  scan.linear_below = 1000000;
  const KnnClassifier a(s, KnnMetricStats::fit(s), tree), b(s, KnnMetricStats::fit(s), scan);
  for (int i = 0; i < 200; ++i) {
    const double v[3] = {rnd(), rnd() * 3, rnd() * 2};
    REQUIRE(a.quality(v) == Approx(b.quality(v)).epsilon(1e-12));
  }
}

TEST_CASE("an RBF SVM separates a separable set and its calibrated probability follows") {
  SampleSet s;
  s.features = {"u", "v"};
  // Two interleaved rings: not linearly separable, separable with an RBF kernel.
  for (int i = 0; i < 120; ++i) {
    const double a = i * 0.3;
    const double in[2] = {0.5 * std::cos(a), 0.5 * std::sin(a)};
    const double out[2] = {2.0 * std::cos(a), 2.0 * std::sin(a)};
    s.add(in, Label::Person);
    s.add(out, Label::NonPerson);
  }
  SvmTraining t;
  t.folds = 3;
  const SvmClassifier svm = SvmClassifier::train(s, t);
  std::vector<double> p;
  svm.probability(s.x.data(), s.size(), p);
  for (std::size_t i = 0; i < s.size(); ++i) REQUIRE((p[i] >= 0.5) == (s.y[i] == Label::Person));
  const double centre[2] = {0, 0}, outside[2] = {3, 0};
  std::vector<double> pc, po;
  svm.probability(centre, 1, pc);
  svm.probability(outside, 1, po);
  CHECK(pc[0] > 0.9);
  CHECK(po[0] < 0.1);
}

TEST_CASE("Platt's sigmoid recovers the curve its labels were drawn from") {
  // At each f, 1000 samples of which round(1000·σ(−2f)) are persons: the fit returns a ≈ −2.
  std::vector<double> f;
  std::vector<Label> y;
  for (double v = -2; v <= 2.001; v += 0.25) {
    const int pos = int(std::lround(1000 / (1 + std::exp(-2 * v))));
    for (int i = 0; i < 1000; ++i) {
      f.push_back(v);
      y.push_back(i < pos ? Label::Person : Label::NonPerson);
    }
  }
  const PlattSigmoid s = PlattSigmoid::fit(f, y);
  CHECK(s.a == Approx(-2).margin(0.02));
  CHECK(s.b == Approx(0).margin(0.02));
  CHECK(s(0) == Approx(0.5).margin(0.01));
}

TEST_CASE("confusion matrix, ROC and AUC by hand") {
  const std::vector<double> sc{0.9, 0.8, 0.7, 0.1};
  const std::vector<Label> y{Label::Person, Label::NonPerson, Label::Person, Label::NonPerson};
  const Confusion c = confusionAt(sc, y, 0.75);
  CHECK(c.tp == 1);
  CHECK(c.fn == 1);
  CHECK(c.fp == 1);
  CHECK(c.tn == 1);
  // Pairs (person, non-person) ordered right: 0.9 > 0.8, 0.9 > 0.1, 0.7 > 0.1 → 3 of 4.
  CHECK(rocAuc(sc, y) == Approx(0.75));
  CHECK(rocAuc({0.5, 0.5}, {Label::Person, Label::NonPerson}) == Approx(0.5));  // a tie: ½
  const auto roc = rocCurve(sc, y);
  REQUIRE(roc.size() == 5);
  CHECK(roc.back().fpr == 1);
  CHECK(roc.back().tpr == 1);
  CHECK(bestAtFpr(roc, 0.0).tpr == Approx(0.5));
  CHECK(bestAtTpr(roc, 1.0).fpr == Approx(0.5));
}

TEST_CASE("subsampling keeps a rare class whole and the order of the samples") {
  SampleSet s;
  s.features = {"i"};
  for (int i = 0; i < 1000; ++i) {
    const double v = i;
    s.add(&v, i % 10 == 0 ? Label::Person : Label::NonPerson);
  }
  const SampleSet t = s.subsample(300, 1);
  CHECK(t.size() == 300);
  CHECK(t.count(Label::Person) == 100);  // all of them: fewer than half the budget
  for (std::size_t i = 1; i < t.size(); ++i) REQUIRE(t.row(i)[0] > t.row(i - 1)[0]);
  CHECK(s.subsample(300, 1).x == t.x);  // deterministic for a seed
}

TEST_CASE("train, save, load: identical predictions; bad model files are one-line errors") {
  const std::string dir = test::freshDir("classify_models");
  SampleSet s = twoSquares();
  for (int i = 0; i < 40; ++i) {  // more samples for the SVM's folds
    const double p[2] = {1 + 0.05 * (i % 7), 1 - 0.04 * (i % 5)};
    const double n[2] = {12 + 0.06 * (i % 6), 2 + 0.05 * (i % 4)};
    s.add(p, Label::Person);
    s.add(n, Label::NonPerson);
  }
  ModelInfo info;
  info.features = s.features;
  info.command = "test";
  info.kind = "knn";
  const KnnClassifier k(s, KnnMetricStats::fit(s), KnnOptions{});
  saveKnnModel(dir + "/k.yml", info, k);
  info.kind = "svm";
  SvmTraining t;
  t.folds = 3;
  const SvmClassifier v = SvmClassifier::train(s, t);
  saveSvmModel(dir + "/s.yml", info, v);

  const auto kl = loadScorer(dir + "/k.yml");
  const auto sl = loadScorer(dir + "/s.yml");
  CHECK(kl->info().command == "test");
  CHECK(kl->info().features == s.features);
  std::vector<double> q;
  for (int i = 0; i < 50; ++i) q.insert(q.end(), {0.3 * i, 0.1 * i});
  std::vector<double> ks, ss, sv;
  kl->score(q.data(), 50, ks);
  sl->score(q.data(), 50, ss);
  v.probability(q.data(), 50, sv);
  for (int i = 0; i < 50; ++i) {
    REQUIRE(ks[i] == k.quality(&q[2 * i]));
    REQUIRE(ss[i] == Approx(sv[i]).epsilon(1e-6));
  }

  auto expectError = [&](const std::string& path, const std::string& what) {
    try {
      loadScorer(path);
      FAIL("no error for " << path);
    } catch (const ConfigError& e) {
      const std::string m = e.what();
      CHECK(m.find(path) == 0);
      CHECK(m.find(what) != std::string::npos);
      CHECK(m.find('\n') == std::string::npos);
    }
  };
  const std::string text = test::readFile(dir + "/s.yml");
  test::writeFile(dir + "/truncated.yml", text.substr(0, text.size() / 2));
  expectError(dir + "/truncated.yml", "truncated");
  test::writeFile(dir + "/garbage.yml", "\x01\x02 not yaml {{{ [");
  expectError(dir + "/garbage.yml", "it does not start with '%YAML'");
  std::string v2 = test::readFile(dir + "/k.yml");
  v2.replace(v2.find("version: 1"), 10, "version: 9");
  test::writeFile(dir + "/v9.yml", v2);
  expectError(dir + "/v9.yml", "version 9");
  expectError(dir + "/missing.yml", "not found");
  // A gzip-compressed model (FileStorage reads .gz, so pedtrack does) scores as the plain one.
  {
    gzFile gz = gzopen((dir + "/k.yml.gz").c_str(), "wb");
    const std::string k_text = test::readFile(dir + "/k.yml");
    REQUIRE(gzwrite(gz, k_text.data(), unsigned(k_text.size())) == int(k_text.size()));
    gzclose(gz);
    std::vector<double> kz;
    loadScorer(dir + "/k.yml.gz")->score(q.data(), 50, kz);
    CHECK(kz == ks);
    // ... and a broken one is the same one-line error.
    const std::string z = test::readFile(dir + "/k.yml.gz");
    test::writeFile(dir + "/cut.yml.gz", z.substr(0, z.size() / 2));
    expectError(dir + "/cut.yml.gz", ": not a readable model file (");
  }
  try {
    loadKnnModel(dir + "/s.yml");
    FAIL("an SVM loaded as k-NN");
  } catch (const ConfigError& e) {
    CHECK(std::string(e.what()).find("'svm' model, not 'knn'") != std::string::npos);
  }
}

TEST_CASE("the RBF decision function agrees with OpenCV's predict on the shipped leg model") {
  const LoadedSvm m = loadSvmModel(std::string(PEDTRACK_SOURCE_DIR) + "/models/legs_svm.yml");
  const SvmClassifier& c = *m.svm;
  const std::size_t n = 200, d = c.dims();
  std::vector<double> x(n * d);
  cv::Mat z(int(n), int(d), CV_32F);
  cv::RNG rng(7);
  const cv::Mat sv = c.svm()->getSupportVectors();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < d; ++j) {
      // near the support vectors (both sides of the boundary), mapped back to raw features
      const float v =
          sv.at<float>(int(i * 7 % std::size_t(sv.rows)), int(j)) + float(rng.gaussian(0.3));
      z.at<float>(int(i), int(j)) = v;
      x[i * d + j] = c.standardizer().mean[j] + v * c.standardizer().scale[j];
    }
  std::vector<double> fast;
  c.decision(x.data(), n, fast);
  cv::Mat ref;
  c.svm()->predict(z, ref, cv::ml::StatModel::RAW_OUTPUT);
  int both_signs[2] = {0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    const double r = ref.at<float>(int(i));
    // Both evaluate the kernel in float: they differ by a few 1e-3 at most.
    CHECK(fast[i] == Approx(r).margin(5e-3));
    ++both_signs[r > 0];
  }
  CHECK(both_signs[0] > 0);  // the inputs reach both sides of the boundary
  CHECK(both_signs[1] > 0);
}

TEST_CASE("a model file found by fuzzing (support vector indices past the vectors) is refused",
          "[classify][fuzz]") {
  // fuzz/regressions/fuzz_model: once a heap overflow in SvmClassifier's constructor.
  const std::string path = fuzzInput("svm_index_past_vectors.yml");
  CHECK_THROWS_WITH(pedtrack::classify::loadScorer(path),
                    Catch::Contains("svm_index_past_vectors.yml: bad 'svm' (a support vector index "
                                    "outside 0..798)"));
}

TEST_CASE("a model file found by fuzzing (a matrix with no rows) is refused before allocating",
          "[classify][fuzz]") {
  // fuzz/regressions/fuzz_model: "rows: ~" made OpenCV's reader allocate 17 GB. The matrix check
  // caught it first; now the line forms do ('~' is no value pedtrack writes), and the matrix
  // check is tested on its own below ("... refused before OpenCV reads").
  const std::string path = fuzzInput("matrix_rows_missing.yml");
  CHECK_THROWS_WITH(
      pedtrack::classify::loadScorer(path),
      Catch::Contains("matrix_rows_missing.yml: not a readable model file (line 38: "
                      "a value that is not a number, word, string, tag or [ ] / { })"));
}

TEST_CASE("a model file found by fuzzing (control bytes) is refused before parsing",
          "[classify][fuzz]") {
  // fuzz/regressions/fuzz_model: control bytes amid the YAML made OpenCV 4.6's parser loop for
  // good (the fuzzer's 24 s timeout). The first one, a NUL, is at offset 10.
  const std::string path = fuzzInput("control_bytes_hang.yml");
  CHECK_THROWS_WITH(pedtrack::classify::loadScorer(path),
                    Catch::Contains("control_bytes_hang.yml: not a readable model file (control "
                                    "byte at offset 10)"));
}

TEST_CASE("model files found by fuzzing (a second YAML document) are refused before parsing",
          "[classify][fuzz]") {
  // fuzz/regressions/fuzz_model: after a document's root OpenCV 4.6's parser skips three
  // characters for the '---' or '...' it assumes, then loops for good on a '-' that is not
  // '---' (the fuzzer's 20 s timeout). The first has its root on the '---' line (and, at offset
  // 683, a lone CR, which is refused first: see below), the second a '...' after the root map.
  const std::string dir = fuzzInput("");
  CHECK_THROWS_WITH(loadScorer(dir + "second_document_hang.yml"),
                    Catch::Contains("second_document_hang.yml: not a readable model file (a CR "
                                    "without LF at offset 683)"));
  CHECK_THROWS_WITH(loadScorer(dir + "marker_after_root_hang.yml"),
                    Catch::Contains("marker_after_root_hang.yml: not a readable model file (line "
                                    "4: a document marker ('---' or '...') after the root"));
}

TEST_CASE("a model's text must have the layout pedtrack writes: one document, a root map") {
  // Every shipped model has it.
  for (const char* name :
       {"legs_knn", "legs_svm", "person3d_knn", "person3d_svm", "torso_knn", "torso_svm"}) {
    const std::string path = std::string(PEDTRACK_SOURCE_DIR) + "/models/" + name + ".yml";
    CHECK(modelTextProblem(test::readFile(path)) == "");
  }
  const std::string head = "%YAML:1.0\n---\n";
  // Comments, blank lines, indented values and CRLF line ends are all fine.
  CHECK(modelTextProblem(head + "# a comment\n\nformat: x\nsvm:\n  a: [ 1, 2,\n    3 ]\n") == "");
  CHECK(modelTextProblem("%YAML:1.0\r\n---\r\nformat: x\r\nkind: svm\r\n") == "");
  CHECK(modelTextProblem("%YAML:1.0\nformat: x\n") == "");  // '---' may be left out
  // XML and JSON are not pedtrack models (and their parsers are not read at all).
  CHECK(modelTextProblem("<?xml version=\"1.0\"?>\n<opencv_storage/>\n") ==
        "not a pedtrack model file (it does not start with '%YAML')");
  CHECK(modelTextProblem("{\"format\": 1}\n") ==
        "not a pedtrack model file (it does not start with '%YAML')");
  CHECK(modelTextProblem(head + "format: x\x01\n") == "control byte at offset 23");
  CHECK(modelTextProblem(head + "--- \nformat: x\n") ==
        "line 3: a second '---' (a model file is "
        "one document)");
  CHECK(modelTextProblem("%YAML:1.0\n--- {format: x}\n") ==
        "line 2: content after '---' (a model file's root is a map on the lines below)");
  CHECK(modelTextProblem(head + "  format: x\n") ==
        "line 3: the root is indented (a model file's root is a map at column 0)");
  CHECK(modelTextProblem(head + "- format\n") == "line 3: the root is not a map of keys");
  CHECK(modelTextProblem(head + "[format]\n") == "line 3: the root is not a map of keys");
  CHECK(modelTextProblem(head + "format: x\n...\n") ==
        "line 4: a document marker ('---' or '...') after the root (a model file is one "
        "document)");
  CHECK(modelTextProblem(head + "format: x\n---\nkind: svm\n") ==
        "line 4: a document marker ('---' or '...') after the root (a model file is one "
        "document)");
  // A marker inside a value (not at a line's start) is text.
  CHECK(modelTextProblem(head + "format: x\ncommand: a --- b ...\n") == "");
  // What OpenCV's writer leaves unquoted is a value; a quoted string may hold anything.
  CHECK(modelTextProblem(head + "command: /usr/bin/pedtrack train (a;b) -x +1\nn: -.Inf\n"
                                "s: \"a: [ {\\\" b\"\n") == "");
  // Nesting with no indentation is refused (OpenCV recurses once per level without a limit:
  // fuzz_model's 6,000 '-' overflowed the stack in pedtrack's walk over the tree, 65,000 '[' in
  // OpenCV's parser).
  CHECK(modelTextProblem(head + "kind:-----\n") ==
        "line 3: a value that is not a number, word, string, tag or [ ] / { }");
  CHECK(modelTextProblem(head + "a:\n  - - b\n") ==
        "line 4: a value that is not a number, word, string, tag or [ ] / { }");
  CHECK(modelTextProblem(head + "a: b: c\n") == "line 3: more after the value");
  CHECK(modelTextProblem(head + "a: " + std::string(17, '[') + "\n") ==
        "line 3: [ ] or { } nested more than 16 deep");
  CHECK(modelTextProblem(head + "a: [ 1,\n  [ 2 ] ] ]\n") == "line 4: more after the value");
  CHECK(modelTextProblem(head + "a: [ 1,\n  \"b\" ]\n") ==
        "line 4: a quote or '#' inside [ ] or { }");
  CHECK(modelTextProblem(head + "a: [ [ 1, # ]\n  ] ]\n") ==
        "line 3: a quote or '#' inside [ ] or { }");
  CHECK(modelTextProblem(head + "a:\n" + std::string(65, ' ') + "b: 1\n") ==
        "line 4: indented more than 64 columns");
  CHECK(modelTextProblem(head + "a: [ 1, 2 ] x\n") == "line 3: more after the value");
  CHECK(modelTextProblem(head + "a: \"open\n") == "line 3: a string without its closing '\"'");
  // A review's bypasses of the first version of these rules, each refused where OpenCV and the
  // check would part: a '[' inside a word (text to OpenCV, counted by the check, which then
  // took the '...' and '-' below for flow content), and a CR (OpenCV drops the rest of the line,
  // so the ']' after it closed nothing).
  CHECK(modelTextProblem(head + "format: x\na: [ x[ ]\n...\n-\n") ==
        "line 4: a '[' or '{' inside a word in [ ] or { }");
  CHECK(modelTextProblem(head + "a: [ [\r]\n  [\r]\n") == "a CR without LF at offset 20");
  CHECK(modelTextProblem(head + "a: [ 1,\n...\n  2 ]\n") ==
        "line 4: a document marker ('---' or '...') after the root (a model file is one "
        "document)");
  CHECK(modelTextProblem(head + "a: [ 1,\n") == "the file ends inside [ ] or { }");
  CHECK(modelTextProblem(head + "t: { [a: 1 }\n") ==
        "line 3: a key inside { } that is not a word followed by ':'");
  CHECK(modelTextProblem(head + "t: { a b: 1 }\n") ==
        "line 3: a key inside { } that is not a word followed by ':'");
  CHECK(modelTextProblem(head + "a: [ 1 }\n") == "line 3: a ']' or '}' that does not match");
  CHECK(modelTextProblem(head + "a: [ [ 1 ] x ]\n") ==
        "line 3: more after a [ ] or { } inside [ ] or { }");
  // ... while what OpenCV writes stays legal: nested and multi-line flow, a flow map's values.
  CHECK(modelTextProblem(head + "a: [ [ 1, -2.5e-01 ], { k: [ 3 ], j:x:y },\n    4 ]\r\n") == "");
  const std::string reg = fuzzInput("");
  CHECK(modelTextProblem(test::readFile(reg + "nested_sequences_stack_overflow.yml")) ==
        "line 5: a value that is not a number, word, string, tag or [ ] / { }");
}

TEST_CASE("model files whose counts would size OpenCV's allocations are refused before it reads",
          "[classify][fuzz]") {
  // fuzz/regressions/fuzz_model/matrix_data_key_mangled.yml: class_labels' "data" key mangled
  // (so the matrix was not checked) and its "rows: (2", which OpenCV reads as INT_MAX: 8 GB.
  // Its line 14 (a mangled key) is now refused first; the matrix itself is patched in below.
  const std::string reg = fuzzInput("");
  CHECK_THROWS_WITH(loadScorer(reg + "matrix_data_key_mangled.yml"),
                    Catch::Contains("matrix_data_key_mangled.yml: not a readable model file (line "
                                    "14: a key without ':')"));
  // SVM::read allocates support vectors × var_count floats and sv_count weights and indices
  // before it reads them: each count is checked against the data first.
  const std::string dir = test::freshDir("classify_svm_counts");
  const std::string good =
      test::readFile(std::string(PEDTRACK_SOURCE_DIR) + "/models/torso_svm.yml");
  auto patched = [&](const std::string& from, const std::string& to) {
    std::string t = good;
    REQUIRE(t.find(from) != std::string::npos);
    t.replace(t.find(from), from.size(), to);
    const std::string path = dir + "/m.yml";
    test::writeFile(path, t);
    return path;
  };
  CHECK_THROWS_WITH(loadScorer(patched("var_count: 4", "var_count: 2147483647")),
                    Catch::Contains("bad 'svm' (var_count is not the features' count)"));
  CHECK_THROWS_WITH(loadScorer(patched("class_count: 2", "class_count: 65537")),
                    Catch::Contains("bad 'svm' (class_count is not 2)"));
  CHECK_THROWS_WITH(
      loadScorer(patched("sv_total: 799", "sv_total: 800")),
      Catch::Contains("bad 'svm' (sv_total does not match support_vectors, or one has "
                      "other than var_count values)"));
  // 40,000 one-number vectors with var_count 40,000 would ask for 6.4 GB: each vector must have
  // var_count values.
  CHECK_THROWS_WITH(
      loadScorer(patched("      - [ -5.01141667e-01, -6.21370435e-01, -5.61020494e-01,\n"
                         "          7.33989596e-01 ]\n",
                         "      - [ -5.01141667e-01 ]\n")),
      Catch::Contains("or one has other than var_count values)"));
  // Only what pedtrack trains: C_SVC, RBF (a LINEAR kernel with optimize_linear indexes the
  // vectors by the file's indices while OpenCV reads), and indices that name a vector.
  CHECK_THROWS_WITH(loadScorer(patched("svmType: C_SVC", "svmType: NU_SVC")),
                    Catch::Contains("bad 'svm' (not a C_SVC SVM)"));
  CHECK_THROWS_WITH(loadScorer(patched("type: RBF", "type: LINEAR")),
                    Catch::Contains("bad 'svm' (not an RBF kernel)"));
  CHECK_THROWS_WITH(loadScorer(patched("var_count: 4", "optimize_linear: 1\n   var_count: 4")),
                    Catch::Contains("bad 'svm' (optimize_linear is set)"));
  CHECK_THROWS_WITH(loadScorer(patched("index: [ 424,", "index: [ 799,")),
                    Catch::Contains("bad 'svm' (a support vector index outside 0..798)"));
  CHECK_THROWS_WITH(loadScorer(patched("sv_count: 799", "sv_count: 2000000000")),
                    Catch::Contains("bad 'svm' (the decision function's sv_count, alpha and index "
                                    "do not agree)"));
  CHECK_THROWS_WITH(loadScorer(patched("sv_count: 799", "sv_count: -5")),
                    Catch::Contains("bad 'svm' (the decision function's sv_count"));
  CHECK_THROWS_WITH(loadScorer(patched("      dt: i\n", "      dt: i\n      sizes: [ 9, 9 ]\n")),
                    Catch::Contains("matrix 'svm.class_labels': rows × cols do not match"));
  // 1,000 channels of 1 × 2 against 2,000 values: sizes that agree, a channel count OpenCV
  // cannot make (at most 512).
  std::string values = "[ 0";
  for (int i = 1; i < 2000; ++i) values += ", 0";
  CHECK_THROWS_WITH(
      loadScorer(patched(
          "      rows: 2\n      cols: 1\n      dt: i\n      data: [ 0, 1 ]\n",
          "      rows: 1\n      cols: 2\n      dt: \"1000i\"\n      data: " + values + " ]\n")),
      Catch::Contains("matrix 'svm.class_labels': rows × cols do not match"));
  // The fuzzer's matrix, in lines pedtrack could have written: "data" renamed, "rows" a word
  // (read as INT_MAX); and "rows" a word with its data (refused before this fix too).
  const std::string labels = "      rows: 2\n      cols: 1\n      dt: i\n      data: [ 0, 1 ]\n";
  CHECK_THROWS_WITH(
      loadScorer(
          patched(labels, "      rows: x\n      cols: 1\n      dt: i\n      dta: [ 0, 1 ]\n")),
      Catch::Contains("matrix 'svm.class_labels': rows × cols do not match its data"));
  CHECK_THROWS_WITH(
      loadScorer(
          patched(labels, "      rows: x\n      cols: 1\n      dt: i\n      data: [ 0, 1 ]\n")),
      Catch::Contains("matrix 'svm.class_labels': rows × cols do not match its data"));
  // The file itself loads.
  CHECK_NOTHROW(loadScorer(patched("sv_total: 799", "sv_total: 799")));
}
