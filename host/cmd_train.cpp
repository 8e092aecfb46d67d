// `pedtrack train knn|svm|forest`: builds a classifier model from labelled clusters — a dataset
// file (configs/training/*.ini), or recordings and scenarios named on the command line — and writes
// a self-describing model file (classify/model_file.h).
#include <iostream>
#include <sstream>

#include "commands.h"
#include "options.h"
#include "pedtrack/classify/model_file.h"
#include "pedtrack/errors.h"
#include "pedtrack/text.h"
#include "sample_csv.h"
#include "train_data_options.h"

namespace pedtrack::cli {
namespace {

const char* kSynopsis =
    "knn|svm|forest [DATASET.ini] --out MODEL.yml [options]\n"
    "\n"
    "Labelled clusters come from a dataset file (configs/training/*.ini), from --samples, or\n"
    "from inputs given here. Retraining on your own sensor needs no hand labels:\n"
    "  1. record a scene with no people in it (walls, furniture, poles): every cluster of it\n"
    "     is a non-person (--negative);\n"
    "  2. record people walking in an area where nothing else moves or stands, and give that\n"
    "     area in the sensor frame (--region): every cluster inside it is a person\n"
    "     (--positive), or give a bag topic of labelled positions (--labels-topic);\n"
    "  3. pedtrack train svm --pipeline configs/segment_2d.ini --negative empty.bag \\\n"
    "       --positive walkers.bag --region \"0.5 -2 4 2\" --out models/mine.yml\n"
    "  4. check it on a recording not used for training: pedtrack eval --model\n"
    "     models/mine.yml --dataset test.ini (or the same options with --positive/--negative).\n"
    "Training is deterministic for a --seed.";

struct TrainArgs {
  std::string kind, dataset, out, pipeline, samples, save_samples, topic, labels_topic, region,
      features, metric = "mahalanobis", weighting = "inverse_distance";
  std::vector<std::string> sims, positives, negatives, plugin_path;
  long frame_step = 1, k = 5, minkowski_p = 2, max_prototypes = 2000, folds = 5, max_samples = 4000;
  long trees = 100, max_depth = 10;
  unsigned long seed = 1;
  double min_range = 0, max_range = 0;
};

void addInputOptions(po::options_description& o, TrainArgs& a) {
  o.add_options()("pipeline", po::value(&a.pipeline),
                  "segmentation pipeline (without a dataset file)")(
      "sim", po::value(&a.sims)->composing(), "simulated scenario, labelled from per-point truth")(
      "positive", po::value(&a.positives)->composing(),
      "recording of people: clusters in --region or at --labels-topic labels are persons")(
      "negative", po::value(&a.negatives)->composing(),
      "recording without people: every cluster is a non-person")("topic", po::value(&a.topic),
                                                                 "scan topic of bag recordings")(
      "labels-topic", po::value(&a.labels_topic),
      "bag topic of person/leg positions (geometry_msgs/PoseArray) for --positive")(
      "region", po::value(&a.region), "\"x0 y0 x1 y1\": persons' area, sensor frame (m)")(
      "frame-step", po::value(&a.frame_step), "use every Nth frame")(
      "min-range", po::value(&a.min_range), "leave out clusters nearer than this (m)")(
      "max-range", po::value(&a.max_range), "leave out clusters farther than this (m, 0: none)")(
      "features", po::value(&a.features), "\"f1 f2 ...\": the features the model reads")(
      "samples", po::value(&a.samples), "labelled samples CSV instead of a dataset")(
      "plugin-path", po::value(&a.plugin_path)->composing(), "extra plugin folder");
}

}  // namespace

Dataset datasetFromOptions(const std::string& dataset_file, const std::string& pipeline,
                           const std::vector<std::string>& sims,
                           const std::vector<std::string>& positives,
                           const std::vector<std::string>& negatives, const std::string& topic,
                           const std::string& labels_topic, const std::string& region,
                           long frame_step, double min_range, double max_range,
                           const std::string& features, const std::string& command) {
  const bool inline_inputs = !sims.empty() || !positives.empty() || !negatives.empty();
  if (!dataset_file.empty() && (inline_inputs || !pipeline.empty()))
    throw ConfigError(command + ": give a dataset file or --pipeline with inputs, not both");
  Dataset d;
  if (!dataset_file.empty()) {
    d = loadDataset(dataset_file);
  } else {
    if (pipeline.empty() || !inline_inputs)
      throw ConfigError(command +
                        ": no training data (a DATASET.ini, --samples, or --pipeline with "
                        "--sim/--positive/--negative)");
    d.pipeline = pipeline;
    d.frame_step = frame_step;
    d.min_range = min_range;
    d.max_range = max_range;
    std::vector<double> box;
    if (!region.empty()) {
      std::istringstream r(region);
      for (double v; r >> v;) box.push_back(v);
      if (box.size() != 4 || box[0] >= box[2] || box[1] >= box[3])
        throw ConfigError("--region '" + region +
                          "': expected \"x0 y0 x1 y1\" with x0 < x1, y0 < y1");
    }
    int n = 0;
    for (const auto& s : sims) {
      DatasetInput in;
      in.kind = DatasetInput::Kind::Sim;
      in.name = "sim." + std::to_string(++n);
      in.file = s;
      d.inputs.push_back(in);
    }
    for (const auto& p : positives) {
      if (box.empty() && labels_topic.empty())
        throw ConfigError("--positive " + p + ": needs --region or --labels-topic");
      DatasetInput in;
      in.kind = DatasetInput::Kind::Positive;
      in.name = "positive." + std::to_string(++n);
      in.file = p, in.topic = topic, in.labels_topic = labels_topic, in.region = box;
      d.inputs.push_back(in);
    }
    for (const auto& p : negatives) {
      DatasetInput in;
      in.kind = DatasetInput::Kind::Negative;
      in.name = "negative." + std::to_string(++n);
      in.file = p, in.topic = topic;
      d.inputs.push_back(in);
    }
  }
  if (!features.empty()) d.features = splitList(features);
  return d;
}

classify::SampleSet loadSamples(const Dataset* d, const std::string& samples_csv,
                                const std::vector<std::string>& features,
                                const std::vector<std::string>& plugin_path, bool progress,
                                std::string& described) {
  classify::SampleSet s;
  if (!samples_csv.empty()) {
    s = readSamplesCsv(samples_csv);
    described = "samples " + samples_csv;
  } else {
    CollectStats st;
    s = collectSamples(*d, plugin_path, progress, st);
    described = d->describe();
    if (progress)
      std::cerr << "collected " << s.size() << " samples from " << st.frames << " frames"
                << (st.out_of_range ? ", " + std::to_string(st.out_of_range) +
                                          " clusters outside the range left out"
                                    : std::string())
                << (st.labels ? ", " + std::to_string(st.labels_matched) + "/" +
                                    std::to_string(st.labels) + " labels matched a cluster"
                              : std::string())
                << "\n";
  }
  if (!features.empty()) s = s.select(features);
  return s;
}

int trainCommand(const std::vector<std::string>& args) {
  TrainArgs a;
  po::options_description o("options");
  o.add_options()("kind", po::value(&a.kind), "knn, svm or forest")(
      "dataset", po::value(&a.dataset), "dataset file (configs/training/*.ini)")(
      "out,o", po::value(&a.out), "model file to write (.yml)")(
      "save-samples", po::value(&a.save_samples), "also write the collected samples (CSV)")(
      "seed", po::value(&a.seed), "random seed (subsampling, folds)")(
      "k", po::value(&a.k), "knn: neighbours (P2: 5)")("metric", po::value(&a.metric),
                                                       "knn: mahalanobis (P2 eq. 5) or minkowski")(
      "minkowski-p", po::value(&a.minkowski_p), "knn: Minkowski level, 1 or 2")(
      "weighting", po::value(&a.weighting),
      "knn: inverse_distance, squared_distance (P2 eq. 6 as printed) or unit")(
      "max-prototypes", po::value(&a.max_prototypes),
      "knn: keep at most this many prototypes (random, per class in proportion)")(
      "folds", po::value(&a.folds), "svm: cross-validation folds (grid search, calibration)")(
      "max-samples", po::value(&a.max_samples),
      "svm: train on at most this many samples (training time grows with their square)")(
      "trees", po::value(&a.trees), "forest: trees (default 100)")(
      "max-depth", po::value(&a.max_depth), "forest: deepest split (default 10)")(
      "quiet,q", "no progress output");
  addInputOptions(o, a);
  po::positional_options_description pos;
  pos.add("kind", 1).add("dataset", 1);
  po::variables_map vm;
  if (!parseOptions("train", kSynopsis, o, pos, args, vm)) return 0;
  if (a.kind != "knn" && a.kind != "svm" && a.kind != "forest")
    throw ConfigError("pedtrack train: first argument must be knn, svm or forest (got '" + a.kind +
                      "')");
  if (a.trees < 1 || a.max_depth < 1)
    throw ConfigError("pedtrack train: --trees and --max-depth must be at least 1");
  if (a.out.empty()) throw ConfigError("pedtrack train: missing --out MODEL.yml");
  const bool progress = !vm.count("quiet");
  std::string command = "pedtrack train";
  for (const auto& s : args) command += " " + s;

  std::string described;
  classify::SampleSet s;
  if (!a.samples.empty()) {
    s = loadSamples(nullptr, a.samples, splitList(a.features), a.plugin_path, progress, described);
  } else {
    const Dataset d = datasetFromOptions(a.dataset, a.pipeline, a.sims, a.positives, a.negatives,
                                         a.topic, a.labels_topic, a.region, a.frame_step,
                                         a.min_range, a.max_range, a.features, "pedtrack train");
    s = loadSamples(&d, "", d.features, a.plugin_path, progress, described);
  }
  if (!a.save_samples.empty()) writeSamplesCsv(a.save_samples, s);
  const std::size_t persons = s.count(classify::Label::Person),
                    others = s.count(classify::Label::NonPerson);
  if (persons == 0 || others == 0)
    throw DataError("pedtrack train: the data has " + std::to_string(persons) + " persons and " +
                    std::to_string(others) + " non-persons; both classes are needed");

  classify::ModelInfo info;
  info.kind = a.kind;
  info.command = command;
  info.dataset = described;
  info.persons = persons;
  info.nonpersons = others;
  if (a.kind == "knn") {
    classify::KnnOptions opt;
    opt.k = int(a.k);
    opt.metric = classify::parseKnnMetric(a.metric);
    opt.minkowski_p = int(a.minkowski_p);
    opt.weighting = classify::parseKnnWeighting(a.weighting);
    classify::SampleSet protos = s.subsample(std::size_t(a.max_prototypes), a.seed);
    info.features = protos.features;
    auto stats = classify::KnnMetricStats::fit(protos);
    const classify::KnnClassifier knn(protos, stats, opt);
    classify::saveKnnModel(a.out, info, knn);
    std::cout << "k-NN model " << a.out << ": " << protos.count(classify::Label::Person)
              << " person and " << protos.count(classify::Label::NonPerson)
              << " non-person prototypes of " << protos.dims() << " features (from " << persons
              << " + " << others << " samples), k = " << opt.k << ", " << a.metric << ", "
              << a.weighting << "\n";
  } else if (a.kind == "forest") {
    classify::ForestTraining t;
    t.trees = int(a.trees);
    t.max_depth = int(a.max_depth);
    t.seed = a.seed;
    info.features = s.features;
    if (progress) std::cerr << "forest: " << t.trees << " trees on " << s.size() << " samples\n";
    const auto forest = classify::ForestClassifier::train(s, t);
    classify::saveForestModel(a.out, info, forest);
    std::cout << "forest model " << a.out << ": " << t.trees << " trees of depth <= " << t.max_depth
              << ", " << s.dims() << " features (trained on " << persons << " + " << others
              << " samples)\n";
  } else {
    classify::SvmTraining t;
    t.folds = int(a.folds);
    t.seed = a.seed;
    if (t.folds < 2) throw ConfigError("--folds: must be at least 2");
    const classify::SampleSet train = s.subsample(std::size_t(a.max_samples), a.seed);
    info.features = train.features;
    if (progress)
      std::cerr << "svm: grid search over C and gamma on " << train.size() << " samples\n";
    const auto svm = classify::SvmClassifier::train(train, t);
    classify::saveSvmModel(a.out, info, svm);
    std::cout << "SVM model " << a.out << ": RBF, C = " << svm.svm()->getC()
              << ", gamma = " << svm.svm()->getGamma() << ", "
              << svm.svm()->getSupportVectors().rows << " support vectors, " << train.dims()
              << " features (trained on " << train.count(classify::Label::Person) << " + "
              << train.count(classify::Label::NonPerson) << " samples), Platt a = " << svm.platt().a
              << ", b = " << svm.platt().b << "\n";
  }
  return exit_code::kOk;
}

}  // namespace pedtrack::cli
