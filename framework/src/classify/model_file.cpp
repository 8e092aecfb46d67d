#include "pedtrack/classify/model_file.h"

#include <cstdio>
#include <ctime>
#include <filesystem>
#include <opencv2/core.hpp>

#include "pedtrack/classify/model_text.h"
#include "pedtrack/errors.h"
#include "pedtrack/text.h"

namespace pedtrack::classify {
namespace {

const char* kFormat = "pedtrack-classifier";

std::string utcNow() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

// Writes through a temporary file renamed into place: a crash never leaves half a model.
class ModelWriter {
 public:
  ModelWriter(const std::string& path, const ModelInfo& info) : path_(path), tmp_(path + ".tmp") {
    std::error_code ec;
    if (const auto dir = std::filesystem::path(path).parent_path(); !dir.empty())
      std::filesystem::create_directories(dir, ec);
    try {
      fs_.open(tmp_, cv::FileStorage::WRITE | cv::FileStorage::FORMAT_YAML);
    } catch (const cv::Exception&) {
    }
    if (!fs_.isOpened()) throw ConfigError(path + ": cannot write the model file");
    fs_ << "format" << kFormat << "version" << kModelFormatVersion << "kind" << info.kind;
    fs_ << "features" << info.features;
    fs_ << "command" << info.command << "dataset" << info.dataset;
    fs_ << "persons" << int(info.persons) << "nonpersons" << int(info.nonpersons);
    fs_ << "created" << (info.created.empty() ? utcNow() : info.created);
  }
  cv::FileStorage& fs() { return fs_; }
  void commit() {
    fs_ << "end" << kFormat;
    fs_.release();
    std::error_code ec;
    std::filesystem::rename(tmp_, path_, ec);
    if (ec) throw ConfigError(path_ + ": cannot write the model file (" + ec.message() + ")");
  }

