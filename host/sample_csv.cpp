#include "sample_csv.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "pedtrack/errors.h"

namespace pedtrack::cli {

void writeSamplesCsv(const std::string& path, const classify::SampleSet& s) {
  std::ofstream out(path);
  if (!out) throw ConfigError(path + ": cannot write the samples file");
  out << "label";
  for (const auto& f : s.features) out << ',' << f;
  out << '\n';
  char buf[32];
  for (std::size_t i = 0; i < s.size(); ++i) {
    out << int(s.y[i]);
    for (std::size_t j = 0; j < s.dims(); ++j) {
      std::snprintf(buf, sizeof buf, ",%.9g", s.row(i)[j]);
      out << buf;
    }
    out << '\n';
  }
  if (!out.flush()) throw DataError(path + ": write failed");
}

void writeScoresCsv(const std::string& path, const std::vector<classify::Label>& y,
                    const std::vector<const std::vector<double>*>& scores) {
  std::ofstream out(path);
  if (!out) throw ConfigError(path + ": cannot write the scores file");
  out << "label";
  for (std::size_t m = 0; m < scores.size(); ++m) out << ",score_" << m;
  out << '\n';
  char buf[32];
  for (std::size_t i = 0; i < y.size(); ++i) {
    out << int(y[i]);
    for (const auto* s : scores) {
      std::snprintf(buf, sizeof buf, ",%.9g", (*s)[i]);
      out << buf;
    }
    out << '\n';
  }
  if (!out.flush()) throw DataError(path + ": write failed");
}

classify::SampleSet readSamplesCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ConfigError(path + ": samples file not found");
  std::string line;
  if (!std::getline(in, line) || line.rfind("label,", 0) != 0)
    throw ConfigError(path + ": line 1: expected the header 'label,<feature>,...'");
  classify::SampleSet s;
  std::stringstream h(line.substr(6));
  for (std::string c; std::getline(h, c, ',');) s.features.push_back(c);
  std::vector<double> v(s.dims());
  for (std::size_t n = 2; std::getline(in, line); ++n) {
    if (line.empty()) continue;
    std::stringstream r(line);
    std::string c;
    std::getline(r, c, ',');
    if (c != "0" && c != "1")
      throw ConfigError(path + ": line " + std::to_string(n) + ": label '" + c + "' is not 0 or 1");
    const auto label = classify::Label(c == "1");
    std::size_t j = 0;
    for (; j < v.size() && std::getline(r, c, ','); ++j) {
      char* end = nullptr;
      v[j] = std::strtod(c.c_str(), &end);
      if (c.empty() || *end || !std::isfinite(v[j]))
        throw ConfigError(path + ": line " + std::to_string(n) + ": '" + c +
                          "' is not a finite number (" + s.features[j] + ")");
    }
    if (j != v.size() || std::getline(r, c, ','))
      throw ConfigError(path + ": line " + std::to_string(n) + ": expected " +
                        std::to_string(v.size() + 1) + " columns");
    s.add(v.data(), label);
  }
  return s;
}

}  // namespace pedtrack::cli
