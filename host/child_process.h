#pragma once
// A child process run to completion while its resident memory is sampled: `pedtrack bench
// --suite` runs each measurement in a process of its own, so the peak RSS it reports is that
// measurement's alone and a crash in one cannot end the suite.
#include <string>
#include <utility>
#include <vector>

namespace pedtrack::cli {

struct ChildResult {
  int exit_code = -1;    ///< the child's exit status; 128 + N when killed by signal N
  double wall_s = 0;     ///< from start to exit
  long peak_rss_kb = 0;  ///< the child's largest resident set (getrusage ru_maxrss)
  /// (seconds since start, VmRSS in kB) every `sample_every_s`; empty when that is 0.
  std::vector<std::pair<double, long>> rss;
};

/// Runs `argv` (argv[0] a path) with stdout and stderr appended to `log` and waits for it.
/// Throws DataError when it cannot be started.
ChildResult runChild(const std::vector<std::string>& argv, const std::string& log,
                     double sample_every_s = 0);

/// This executable's own path (/proc/self/exe), to run `pedtrack` subcommands as children.
std::string selfExecutable();

/// The last `lines` lines of a text file ("" when it cannot be read), for error messages.
std::string tailOf(const std::string& path, int lines = 3);

}  // namespace pedtrack::cli