 private:
  std::string path_, tmp_;
  cv::FileStorage fs_;
};

cv::Mat toMat(const Eigen::MatrixXd& m) {
  cv::Mat out(int(m.rows()), int(m.cols()), CV_64F);
  for (int r = 0; r < out.rows; ++r)
    for (int c = 0; c < out.cols; ++c) out.at<double>(r, c) = m(r, c);
  return out;
}

Eigen::MatrixXd toEigen(const cv::Mat& m) {
  Eigen::MatrixXd out(m.rows, m.cols);
  for (int r = 0; r < m.rows; ++r)
    for (int c = 0; c < m.cols; ++c) out(r, c) = m.at<double>(r, c);
  return out;
}

// Every matrix under `n` (a map with a "dt", which is what OpenCV's reader takes for one) must
// have whole-number rows and cols of at most 10^7, 1–512 channels, no "sizes" (pedtrack writes
// 2-D matrices only) and as many data values as rows × cols × channels: OpenCV's reader
// allocates rows × cols first, so a corrupt "rows" asked it for gigabytes (found by fuzz_model,
// twice: a "rows: ~", and a matrix whose "data" key was mangled, so that it was not checked and
// its "rows: (2" read as INT_MAX). Returns the first bad matrix's key path, "" when all are sound.
std::string badMatrix(const cv::FileNode& n, const std::string& at) {
  if (n.isMap() && !n["dt"].empty()) {
    const cv::FileNode rows = n["rows"], cols = n["cols"], dt = n["dt"], data = n["data"];
    if (!rows.isInt() || !cols.isInt() || !dt.isString() || !data.isSeq() || !n["sizes"].empty())
      return at;
    const long r = int(rows), c = int(cols);
    const std::string type = std::string(dt);
    const long channels = !type.empty() && std::isdigit(static_cast<unsigned char>(type[0]))
                              ? std::strtol(type.c_str(), nullptr, 10)
                              : 1;
    if (r < 0 || c < 0 || r > 10000000 || c > 10000000 || channels < 1 || channels > 512 ||
        r * c * channels != static_cast<long>(data.size()))
      return at;
    return "";
  }
  if (n.isMap() || n.isSeq()) {
    std::size_t i = 0;
    for (auto it = n.begin(); it != n.end(); ++it, ++i) {
      const cv::FileNode child = *it;
      const std::string name = n.isMap() ? child.name() : "[" + std::to_string(i) + "]";
      if (std::string bad = badMatrix(child, at.empty() ? name : at + "." + name); !bad.empty())
        return bad;
    }
  }
  return "";
}

// The first thing in an SVM node that OpenCV's SVM::read would trust unchecked, "" when none.
// pedtrack trains C_SVC with an RBF kernel: two classes, one decision function, `dims` features.
// SVM::read allocates support vectors × var_count floats and, per decision function, sv_count
// weights and indices before it checks them against the data (a corrupt var_count or sv_count
// asked for gigabytes, and 40,000 features × 40,000 one-number vectors would ask for 6.4 GB),
// and with a LINEAR kernel and optimize_linear it indexes the vectors by the file's indices as
// it reads. So every count must match the data it counts, and every index a vector.
std::string badSvm(const cv::FileNode& svm, int dims) {
  const auto whole = [](const cv::FileNode& v, long lo, long hi) {
    return v.isInt() && int(v) >= lo && int(v) <= hi;
  };
  const auto vectors = [&](const cv::FileNode& list, const cv::FileNode& total) {
    if (!list.isSeq() || !total.isInt() || int(total) != int(list.size())) return false;
    for (auto it = list.begin(); it != list.end(); ++it)
      if (!(*it).isSeq() || int((*it).size()) != dims) return false;
    return true;
  };
  if (!svm["svm_type"].empty() || std::string(svm["svmType"]) != "C_SVC") return "not a C_SVC SVM";
  if (std::string(svm["kernel"]["type"]) != "RBF") return "not an RBF kernel";
  if (!svm["optimize_linear"].empty() && !whole(svm["optimize_linear"], 0, 0))
    return "optimize_linear is set";
  if (!whole(svm["var_count"], dims, dims)) return "var_count is not the features' count";
  if (!whole(svm["class_count"], 2, 2)) return "class_count is not 2";
  if (!vectors(svm["support_vectors"], svm["sv_total"]) || int(svm["sv_total"]) < 1)
    return "sv_total does not match support_vectors, or one has other than var_count values";
  const long sv_total = int(svm["sv_total"]);
  const cv::FileNode uncompressed = svm["uncompressed_sv_total"];
  if (!uncompressed.empty() &&
      !(whole(uncompressed, 0, 0) || vectors(svm["uncompressed_support_vectors"], uncompressed)))
    return "uncompressed_sv_total does not match uncompressed_support_vectors, or one has other "
           "than var_count values";
  const cv::FileNode functions = svm["decision_functions"];
  if (!functions.isSeq() || functions.size() != 1) return "not one decision function";
  const cv::FileNode f = functions[0], index = f["index"];
  if (!whole(f["sv_count"], 0, sv_total) || f["alpha"].size() != std::size_t(int(f["sv_count"])) ||
      index.size() != std::size_t(int(f["sv_count"])))
    return "the decision function's sv_count, alpha and index do not agree";
  for (auto it = index.begin(); it != index.end(); ++it)
    if (!whole(*it, 0, sv_total - 1))
      return "a support vector index outside 0.." + std::to_string(sv_total - 1);
  return "";
}

// An open, checked model file: format, version, kind and end marker verified.
class ModelReader {
 public:
  ModelReader(const std::string& path, const std::string& want_kind) : path_(path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
      throw ConfigError(path + ": model file not found");
    // Parsed from the very text that was checked (readModelText) rather than reopened by name.
    const std::string text = readModelText(path);
    try {
      fs_.open(text,
               cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
    } catch (const cv::Exception& e) {
      fail("not a readable model file (" + oneLine(e.err) + ")");
    }
    if (!fs_.isOpened()) fail("not a readable model file");
    if (fs_["format"].empty() || std::string(fs_["format"]) != kFormat)
      fail("not a pedtrack classifier model (no 'format: pedtrack-classifier')");
    const int version = fs_["version"].empty() ? -1 : int(fs_["version"]);
    if (version != kModelFormatVersion)
      fail("model format version " + std::to_string(version) + ", this pedtrack reads version " +
           std::to_string(kModelFormatVersion) + " (retrain it with `pedtrack train`)");
    if (fs_["end"].empty() || std::string(fs_["end"]) != kFormat)
      fail("truncated model file (no end marker)");
    if (const std::string bad = badMatrix(fs_.root(), ""); !bad.empty())
      fail("matrix '" + bad + "': rows × cols do not match its data");
    info.kind = std::string(fs_["kind"]);
    if (!want_kind.empty() && info.kind != want_kind)
      fail("holds a '" + info.kind + "' model, not '" + want_kind + "'");
    fs_["features"] >> info.features;
    if (info.features.empty()) fail("lists no features");
    info.command = std::string(fs_["command"]);
    info.dataset = std::string(fs_["dataset"]);
    info.persons = std::size_t(std::max(0, int(fs_["persons"])));
    info.nonpersons = std::size_t(std::max(0, int(fs_["nonpersons"])));
    info.created = std::string(fs_["created"]);
  }
  [[noreturn]] void fail(const std::string& what) const { throw ConfigError(path_ + ": " + what); }
  cv::Mat mat(const char* key, int rows, int cols, int type) {
    cv::Mat m;
    try {
      fs_[key] >> m;
    } catch (const cv::Exception& e) {
      fail(std::string("bad '") + key + "' (" + oneLine(e.err) + ")");
    }
    if (m.empty() || m.type() != type || (rows >= 0 && m.rows != rows) || m.cols != cols)
      fail(std::string("'") + key + "' is missing or has the wrong size");
    return m;
  }
  cv::FileNode node(const char* key) { return fs_[key]; }

  ModelInfo info;

 private:
  std::string path_;
  cv::FileStorage fs_;
};

}  // namespace

Scorer::~Scorer() = default;

void saveKnnModel(const std::string& path, const ModelInfo& info, const KnnClassifier& knn) {
  ModelWriter w(path, info);
  auto& fs = w.fs();
  const SampleSet& p = knn.prototypes();
  cv::Mat x(int(p.size()), int(p.dims()), CV_64F), y(int(p.size()), 1, CV_32S);
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t j = 0; j < p.dims(); ++j) x.at<double>(int(i), int(j)) = p.row(i)[j];
    y.at<int>(int(i)) = int(p.y[i]);
  }
  fs << "k" << knn.options().k << "metric" << toString(knn.options().metric);
  fs << "minkowski_p" << knn.options().minkowski_p;
  fs << "weighting" << toString(knn.options().weighting);
  fs << "sigma" << toMat(knn.stats().sigma);                // (Σ_P + Σ_P̄)/2
  fs << "stddev" << toMat(knn.stats().stddev.transpose());  // Minkowski scaling 1/σ
  fs << "prototypes" << x << "labels" << y;
  w.commit();
}

