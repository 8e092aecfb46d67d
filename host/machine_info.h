#pragma once
// What a benchmark ran on, for the head of BENCHMARKS.md: CPU, cores, memory, kernel, compiler,
// build type and the source's commit.
#include <string>

namespace pedtrack::cli {

struct MachineInfo {
  std::string cpu;       ///< /proc/cpuinfo "model name"
  unsigned threads = 0;  ///< hardware threads
  double memory_gb = 0;  ///< /proc/meminfo MemTotal
  std::string kernel;    ///< uname -sr
  std::string compiler;  ///< of this build
  std::string build_type;
  std::string commit;  ///< `git rev-parse --short HEAD` of `source_dir`, "+ changes" when dirty
};

MachineInfo machineInfo(const std::string& source_dir, const std::string& build_type);

}  // namespace pedtrack::cli
