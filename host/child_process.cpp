#include "child_process.h"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <deque>
#include <filesystem>
#include <fstream>
#include <thread>

#include "pedtrack/errors.h"

namespace pedtrack::cli {
namespace {

// VmRSS of a live process, kB; -1 once it is gone.
long residentKb(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string key;
  while (status >> key) {
    if (key == "VmRSS:") {
      long kb = -1;
      status >> kb;
      return kb;
    }
    status.ignore(4096, '\n');
  }
  return -1;
}

}  // namespace

ChildResult runChild(const std::vector<std::string>& argv, const std::string& log,
                     double sample_every_s) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd < 0) throw DataError(log + ": cannot write");
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const pid_t pid = fork();
  if (pid < 0) {
    ::close(fd);
    throw DataError("cannot start " + argv.at(0));
  }
  if (pid == 0) {
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    execv(args[0], args.data());
    _exit(127);
  }
  ::close(fd);
  ChildResult r;
  const auto since = [&] { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  int status = 0;
  rusage usage{};
  double next_sample = 0;
  for (;;) {
    const pid_t done = wait4(pid, &status, WNOHANG, &usage);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) throw DataError("lost the child process " + argv.at(0));
    if (sample_every_s > 0 && since() >= next_sample) {
      if (const long kb = residentKb(pid); kb > 0) r.rss.emplace_back(since(), kb);
      next_sample += sample_every_s;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  r.wall_s = since();
  r.peak_rss_kb = usage.ru_maxrss;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

std::string selfExecutable() {
  std::error_code ec;
  const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw DataError("/proc/self/exe: cannot read this program's path");
  return p.string();
}

std::string tailOf(const std::string& path, int lines) {
  std::ifstream in(path);
  std::deque<std::string> last;
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) continue;
    last.push_back(line);
    if (static_cast<int>(last.size()) > lines) last.pop_front();
  }
  std::string s;
  for (const auto& l : last) s += (s.empty() ? "" : " | ") + l;
  return s;
}

}  // namespace pedtrack::cli
