#pragma once
// Small formatting helpers shared by the `pedtrack eval` reports.
#include <mrpt/core/format.h>

#include <cmath>
#include <string>

#include "pedtrack/outputs.h"

namespace pedtrack::cli {

/// A number for the table: "-" when undefined (0/0).
inline std::string fixed(double v, int decimals = 4) {
  return std::isfinite(v) ? mrpt::format("%.*f", decimals, v) : std::string("-");
}

// The report is a handful of flat objects; a JSON library would be a dependency for a dozen
// keys (as in writeRunJson). Undefined numbers (0/0) are null.
class Json {
 public:
  explicit Json(bool multiline = false) : sep_(multiline ? ",\n  " : ", "), multiline_(multiline) {}
  Json& num(const char* key, double v) {
    return raw(key, std::isfinite(v) ? mrpt::format("%.10g", v) : std::string("null"));
  }
  Json& count(const char* key, std::size_t v) { return raw(key, std::to_string(v)); }
  Json& text(const char* key, const std::string& v) {
    return raw(key, "\"" + jsonEscape(v) + "\"");
  }
  Json& raw(const char* key, const std::string& v) {
    out_ += (first_ ? "" : sep_) + std::string("\"") + key + "\": " + v;
    first_ = false;
    return *this;
  }
  std::string str() const { return multiline_ ? "{\n  " + out_ + "\n}" : "{" + out_ + "}"; }

 private:
  std::string sep_;
  bool multiline_;
  std::string out_;
  bool first_ = true;
};

}  // namespace pedtrack::cli