void saveSvmModel(const std::string& path, const ModelInfo& info, const SvmClassifier& svm) {
  ModelWriter w(path, info);
  auto& fs = w.fs();
  fs << "mean" << svm.standardizer().mean << "scale" << svm.standardizer().scale;
  fs << "platt_a" << svm.platt().a << "platt_b" << svm.platt().b;
  fs << "svm"
     << "{";
  svm.svm()->write(fs);
  fs << "}";
  w.commit();
}

void saveForestModel(const std::string& path, const ModelInfo& info, const ForestClassifier& f) {
  ModelWriter w(path, info);
  auto& fs = w.fs();
  fs << "forest"
     << "{";
  f.forest()->write(fs);
  fs << "}";
  w.commit();
}

namespace {

// The loaders' bodies, on a reader already open and checked, so that loadScorer reads a file
// once (it read it twice, once for its kind).
LoadedKnn readKnn(ModelReader& r) {
  LoadedKnn m;
  m.info = r.info;
  const int d = int(m.info.features.size());
  const cv::Mat x = r.mat("prototypes", -1, d, CV_64F);
  const cv::Mat y = r.mat("labels", x.rows, 1, CV_32S);
  m.stats.sigma = toEigen(r.mat("sigma", d, d, CV_64F));
  m.stats.stddev = toEigen(r.mat("stddev", 1, d, CV_64F)).transpose();
  try {
    m.options.k = int(r.node("k"));
    m.options.metric = parseKnnMetric(std::string(r.node("metric")));
    m.options.minkowski_p = int(r.node("minkowski_p"));
    m.options.weighting = parseKnnWeighting(std::string(r.node("weighting")));
  } catch (const ConfigError& e) {
    r.fail(e.what());
  }
  m.prototypes.features = m.info.features;
  for (int i = 0; i < x.rows; ++i) {
    const int l = y.at<int>(i);
    if (l != 0 && l != 1)
      r.fail("label " + std::to_string(l) + " of prototype " + std::to_string(i) +
             " is not 0 or 1");
    m.prototypes.add(x.ptr<double>(i), Label(l));
  }
  return m;
}

LoadedSvm readSvm(ModelReader& r) {
  LoadedSvm m;
  m.info = r.info;
  const int d = int(m.info.features.size());
  Standardizer z;
  r.node("mean") >> z.mean;
  r.node("scale") >> z.scale;
  if (int(z.mean.size()) != d || int(z.scale.size()) != d)
    r.fail("'mean'/'scale' do not match the features");
  for (double s : z.scale)
    if (!(s > 0)) r.fail("'scale' has a value that is not positive");
  PlattSigmoid platt{double(r.node("platt_a")), double(r.node("platt_b"))};
  if (const std::string bad = badSvm(r.node("svm"), d); !bad.empty())
    r.fail("bad 'svm' (" + bad + ")");
  auto svm = cv::ml::SVM::create();
  try {
    svm->read(r.node("svm"));
  } catch (const cv::Exception& e) {
    r.fail("bad 'svm' (" + oneLine(e.err) + ")");
  }
  if (!svm->isTrained() || svm->getVarCount() != d)
    r.fail("'svm' is missing or does not match the features");
  try {
    m.svm = std::make_unique<SvmClassifier>(svm, z, platt, m.info.features);
  } catch (const DataError& e) {
    r.fail(e.what());
  }
  return m;
}

LoadedForest readForest(ModelReader& r) {
  LoadedForest m;
  m.info = r.info;
  auto f = cv::ml::RTrees::create();
  try {
    f->read(r.node("forest"));
  } catch (const cv::Exception& e) {
    r.fail("bad 'forest' (" + oneLine(e.err) + ")");
  }
  try {
    m.forest = std::make_unique<ForestClassifier>(f, m.info.features);
  } catch (const DataError& e) {
    r.fail(std::string("'forest' is missing or does not match the features (") + e.what() + ")");
  }
  return m;
}

}  // namespace

