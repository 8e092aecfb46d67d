#include "pedtrack/params.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "pedtrack/errors.h"
#include "pedtrack/param_table.h"
#include "pedtrack/text.h"

namespace pedtrack {

const char* toString(ParamType t) {
  switch (t) {
    case ParamType::Bool:
      return "bool";
    case ParamType::Int:
      return "int";
    case ParamType::Double:
      return "double";
    case ParamType::String:
      return "string";
    case ParamType::Enum:
      return "enum";
    case ParamType::InputFile:
      return "file";
    case ParamType::Vector:
      return "vector";
  }
  return "?";
}

static std::string formatNumber(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

ParamSpec ParamSpec::boolean(std::string name, bool def, std::string doc) {
  ParamSpec s;
  s.name = std::move(name);
  s.type = ParamType::Bool;
  s.default_value = def ? "true" : "false";
  s.doc = std::move(doc);
  return s;
}

ParamSpec ParamSpec::integer(std::string name, std::optional<long> def, std::string unit,
                             double min, double max, std::string doc) {
  ParamSpec s;
  s.name = std::move(name);
  s.type = ParamType::Int;
  if (def) s.default_value = std::to_string(*def);
  s.unit = std::move(unit);
  s.min = min;
  s.max = max;
  s.doc = std::move(doc);
  return s;
}

ParamSpec ParamSpec::real(std::string name, std::optional<double> def, std::string unit, double min,
                          double max, std::string doc) {
  ParamSpec s;
  s.name = std::move(name);
  s.type = ParamType::Double;
  if (def) s.default_value = formatNumber(*def);
  s.unit = std::move(unit);
  s.min = min;
  s.max = max;
  s.doc = std::move(doc);
  return s;
}

ParamSpec ParamSpec::text(std::string name, std::optional<std::string> def, std::string doc) {
  ParamSpec s;
  s.name = std::move(name);
  s.type = ParamType::String;
  s.default_value = std::move(def);
  s.doc = std::move(doc);
  return s;
}

ParamSpec ParamSpec::choice(std::string name, std::string def, std::vector<std::string> choices,
                            std::string doc) {
  ParamSpec s;
  s.name = std::move(name);
  s.type = ParamType::Enum;
  s.default_value = std::move(def);
  s.choices = std::move(choices);
  s.doc = std::move(doc);
  return s;
}

// 12 significant digits: a value typed in a pipeline survives validation unchanged.
static std::string joinNumbers(const std::vector<double>& v) {
  std::ostringstream os;
  os.precision(12);
  for (std::size_t i = 0; i < v.size(); ++i) os << (i ? " " : "") << v[i];
  return os.str();
}

std::string shortestNumber(double v) {
  char buf[40];
  // From 6 digits on, as `%g` writes them: 100 is "100", not "1e+02".
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

namespace param_detail {

std::string roundedNumber(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  return buf;
}

std::string joinNumbers(const std::vector<double>& v, bool exact) {
  std::string out;
  for (std::size_t i = 0; i < v.size(); ++i)
    out += (i ? " " : "") + (exact ? shortestNumber(v[i]) : roundedNumber(v[i]));
  return out;
}

}  // namespace param_detail

ParamSpec ParamSpec::vector(std::string name, std::optional<std::vector<double>> def,
                            std::string unit, std::size_t length, double min, double max,
                            std::string doc) {
  ParamSpec s;
  s.name = std::move(name);
  s.type = ParamType::Vector;
  if (def) s.default_value = joinNumbers(*def);
  s.unit = std::move(unit);
  s.length = length;
  s.min = min;
  s.max = max;
  s.doc = std::move(doc);
  return s;
}

ParamSpec ParamSpec::inputFile(std::string name, std::string doc, bool folder_ok) {
  ParamSpec s;
  s.name = std::move(name);
  s.type = ParamType::InputFile;
  s.doc = std::move(doc);
  s.folder_ok = folder_ok;
  return s;
}

std::string ParamSpec::rangeText() const {
  if (type == ParamType::Enum) {
    std::string r = "{";
    for (size_t i = 0; i < choices.size(); ++i) r += (i ? ", " : "") + choices[i];
    return r + "}";
  }
  if (type == ParamType::Bool) return "{true, false}";
  if (type == ParamType::Vector) {
    const std::string count = length ? std::to_string(length) : std::string("n");
    if (!std::isfinite(min) && !std::isfinite(max)) return count + " numbers";
    return count + " × [" + (std::isfinite(min) ? formatNumber(min) : std::string("-inf")) + ", " +
           (std::isfinite(max) ? formatNumber(max) : std::string("inf")) + "]";
  }
  if ((type == ParamType::Int || type == ParamType::Double) &&
      (std::isfinite(min) || std::isfinite(max))) {
    return "[" + (std::isfinite(min) ? formatNumber(min) : std::string("-inf")) + ", " +
           (std::isfinite(max) ? formatNumber(max) : std::string("inf")) + "]";
  }
  return "";
}

[[noreturn]] static void failAt(const std::string& where, const std::string& what) {
  throw ConfigError(where + ": " + what);
}

std::string validateValue(const ParamSpec& spec, const std::string& value,
                          const std::string& where) {
  auto fail = [&](const std::string& what) { failAt(where, what); };
  switch (spec.type) {
    case ParamType::Bool: {
      std::string v = value;
      std::transform(v.begin(), v.end(), v.begin(), ::tolower);
      if (v == "true" || v == "1" || v == "yes" || v == "on") return "true";
      if (v == "false" || v == "0" || v == "no" || v == "off") return "false";
      failAt(where, "'" + value + "' is not a boolean (expected true or false)");
    }
    case ParamType::Int:
    case ParamType::Double: {
      const bool integral = spec.type == ParamType::Int;
      std::size_t used = 0;
      double v = 0;
      try {
        v = integral ? static_cast<double>(std::stol(value, &used)) : std::stod(value, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != value.size() || !std::isfinite(v))
        fail("'" + value + "' is not " + (integral ? "an integer" : "a number") +
             (spec.unit.empty() ? "" : " (" + spec.unit + ")"));
      if (v < spec.min || v > spec.max)
        fail(value + " is out of range " + spec.rangeText() +
             (spec.unit.empty() ? "" : " " + spec.unit));
      return value;
    }
    case ParamType::Enum:
      if (std::find(spec.choices.begin(), spec.choices.end(), value) == spec.choices.end()) {
        std::string hint = closestMatch(value, spec.choices);
        fail("'" + value + "' is not one of " + spec.rangeText() +
             (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
      }
      return value;
    case ParamType::InputFile:
      if (value.empty()) fail("no file given");
      if (!std::filesystem::exists(value)) fail("file '" + value + "' does not exist");
      if (!spec.folder_ok && std::filesystem::is_directory(value))
        fail("'" + value + "' is a directory, not a file");
      return value;
    case ParamType::String:
      return value;
    case ParamType::Vector: {
      std::string text = value;
      std::replace(text.begin(), text.end(), ';', ' ');
      std::vector<double> v;
      for (const auto& tok : splitList(text)) {
        char* end = nullptr;
        const double x = std::strtod(tok.c_str(), &end);
        if (end == tok.c_str() || *end || !std::isfinite(x)) fail("'" + tok + "' is not a number");
        if (x < spec.min || x > spec.max)
          fail("element " + std::to_string(v.size() + 1) + " (" + tok + ") is out of range " +
               spec.rangeText() + (spec.unit.empty() ? "" : " " + spec.unit));
        v.push_back(x);
      }
      if (v.empty()) fail("no numbers given");
      if (spec.length && v.size() != spec.length)
        fail("expected " + std::to_string(spec.length) + " numbers, got " +
             std::to_string(v.size()));
      return joinNumbers(v);
    }
  }
  return value;
}

// Damerau-free Levenshtein distance; keys are short, so O(n*m) is nothing.
static std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t sub = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::numeric_limits<std::size_t>::max();
  for (const auto& c : candidates) {
    const std::size_t d = editDistance(word, c);
    if (d < best_d) best_d = d, best = c;
  }
  // Close enough: at most a third of the word wrong (and at least one edit allowed).
  const std::size_t limit = std::max<std::size_t>(1, (word.size() + 2) / 3);
  return best_d <= limit ? best : std::string();
}

std::string ParamSet::where(const std::string& key) const {
  return file_ + ": [" + section_ + "] " + key;
}

const std::string& ParamSet::getString(const std::string& key) const {
  auto it = values_.find(key);
  if (it == values_.end())
    throw std::logic_error("plugin reads undeclared parameter '" + key + "' of [" + section_ + "]");
  return it->second;
}

double ParamSet::getDouble(const std::string& key) const {
  return std::stod(getString(key));
}
long ParamSet::getInt(const std::string& key) const {
  return std::stol(getString(key));
}
bool ParamSet::getBool(const std::string& key) const {
  return getString(key) == "true";
}

std::vector<double> ParamSet::getVector(const std::string& key) const {
  return getNumbers(key);
}

std::vector<std::string> ParamSet::getList(const std::string& key) const {
  return splitList(getString(key));
}

std::vector<double> ParamSet::getNumbers(const std::string& key, std::size_t n) const {
  return parseNumbers(getString(key), n, where(key));
}

std::vector<double> parseNumbers(const std::string& value, std::size_t n,
                                 const std::string& where) {
  std::vector<double> out;
  std::string text = value;
  std::replace(text.begin(), text.end(), ';', ' ');
  for (const auto& tok : splitList(text)) {
    char* end = nullptr;
    const double v = std::strtod(tok.c_str(), &end);
    if (end == tok.c_str() || *end) throw ConfigError(where + ": '" + tok + "' is not a number");
    out.push_back(v);
  }
  if (n && out.size() != n)
    throw ConfigError(where + ": expected " + std::to_string(n) + " numbers, got " +
                      std::to_string(out.size()));
  return out;
}

ParamSet validateSection(const std::vector<ParamSpec>& specs,
                         const std::vector<std::pair<std::string, std::string>>& given,
                         const std::string& file, const std::string& section,
                         const std::string& kind) {
  ParamSet out(file, section);
  std::vector<std::string> declared;
  for (const auto& p : specs) declared.push_back(p.name);
  for (const auto& [key, value] : given) {
    if (std::find(declared.begin(), declared.end(), key) != declared.end()) continue;
    const std::string hint = closestMatch(key, declared);
    throw ConfigError(out.where(key) + ": unknown key for " + kind +
                      (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
  }
  for (const auto& spec : specs) {
    const std::string where = out.where(spec.name);
    auto it = std::find_if(given.begin(), given.end(),
                           [&](const auto& kv) { return kv.first == spec.name; });
    if (it == given.end()) {
      if (spec.required()) throw ConfigError(where + ": missing required key (" + spec.doc + ")");
      out.setDefault(spec.name, *spec.default_value);
      continue;
    }
    out.set(spec.name, validateValue(spec, it->second, where));
  }
  return out;
}

}  // namespace pedtrack
