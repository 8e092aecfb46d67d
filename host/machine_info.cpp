#include "machine_info.h"

#include <sys/utsname.h>

#include <cstdio>
#include <fstream>
#include <thread>

namespace pedtrack::cli {
namespace {

// The first line a shell command prints, "" when it fails.
std::string firstLine(const std::string& command) {
  std::string out;
  if (FILE* p = popen(command.c_str(), "r")) {
    char buf[256];
    if (fgets(buf, sizeof buf, p)) out = buf;
    pclose(p);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

std::string shellQuoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

MachineInfo machineInfo(const std::string& source_dir, const std::string& build_type) {
  MachineInfo m;
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);)
    if (line.rfind("model name", 0) == 0) {
      m.cpu = line.substr(line.find(':') + 2);
      break;
    }
  m.threads = std::thread::hardware_concurrency();
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  long kb = 0;
  if (meminfo >> key >> kb && key == "MemTotal:") m.memory_gb = kb / 1048576.0;
  utsname u{};
  if (uname(&u) == 0) m.kernel = std::string(u.sysname) + " " + u.release;
#if defined(__clang__)
  m.compiler = "clang " __clang_version__;
#elif defined(__GNUC__)
  m.compiler = "gcc " __VERSION__;
#endif
  m.build_type = build_type.empty() ? "(none)" : build_type;
  const std::string git = "git -C " + shellQuoted(source_dir);
  m.commit = firstLine(git + " rev-parse --short HEAD 2>/dev/null");
  if (m.commit.empty())
    m.commit = "unknown (not a git checkout)";
  else if (!firstLine(git + " status --porcelain --untracked-files=no 2>/dev/null").empty())
    m.commit += " + uncommitted changes";
  return m;
}

}  // namespace pedtrack::cli
