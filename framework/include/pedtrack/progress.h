#pragma once
// Progress on long work: a bar on a terminal, a plain line every few seconds otherwise.
#include <chrono>
#include <string>

namespace pedtrack {

class Progress {
 public:
  /// `enabled` false silences it (--quiet).
  Progress(std::string label, bool enabled);
  /// `fraction` < 0 when the total is unknown.
  void update(std::size_t items, double fraction);
  void done(std::size_t items);

 private:
  std::string label_;
  bool enabled_, tty_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace pedtrack
