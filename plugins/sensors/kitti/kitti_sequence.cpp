#include "kitti_sequence.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pedtrack/errors.h"

namespace pedtrack::kitti {
namespace fs = std::filesystem;

namespace {

// The number a scan file is named by; nullopt when its stem is not all digits.
std::optional<long> indexOf(const fs::path& p) {
  const std::string stem = p.stem().string();
  if (stem.empty() || stem.size() > 18 ||
      !std::all_of(stem.begin(), stem.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::nullopt;
  return std::stol(stem);
}

// "2011-09-26 13:02:25.964389445" (UTC) as seconds since the epoch; nullopt when malformed.
std::optional<double> parseStamp(const std::string& line) {
  int Y, M, D, h, m;
  double s;
  char tail = 0;
  if (std::sscanf(line.c_str(), "%d-%d-%d %d:%d:%lf %c", &Y, &M, &D, &h, &m, &s, &tail) != 6)
    return std::nullopt;
  std::tm tm{};
  tm.tm_year = Y - 1900, tm.tm_mon = M - 1, tm.tm_mday = D, tm.tm_hour = h, tm.tm_min = m;
  return double(timegm(&tm)) + s;
}

}  // namespace

std::vector<Scan> listScans(const std::string& input, double rate) {
  std::vector<Scan> scans;
  const fs::path in(input);
  std::error_code ec;
  if (fs::is_directory(in, ec)) {
    for (const auto& e : fs::directory_iterator(in, ec))
      if (e.path().extension() == ".bin") scans.push_back({e.path().string(), 0, 0});
    if (ec) throw DataError(input + ": cannot list the folder (" + ec.message() + ")");
    if (scans.empty()) throw DataError(input + ": no .bin scans in the folder");
    std::sort(scans.begin(), scans.end(),
              [](const Scan& a, const Scan& b) { return a.path < b.path; });
  } else {
    scans.push_back({input, 0, 0});
  }
  for (auto& s : scans) {
    const auto i = indexOf(s.path);
    if (!i && scans.size() > 1)
      throw DataError(s.path + ": a sequence's scans are named by their number (000042.bin)");
    s.index = i.value_or(0);
    s.t = s.index / rate;
  }
  // KITTI raw: DRIVE/velodyne_points/{data/NNNNNNNNNN.bin, timestamps.txt}, a line per scan.
  const fs::path stamps =
      (fs::is_directory(in) ? in : in.parent_path()).parent_path() / "timestamps.txt";
  if (fs::is_regular_file(stamps, ec)) {
    std::ifstream f(stamps);
    std::vector<double> t;
    std::string line;
    while (std::getline(f, line)) {
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      const auto v = parseStamp(line);
      if (!v)
        throw DataError(stamps.string() + ": line " + std::to_string(t.size() + 1) +
                        ": expected a time like 2011-09-26 13:02:25.964389445");
      t.push_back(*v);
    }
    for (auto& s : scans) {
      if (s.index < 0 || std::size_t(s.index) >= t.size())
        throw DataError(stamps.string() + ": no time for scan " + s.path + " (" +
                        std::to_string(t.size()) + " lines)");
      s.t = t[std::size_t(s.index)];
    }
  }
  return scans;
}

mrpt::maps::CPointsMapXYZI::Ptr readScan(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw DataError(path + ": cannot open");
  f.seekg(0, std::ios::end);
  const std::streamoff bytes = f.tellg();
  f.seekg(0);
  if (bytes < 0 || bytes % 16)
    throw DataError(path + ": " + std::to_string(bytes) +
                    " bytes is not a whole number of points (4 float32 each: x y z reflectance)");
  std::vector<float> v(std::size_t(bytes) / 4);
  if (!f.read(reinterpret_cast<char*>(v.data()), bytes)) throw DataError(path + ": read failed");
  auto map = mrpt::maps::CPointsMapXYZI::Create();
  // Keep every return (MRPT's default insertion options thin close points).
  map->insertionOptions.minDistBetweenLaserPoints = 0;
  map->reserve(v.size() / 4);
  for (std::size_t i = 0; i + 3 < v.size(); i += 4) {
    // KITTI marks nothing invalid, but a damaged file must not feed NaN to the pipeline.
    if (!std::isfinite(v[i]) || !std::isfinite(v[i + 1]) || !std::isfinite(v[i + 2])) continue;
    map->insertPointFast(v[i], v[i + 1], v[i + 2]);
    map->setPointIntensity(map->size() - 1, std::isfinite(v[i + 3]) ? v[i + 3] : 0.f);
  }
  map->mark_as_modified();
  return map;
}

std::string findOxts(const std::string& input) {
  const fs::path in(input);
  std::error_code ec;
  const fs::path folder = fs::is_directory(in, ec) ? in : in.parent_path();
  // raw: DRIVE/velodyne_points/data -> DRIVE/oxts/data
  if (folder.filename() == "data" && folder.parent_path().filename() == "velodyne_points") {
    const fs::path o = folder.parent_path().parent_path() / "oxts" / "data";
    if (fs::is_directory(o, ec)) return o.string();
  }
  // tracking: ROOT/velodyne/SSSS -> ROOT/oxts/SSSS.txt
  if (folder.parent_path().filename() == "velodyne") {
    const fs::path o =
        folder.parent_path().parent_path() / "oxts" / (folder.filename().string() + ".txt");
    if (fs::is_regular_file(o, ec)) return o.string();
  }
  return "";
}

}  // namespace pedtrack::kitti
