// The rosbag source on the real leg_tracker bag, and `pedtrack import` of it to a rawlog.
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/LaserScan.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <iostream>

#include "pedtrack/pipeline.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;

namespace {

std::string demoBag() {
  const std::string data = sharedDataDir();
  const std::string bag =
      data.empty() ? "" : data + "/leg_tracker/demo_stationary_simple_environment.bag";
  requireData(bag);
  return bag;
}

std::vector<Frame> replay(const std::string& plugin, const std::string& file,
                          const std::string& extra = "") {
  return readAllFrames("[pipeline]\nstages = source\n[source]\nplugin = " + plugin +
                       "\nfile = " + file + "\n" + extra);
}

// The bag's own LaserScan messages, read with rosbag_storage alone.
std::vector<sensor_msgs::LaserScan> bagScans(const std::string& file) {
  rosbag::Bag bag(file, rosbag::bagmode::Read);
  rosbag::View view(bag, rosbag::TopicQuery("/scan"));
  std::vector<sensor_msgs::LaserScan> scans;
  for (const auto& m : view)
    if (auto s = m.instantiate<sensor_msgs::LaserScan>()) scans.push_back(*s);
  return scans;
}

void checkSameRanges(const std::vector<Frame>& frames,
                     const std::vector<sensor_msgs::LaserScan>& scans) {
  REQUIRE(frames.size() == scans.size());
  std::size_t compared = 0, mismatched = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    REQUIRE(frames[i].observations.size() == 1);
    const auto* o =
        dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(frames[i].observations[0].get());
    REQUIRE(o != nullptr);
    const auto& s = scans[i];
    REQUIRE(o->getScanSize() == s.ranges.size());
    CHECK(frames[i].t == Approx(s.header.stamp.toSec()).margin(1e-6));
    for (std::size_t k = 0; k < s.ranges.size(); ++k) {
      const float r = s.ranges[k];
      const bool valid = std::isfinite(r) && r >= s.range_min && r <= s.range_max;
      if (valid) {
        ++compared;
        if (!o->getScanRangeValidity(k) || o->getScanRange(k) != r) {
          ++mismatched;
          std::cerr << "scan " << i << " beam " << k << ": bag " << r << " [" << s.range_min << ", "
                    << s.range_max << "], mrpt " << o->getScanRange(k) << " valid "
                    << o->getScanRangeValidity(k) << "\n";
        }
      }
    }
  }
  CHECK(compared > 100000);
  CHECK(mismatched == 0);
}

}  // namespace

TEST_CASE("the leg_tracker demo bag replays as 1265 frames whose ranges equal the bag's",
          "[rosbag]") {
  const std::string bag = demoBag();
  const auto scans = bagScans(bag);
  CHECK(scans.size() == 1265);
  checkSameRanges(replay("rosbag", bag, "topic = /scan\n"), scans);
}

TEST_CASE("a bag topic that does not exist is named with a suggestion", "[rosbag]") {
  const std::string bag = demoBag();
  CHECK_THROWS_WITH(replay("rosbag", bag, "topic = /scn\n"),
                    Catch::Contains("[source] topic: '/scn' is not in bag") &&
                        Catch::Contains("did you mean '/scan'?"));
}

TEST_CASE("pedtrack import writes the bag as a rawlog that rawlog-edit and the rawlog source read",
          "[rosbag]") {
  const std::string bag = demoBag();
  const std::string out = freshDir("rosbag_import") + "/demo.rawlog";
  const auto r = runHost({"import", bag, "--out", out, "--topic", "/scan", "-q"});
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("wrote 1265 observations"));
  const auto info = runShell("rawlog-edit --info -i '" + out + "'");
  CHECK(info.exit_code == 0);
  CHECK_THAT(
      info.output,
      Catch::Matches("(.|\n)*Sensor \\(Label/Occurs/Rate/Durat\\.\\) : +/scan / +1265 /(.|\n)*"));
  checkSameRanges(replay("rawlog", out), bagScans(bag));
}
