#include "pedtrack/kitti_tracking_file.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>

#include "pedtrack/errors.h"
#include "pedtrack/text.h"

namespace pedtrack {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::vector<KittiTrackRow> readKittiTrackFile(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw DataError(path + ": cannot open");
  std::vector<KittiTrackRow> out;
  std::string line;
  for (long n = 1; std::getline(f, line); ++n) {
    const std::vector<std::string> v = splitList(line);
    if (v.empty()) continue;
    const std::string where = path + ": line " + std::to_string(n);
    if (v.size() != 17 && v.size() != 18)
      throw DataError(where +
                      ": expected 17 or 18 values (frame track_id type truncated occluded "
                      "alpha x1 y1 x2 y2 h w l x y z rotation_y [score]), got " +
                      std::to_string(v.size()));
    std::vector<double> d(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (i == 2) continue;
      char* end = nullptr;
      d[i] = std::strtod(v[i].c_str(), &end);
      if (end == v[i].c_str() || *end || !std::isfinite(d[i]))
        throw DataError(where + ": value " + std::to_string(i + 1) + " '" + v[i] +
                        "' is not a number");
    }
    if (d[0] < 0 || d[0] > 1e6 || d[0] != std::floor(d[0]))
      throw DataError(where + ": frame '" + v[0] + "' is not a frame number (0 ... 1,000,000)");
    if (d[1] < -1 || d[1] > 1e12 || d[1] != std::floor(d[1]))
      throw DataError(where + ": track id '" + v[1] + "' is not an id (-1 or a whole number)");
    // KITTI: truncated 0-2 (tracking) or 0-1 (objects), occluded 0-3; DontCare -1.
    for (std::size_t k : {std::size_t(3), std::size_t(4)})
      if (d[k] < -1 || d[k] > 3)
        throw DataError(where + ": " + (k == 3 ? "truncated" : "occluded") + " '" + v[k] +
                        "' is out of KITTI's range (-1 ... 3)");
    KittiTrackRow r;
    r.frame = long(d[0]), r.id = long(d[1]), r.type = lower(v[2]);
    r.truncated = int(d[3]), r.occluded = int(d[4]);
    r.x1 = d[6], r.y1 = d[7], r.x2 = d[8], r.y2 = d[9];
    r.box = {d[10], d[11], d[12], d[13], d[14], d[15], d[16]};
    if (v.size() == 18) r.score = d[17], r.has_score = true;
    out.push_back(r);
  }
  return out;
}

}  // namespace pedtrack
