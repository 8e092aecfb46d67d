// `pedtrack eval --model M.yml --dataset D.ini`: one or more classifier models scored on labelled
// clusters they were not trained on — the confusion matrix at the decision threshold in P2
// Table 1's layout, detection and false-positive rates, the ROC curve's area, and the curves
// drawn to a PNG.
#include <filesystem>
#include <iostream>

#include "commands.h"
#include "options.h"
#include "pedtrack/classify/model_file.h"
#include "pedtrack/classify/roc.h"
#include "pedtrack/errors.h"
#include "pedtrack/text.h"
#include "plot.h"
#include "report_format.h"
#include "sample_csv.h"
#include "train_data_options.h"

namespace pedtrack::cli {
namespace {

using namespace pedtrack::classify;

struct ModelResult {
  std::string path, label;
  std::vector<double> scores;
  std::vector<Label> y;
  Confusion c;
  double auc = 0;
  // Operating points: the best detection at ≤ at_fp false positives, the fewest false positives
  // at ≥ at_detection detected (--at-fp, --at-detection); and at the defaults 5 % / 90 %.
  RocPoint at_fpr, at_tpr, at_5pct_fpr, at_90pct_tpr;
  double at_fp = 0.05, at_detection = 0.90;
};

void drawRoc(const std::string& path, const std::vector<ModelResult>& rs, double threshold) {
  plot::Axis x{"false positive rate", 0, 1, false, 0.1}, y{"detection rate", 0, 1, false, 0.1};
  plot::Plot p(640, 640, x, y);
  p.line({0, 1}, {0, 1}, cv::Scalar(220, 220, 220), 1);
  for (std::size_t i = 0; i < rs.size(); ++i) {
    const cv::Scalar col = plot::colour(i);
    std::vector<double> fpr, tpr;
    for (const auto& pt : rocCurve(rs[i].scores, rs[i].y))
      fpr.push_back(pt.fpr), tpr.push_back(pt.tpr);
    p.line(fpr, tpr, col, 2, false,
           mrpt::format("%s AUC %.3f, o at %.2f: %.1f%% / %.1f%%",
                        std::filesystem::path(rs[i].path).filename().c_str(), rs[i].auc, threshold,
                        100 * rs[i].c.detectionRate(), 100 * rs[i].c.falsePositiveRate()));
    p.marker(rs[i].c.falsePositiveRate(), rs[i].c.detectionRate(), col);
  }
  p.legend();
  if (!p.write(path)) throw ConfigError("--roc: cannot write '" + path + "'");
}

std::string table(const ModelResult& r, double threshold) {
  const Confusion& c = r.c;
  return mrpt::format(
      "%s\n  confusion at score >= %.2f        decided\n"
      "                              nonperson   person\n"
      "  actual  nonperson       %12zu %8zu\n"
      "          person          %12zu %8zu\n"
      "  detection rate %.2f %% (%zu/%zu), false positive rate %.2f %% (%zu/%zu), AUC %.4f\n"
      "  on the ROC curve: %.2f %% detected at <= %g %% false positives (score >= %.3f); "
      "%.2f %% false positives at >= %g %% detected (score >= %.3f)\n",
      r.label.c_str(), threshold, c.tn, c.fp, c.fn, c.tp, 100 * c.detectionRate(), c.tp,
      c.tp + c.fn, 100 * c.falsePositiveRate(), c.fp, c.fp + c.tn, r.auc, 100 * r.at_fpr.tpr,
      100 * r.at_fp, r.at_fpr.threshold, 100 * r.at_tpr.fpr, 100 * r.at_detection,
      r.at_tpr.threshold);
}

}  // namespace

int evalClassifierCommand(const std::vector<std::string>& args) {
  std::vector<std::string> models, sims, positives, negatives, plugin_path;
  std::string dataset, samples, save_samples, save_scores, pipeline, topic, labels_topic, region,
      roc, metric, weighting;
  long frame_step = 1, k = 0, minkowski_p = 0;
  double min_range = 0, max_range = 0, threshold = 0.5, at_fp = 0.05, at_detection = 0.90;
  po::options_description o("options");
  o.add_options()("model", po::value(&models)->composing(),
                  "model file to score (repeatable: compared on the same samples)")(
      "dataset", po::value(&dataset), "test dataset file (configs/training/*.ini)")(
      "samples", po::value(&samples), "labelled samples CSV instead of a dataset")(
      "save-samples", po::value(&save_samples), "also write the collected samples (CSV)")(
      "save-scores", po::value(&save_scores),
      "write every sample's label and each model's score (CSV, in the samples' order)")(
      "pipeline", po::value(&pipeline), "segmentation pipeline (without a dataset file)")(
      "sim", po::value(&sims)->composing(), "simulated scenario (per-point truth labels)")(
      "positive", po::value(&positives)->composing(), "recording of people (see pedtrack train)")(
      "negative", po::value(&negatives)->composing(), "recording without people")(
      "topic", po::value(&topic), "scan topic of bag recordings")(
      "labels-topic", po::value(&labels_topic), "bag topic of person/leg positions")(
      "region", po::value(&region), "\"x0 y0 x1 y1\": persons' area, sensor frame (m)")(
      "frame-step", po::value(&frame_step), "use every Nth frame")(
      "min-range", po::value(&min_range), "leave out clusters nearer than this (m)")(
      "max-range", po::value(&max_range), "leave out clusters farther than this (m)")(
      "threshold", po::value(&threshold), "decision threshold on the score (default 0.5)")(
      "at-fp", po::value(&at_fp),
      "operating point: the best detection rate at at most this false-positive rate (0.05)")(
      "at-detection", po::value(&at_detection),
      "operating point: the fewest false positives at at least this detection rate (0.90)")(
      "k", po::value(&k), "knn models: neighbours instead of the model's")(
      "metric", po::value(&metric), "knn models: mahalanobis or minkowski instead of the model's")(
      "minkowski-p", po::value(&minkowski_p), "knn models: Minkowski level 1 or 2")(
      "weighting", po::value(&weighting),
      "knn models: inverse_distance, squared_distance or unit instead of the model's")(
      "roc", po::value(&roc), "draw the ROC curves to this PNG")("json", "print JSON")(
      "plugin-path", po::value(&plugin_path)->composing(), "extra plugin folder")(
      "quiet,q", "no progress output");
  po::variables_map vm;
  if (!parseOptions("eval", "--model MODEL.yml (DATASET | --samples CSV | inputs) [options]", o, {},
                    args, vm, "eval --model"))
    return 0;
  if (models.empty()) throw ConfigError("pedtrack eval: missing --model");
  if (!(threshold >= 0 && threshold <= 1))
    throw ConfigError("--threshold: must be within [0, 1] for a classifier score");
  if (!(at_fp >= 0 && at_fp <= 1) || !(at_detection >= 0 && at_detection <= 1))
    throw ConfigError("--at-fp and --at-detection: must be rates within [0, 1]");
  const bool progress = !vm.count("quiet") && !vm.count("json");

  // Every model is read (and rejected) before the data is collected.
  std::vector<std::unique_ptr<Scorer>> scorers;
  for (const auto& m : models) {
    if (modelKind(m) == "knn") {
      KnnOptions opt = loadKnnModel(m).options;
      if (k > 0) opt.k = int(k);
      if (!metric.empty()) opt.metric = parseKnnMetric(metric);
      if (minkowski_p > 0) opt.minkowski_p = int(minkowski_p);
      if (!weighting.empty()) opt.weighting = parseKnnWeighting(weighting);
      scorers.push_back(loadScorer(m, &opt));
    } else {
      scorers.push_back(loadScorer(m));
    }
  }
  std::string described;
  SampleSet all;
  if (!samples.empty()) {
    all = loadSamples(nullptr, samples, {}, plugin_path, progress, described);
  } else {
    Dataset d =
        datasetFromOptions(dataset, pipeline, sims, positives, negatives, topic, labels_topic,
                           region, frame_step, min_range, max_range, "", "pedtrack eval");
    d.features.clear();  // each model takes its own features below
    all = loadSamples(&d, "", {}, plugin_path, progress, described);
  }
  if (!save_samples.empty()) writeSamplesCsv(save_samples, all);

  std::vector<ModelResult> rs;
  for (std::size_t i = 0; i < scorers.size(); ++i) {
    const SampleSet s = all.select(scorers[i]->info().features);
    ModelResult r;
    r.path = models[i];
    r.label = models[i] + " (" + scorers[i]->info().kind + ")";
    scorers[i]->score(s.x.data(), s.size(), r.scores);
    r.y = s.y;
    r.c = confusionAt(r.scores, r.y, threshold);
    r.auc = rocAuc(r.scores, r.y);
    const auto curve = rocCurve(r.scores, r.y);
    r.at_fp = at_fp, r.at_detection = at_detection;
    r.at_fpr = bestAtFpr(curve, at_fp);
    r.at_tpr = bestAtTpr(curve, at_detection);
    r.at_5pct_fpr = bestAtFpr(curve, 0.05);
    r.at_90pct_tpr = bestAtTpr(curve, 0.90);
    rs.push_back(std::move(r));
  }
  if (!roc.empty()) drawRoc(roc, rs, threshold);
  if (!save_scores.empty()) {
    std::vector<const std::vector<double>*> scores;
    for (const auto& r : rs) scores.push_back(&r.scores);
    writeScoresCsv(save_scores, rs.front().y, scores);
  }
  if (vm.count("json")) {
    std::string out = "{\"samples\": " + std::to_string(all.size()) +
                      ", \"persons\": " + std::to_string(all.count(Label::Person)) +
                      ", \"nonpersons\": " + std::to_string(all.count(Label::NonPerson)) +
                      ", \"models\": [";
    for (std::size_t i = 0; i < rs.size(); ++i) {
      Json j;
      j.text("model", rs[i].path).text("kind", scorers[i]->info().kind).num("threshold", threshold);
      j.count("tp", rs[i].c.tp)
          .count("fn", rs[i].c.fn)
          .count("fp", rs[i].c.fp)
          .count("tn", rs[i].c.tn);
      j.num("detection_rate", rs[i].c.detectionRate())
          .num("false_positive_rate", rs[i].c.falsePositiveRate())
          .num("auc", rs[i].auc)
          .num("detection_rate_at_5pct_fp", rs[i].at_5pct_fpr.tpr)
          .num("false_positive_rate_at_90pct_detection", rs[i].at_90pct_tpr.fpr)
          .num("at_fp", at_fp)
          .num("detection_rate_at_fp", rs[i].at_fpr.tpr)
          .num("at_detection", at_detection)
          .num("false_positive_rate_at_detection", rs[i].at_tpr.fpr);
      out += (i ? ", " : "") + j.str();
    }
    std::cout << out << "]}\n";
    return exit_code::kOk;
  }
  std::cout << "test data: " << described << "\n"
            << all.count(Label::Person) << " persons, " << all.count(Label::NonPerson)
            << " non-persons\n\n";
  for (const auto& r : rs) std::cout << table(r, threshold) << "\n";
  if (!roc.empty()) std::cout << "ROC curves: " << roc << "\n";
  return exit_code::kOk;
}

}  // namespace pedtrack::cli