LoadedKnn loadKnnModel(const std::string& path) {
  ModelReader r(path, "knn");
  return readKnn(r);
}

LoadedSvm loadSvmModel(const std::string& path) {
  ModelReader r(path, "svm");
  return readSvm(r);
}

LoadedForest loadForestModel(const std::string& path) {
  ModelReader r(path, "forest");
  return readForest(r);
}

std::string modelKind(const std::string& path) {
  return ModelReader(path, "").info.kind;
}

namespace {

class KnnScorer : public Scorer {
 public:
  KnnScorer(LoadedKnn m, const KnnOptions* o)
      : info_(m.info), knn_(std::move(m.prototypes), std::move(m.stats), o ? *o : m.options) {}
  const ModelInfo& info() const override { return info_; }
  void score(const double* x, std::size_t n, std::vector<double>& out) const override {
    out.resize(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = knn_.quality(x + i * knn_.dims());
  }

 private:
  ModelInfo info_;
  KnnClassifier knn_;
};

class SvmScorer : public Scorer {
 public:
  explicit SvmScorer(LoadedSvm m) : info_(m.info), svm_(std::move(m.svm)) {}
  const ModelInfo& info() const override { return info_; }
  void score(const double* x, std::size_t n, std::vector<double>& out) const override {
    svm_->probability(x, n, out);
  }

 private:
  ModelInfo info_;
  std::unique_ptr<SvmClassifier> svm_;
};

class ForestScorer : public Scorer {
 public:
  explicit ForestScorer(LoadedForest m) : info_(m.info), forest_(std::move(m.forest)) {}
  const ModelInfo& info() const override { return info_; }
  void score(const double* x, std::size_t n, std::vector<double>& out) const override {
    forest_->probability(x, n, out);
  }

 private:
  ModelInfo info_;
  std::unique_ptr<ForestClassifier> forest_;
};

}  // namespace

std::unique_ptr<Scorer> loadScorer(const std::string& path, const KnnOptions* knn) {
  ModelReader r(path, "");
  const std::string kind = r.info.kind;
  if (kind == "knn") return std::make_unique<KnnScorer>(readKnn(r), knn);
  if (kind == "svm") return std::make_unique<SvmScorer>(readSvm(r));
  if (kind == "forest") return std::make_unique<ForestScorer>(readForest(r));
  throw ConfigError(path + ": unknown model kind '" + kind + "' (knn, svm, forest)");
}

}  // namespace pedtrack::classify
