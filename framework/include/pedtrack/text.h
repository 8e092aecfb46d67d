#pragma once
// Small string helpers shared by the host, the framework and plugins.
#include <string>
#include <vector>

namespace pedtrack {

std::string trim(const std::string& s);
/// Splits on white space and commas, dropping empty items.
std::vector<std::string> splitList(const std::string& s);
/// The fields of one line of the output contract's CSV files (they never quote): split at
/// `sep`, each field trimmed, empty ones kept, a carriage return dropped.
std::vector<std::string> splitFields(const std::string& line, char sep = ',');
/// The message of an exception in one line: MRPT exceptions carry a multi-line header, location
/// and call trace around their "Message:" line; other multi-line texts give their last line.
std::string oneLine(const std::string& what);
/// A number as a message shows it: up to 6 significant digits, no trailing zeros ("0.5", "10").
std::string shortNumber(double v);

/// Prints "warning: <prefix><message>" on stderr the first time each message is given: input
/// that is wrong the same way in every frame is reported once, not thousands of times.
class WarnOnce {
 public:
  explicit WarnOnce(std::string prefix = std::string()) : prefix_(std::move(prefix)) {}
  void operator()(const std::string& message);

 private:
  std::string prefix_;
  std::vector<std::string> seen_;
};

}  // namespace pedtrack
