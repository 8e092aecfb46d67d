#include "test_support.h"

#include <pthread.h>
#include <sched.h>
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "pedtrack/pipeline.h"

namespace fs = std::filesystem;

namespace pedtrack::test {

static std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

CommandResult runShell(const std::string& command_line) {
  CommandResult r;
  FILE* p = popen((command_line + " 2>&1").c_str(), "r");
  if (!p) throw std::runtime_error("popen failed: " + command_line);
  char buf[4096];
  std::size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.output.append(buf, n);
  const int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

CommandResult runHost(const std::vector<std::string>& args) {
  std::string cmd = quote(PEDTRACK_BIN);
  for (const auto& a : args) cmd += " " + quote(a);
  return runShell(cmd);
}

std::string evalRunJson(const std::string& dir, const std::vector<std::string>& extra) {
  std::vector<std::string> args{"eval",     "--truth",           dir + "/truth.csv",
                                "--tracks", dir + "/tracks.csv", "--json"};
  args.insert(args.end(), extra.begin(), extra.end());
  const auto e = runHost(args);
  INFO(e.output);
  REQUIRE(e.exit_code == 0);
  return e.output;
}

void pinToDeviceCpu() {
  const char* cpu = std::getenv("PEDTRACK_DEVICE_CPU");
  if (!cpu || !*cpu) return;
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(std::atoi(cpu), &set);
  pthread_setaffinity_np(pthread_self(), sizeof set, &set);
}

std::size_t liveFrames(std::size_t fallback) {
  const char* n = std::getenv("PEDTRACK_LIVE_FRAMES");
  return n && std::atol(n) > 0 ? std::size_t(std::atol(n)) : fallback;
}

std::string freshDir(const std::string& tag) {
  // PEDTRACK_TEST_WORK: a work root of its own, for copies of a test run side by side (the
  // repeated runs that look for a flaky test under load).
  const char* root = std::getenv("PEDTRACK_TEST_WORK");
  const fs::path d =
      (root && *root ? fs::path(root) : fs::path(PEDTRACK_BUILD_DIR) / "Testing" / "work") / tag;
  fs::remove_all(d);
  fs::create_directories(d);
  return d.string();
}

std::string sharedDataDir() {
  if (const char* env = std::getenv("PEDTRACK_DATA"); env && fs::is_directory(env)) return env;
  const fs::path d = fs::path(PEDTRACK_SOURCE_DIR).parent_path() / "shared" / "data";
  return fs::is_directory(d) ? d.string() : std::string();
}

std::string mrptDataset(const std::string& name) {
  return "/usr/share/mrpt/datasets/" + name;
}

std::string readFile(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

void writeFile(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream is(text);
  std::string l;
  while (std::getline(is, l))
    if (!l.empty()) out.push_back(l);
  return out;
}

double jsonValue(const std::string& json, const std::string& key) {
  const std::string k = "\"" + key + "\": ";
  for (auto p = json.find(k); p != std::string::npos; p = json.find(k, p + 1)) {
    const char c = json[p + k.size()];
    if (c == '-' || (c >= '0' && c <= '9')) return std::stod(json.substr(p + k.size()));
  }
  throw std::runtime_error("no number for " + key + " in " + json);
}

double jsonNumber(const std::string& json, const std::string& key) {
  const auto k = json.find("\"" + key + "\":");
  if (k == std::string::npos) throw std::runtime_error("run.json has no key " + key);
  return std::stod(json.substr(k + key.size() + 3));
}

}  // namespace pedtrack::test

namespace pedtrack::test {
void requireData(const std::string& path) {
  if (!path.empty() && fs::exists(path)) return;
  std::printf("SKIPPED: shared data not found: %s (set PEDTRACK_DATA or clone next to ../shared)\n",
              path.empty() ? "../shared/data" : path.c_str());
  std::fflush(stdout);
  std::exit(77);
}

std::string requiredDataFile(const std::string& relative) {
  const std::string data = sharedDataDir();
  const std::string path = data.empty() ? "" : data + "/" + relative;
  requireData(path);
  return path;
}

std::string requiredDataFileExported(const std::string& relative) {
  const std::string path = requiredDataFile(relative);
  setenv("PEDTRACK_DATA", sharedDataDir().c_str(), 1);
  return path;
}
}  // namespace pedtrack::test

namespace pedtrack::test {
const PluginRegistry& testRegistry() {
  static PluginRegistry r({PEDTRACK_TEST_PLUGIN_DIR});
  return r;
}

DrivenStages::DrivenStages(const std::string& pipeline_text, const std::string& file)
    : config(PipelineConfig::fromText(pipeline_text, file, {}, testRegistry())),
      pipeline(std::make_unique<Pipeline>(config)) {}

void DrivenStages::run(Frame& f) {
  for (Stage* s : pipeline->stages()) s->process(f);
}

std::vector<Frame> readAllFrames(const std::string& pipeline_text, const std::string& file) {
  const auto cfg = PipelineConfig::fromText(pipeline_text, file, {}, testRegistry());
  Pipeline p(cfg);
  std::vector<Frame> frames;
  Frame f;
  while (p.source().next(f)) frames.push_back(f), f = Frame();
  return frames;
}

std::string readFramesUntilError(const std::string& pipeline_text,
                                 const std::function<void(const Frame&)>& each) {
  try {
    const auto cfg = PipelineConfig::fromText(pipeline_text, "t.ini", {}, testRegistry());
    Pipeline p(cfg);
    Frame f;
    while (p.source().next(f)) each(f), f = Frame();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

std::map<std::string, std::vector<double>> readCsv(const std::string& path) {
  std::ifstream f(path);
  std::string line;
  std::getline(f, line);
  std::vector<std::string> names;
  std::stringstream h(line);
  for (std::string c; std::getline(h, c, ',');) names.push_back(c);
  std::map<std::string, std::vector<double>> cols;
  while (std::getline(f, line)) {
    std::stringstream s(line);
    std::string v;
    for (std::size_t i = 0; i < names.size() && std::getline(s, v, ','); ++i)
      cols[names[i]].push_back(v.empty() ? NAN : std::stod(v));
  }
  return cols;
}

}  // namespace pedtrack::test
