#pragma once
// Plugin parameters are declared once, as data: from one declaration come INI validation,
// the "did you mean" error for a misspelt key, and `pedtrack plugins NAME`.
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace pedtrack {

/// Vector: a list of numbers (white space, commas or semicolons between them), with an exact
/// length (or any) and a range every element must lie in — matrices and noise diagonals.
enum class ParamType { Bool, Int, Double, String, Enum, InputFile, Vector };
const char* toString(ParamType t);

struct ParamSpec {
  std::string name;
  ParamType type = ParamType::String;
  std::string unit;                                       ///< "m", "s", "Hz", "" for none
  std::optional<std::string> default_value;               ///< no default → the key is required
  double min = -std::numeric_limits<double>::infinity();  ///< Int/Double; Vector elements
  double max = std::numeric_limits<double>::infinity();
  std::vector<std::string> choices;  ///< Enum only
  std::size_t length = 0;            ///< Vector only: exact element count, 0 = any (≥ 1)
  std::string doc;                   ///< one line
  bool folder_ok = false;            ///< InputFile only: a folder is accepted too

  // Fluent builders, so a plugin's declaration reads as a table.
  static ParamSpec boolean(std::string name, bool def, std::string doc);
  static ParamSpec integer(std::string name, std::optional<long> def, std::string unit, double min,
                           double max, std::string doc);
  static ParamSpec real(std::string name, std::optional<double> def, std::string unit, double min,
                        double max, std::string doc);
  static ParamSpec text(std::string name, std::optional<std::string> def, std::string doc);
  static ParamSpec choice(std::string name, std::string def, std::vector<std::string> choices,
                          std::string doc);
  /// A list of numbers; `length` 0 accepts any count of at least one.
  static ParamSpec vector(std::string name, std::optional<std::vector<double>> def,
                          std::string unit, std::size_t length, double min, double max,
                          std::string doc);
  /// A file that must exist before the first frame (checked at validation time); with
  /// `folder_ok` a folder too (a sequence of scans, one file each).
  static ParamSpec inputFile(std::string name, std::string doc, bool folder_ok = false);
  bool required() const { return !default_value.has_value(); }
  /// "[0, 100]", "{realtime, max}", "9 × [0, 1]" or "" when anything of the type goes.
  std::string rangeText() const;
};

/// Validated values of one plugin instance (one INI section). Only keys that were declared
/// can be read; every declared key has a value (given or default).
class ParamSet {
 public:
  ParamSet() = default;
  ParamSet(std::string file, std::string section)
      : file_(std::move(file)), section_(std::move(section)) {}

  /// A value the pipeline gave (or a caller set).
  void set(const std::string& key, std::string value) {
    values_[key] = std::move(value);
    given_.insert(key);
  }
  /// A declared default: readable like any value, but not given().
  void setDefault(const std::string& key, std::string value) {
    values_[key] = std::move(value);
    given_.erase(key);
  }
  bool has(const std::string& key) const { return values_.count(key) != 0; }
  /// The pipeline gave this key (it is not the declared default).
  bool given(const std::string& key) const { return given_.count(key) != 0; }

  const std::string& getString(const std::string& key) const;
  double getDouble(const std::string& key) const;
  long getInt(const std::string& key) const;
  bool getBool(const std::string& key) const;
  /// A Vector parameter's numbers (validated already).
  std::vector<double> getVector(const std::string& key) const;
  /// Splits a list value on whitespace and commas.
  std::vector<std::string> getList(const std::string& key) const;
  /// The value as numbers separated by white space, commas or semicolons; exactly `n` of them
  /// unless n is 0. ConfigError naming the key for a non-number or a wrong count.
  std::vector<double> getNumbers(const std::string& key, std::size_t n = 0) const;

  const std::string& file() const { return file_; }
  const std::string& section() const { return section_; }
  /// "pipeline.ini: [source] file" — the prefix every error about this key starts with.
  std::string where(const std::string& key) const;
  const std::map<std::string, std::string>& values() const { return values_; }

 private:
  std::string file_, section_;
  std::map<std::string, std::string> values_;
  std::set<std::string> given_;
};

/// Checks `value` against `spec`; returns the normalised value or throws ConfigError whose text
/// starts with `where`.
std::string validateValue(const ParamSpec& spec, const std::string& value,
                          const std::string& where);

/// Validates one INI section's keys against `specs`: an unknown key (with a "did you mean"), a
/// missing required key or a bad value throws ConfigError naming file, section and key; every
/// declared key gets its value or its default. `kind` names what the section is in messages.
ParamSet validateSection(const std::vector<ParamSpec>& specs,
                         const std::vector<std::pair<std::string, std::string>>& given,
                         const std::string& file, const std::string& section,
                         const std::string& kind);

/// The numbers of a list value (white space, commas or semicolons between them): exactly `n` of
/// them unless n is 0. ConfigError starting with `where` for a non-number or a wrong count.
std::vector<double> parseNumbers(const std::string& value, std::size_t n, const std::string& where);

/// `v` as the shortest text that reads back as exactly `v` ("0.45", "0.2617993877991494").
std::string shortestNumber(double v);

/// The closest candidate to `word` by edit distance, or "" when nothing is close enough.
std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace pedtrack
