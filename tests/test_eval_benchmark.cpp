// `pedtrack eval --truth BAG` on bags of the leg_tracker benchmark (ICRA 2015): people annotated
// as leg_tracker/Person messages right after the scan they annotate, read from the bag's own
// message definition, scored by the benchmark's clear_mot.py rules (a small bag whose score is
// computed by hand below), in following mode, within a bearing window, and pooled over bags.
// Also the definition-driven decoder on its own.
#include <geometry_msgs/Pose.h>
#include <ros/message_traits.h>
#include <ros/serialization.h>
#include <rosbag/bag.h>
#include <sensor_msgs/LaserScan.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "ros_message_decode.h"
#include "test_support.h"

// leg_tracker's Person message, as the benchmark's bags define it (no header: order ties it to
// its scan).
namespace leg_tracker {
struct Person {
  geometry_msgs::Pose pose;
  std::uint32_t id = 0;
};
}  // namespace leg_tracker

namespace ros::message_traits {
template <>
struct MD5Sum<leg_tracker::Person> {
  static const char* value() { return "a9d14a3d9e1d2e8f5a1a2b3c4d5e6f70"; }
  static const char* value(const leg_tracker::Person&) { return value(); }
};
template <>
struct DataType<leg_tracker::Person> {
  static const char* value() { return "leg_tracker/Person"; }
  static const char* value(const leg_tracker::Person&) { return value(); }
};
template <>
struct Definition<leg_tracker::Person> {
  static const char* value() {
    return "# Pose of a person\ngeometry_msgs/Pose pose\nuint32 id\n"
           "================================================================================\n"
           "MSG: geometry_msgs/Pose\nPoint position\nQuaternion orientation\n"
           "================================================================================\n"
           "MSG: geometry_msgs/Point\nfloat64 x\nfloat64 y\nfloat64 z\n"
           "================================================================================\n"
           "MSG: geometry_msgs/Quaternion\nfloat64 x\nfloat64 y\nfloat64 z\nfloat64 w\n";
  }
  static const char* value(const leg_tracker::Person&) { return value(); }
};
}  // namespace ros::message_traits

namespace ros::serialization {
template <>
struct Serializer<leg_tracker::Person> {
  template <typename Stream, typename T>
  inline static void allInOne(Stream& stream, T m) {
    stream.next(m.pose);
    stream.next(m.id);
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};
}  // namespace ros::serialization

using namespace pedtrack::test;

namespace {

constexpr double kT0 = 1700000000;

struct Annotated {
  long id;
  double x, y;
};

// A bag of four scans (t0 + 1 ... t0 + 4), each followed by its annotations, then `tail` scans
// nobody annotated (the annotation stopped).
std::string writeBenchmarkBag(const std::string& dir, int tail = 0) {
  std::vector<std::vector<Annotated>> people = {{{7, 1.0, 0}, {8, 3.0, 0}},
                                                {{7, 1.1, 0}, {8, 3.0, 0}},
                                                {{7, 1.2, 0}},
                                                {{7, 1.3, 0}, {8, 3.0, 0.1}}};
  people.resize(people.size() + std::size_t(tail));
  const std::string path = dir + "/bench.bag";
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  for (std::size_t k = 0; k < people.size(); ++k) {
    sensor_msgs::LaserScan scan;
    scan.header.stamp = ros::Time(kT0 + double(k + 1));
    scan.header.frame_id = "base_laser_link";
    scan.angle_min = -1, scan.angle_max = 1, scan.angle_increment = 1;
    scan.range_min = 0.1, scan.range_max = 10;
    scan.ranges = {5, 5, 5};
    bag.write("/scan", scan.header.stamp, scan);
    for (const Annotated& a : people[k]) {
      leg_tracker::Person p;
      p.pose.position.x = a.x;
      p.pose.position.y = a.y;
      p.pose.orientation.w = 1;
      p.id = std::uint32_t(a.id);
      bag.write("/ground_truth_people_tracks", scan.header.stamp + ros::Duration(0.001), p);
    }
  }
  bag.close();
  return path;
}

// The tracks, laser frame: scan 1 matches both people (0.05 and 0.1 m) with one track on no one;
// scan 2 loses person 8; scan 3 gives person 7 to track 2, last matched to person 8 (an ID
// switch; the script's memory is one to one, so the pairs 1-7 and 2-8 are forgotten); scan 4
// gives person 7 to track 1, while 7 was last matched to track 2 (one more switch), and person 8
// to track 3, neither remembering anyone (no switch).
// `tail`: also track 1 in scan 5 (after the annotation stopped).
std::string writeTracks(const std::string& dir, bool tail = false) {
  const std::string path = dir + "/tracks.csv";
  std::string csv = "t,frame,track,x,y,sensor_x,sensor_y\n";
  auto row = [&](int scan, int track, double x, double y) {
    char line[200];
    std::snprintf(line, sizeof line, "%.6f,%d,%d,%g,%g,%g,%g\n", kT0 + scan, scan - 1, track, x, y,
                  x, y);
    csv += line;
  };
  row(1, 1, 1.05, 0), row(1, 2, 3.1, 0), row(1, 3, 5, 5);
  row(2, 1, 1.1, 0.2);
  row(3, 2, 1.2, 0.1);
  row(4, 1, 1.3, 0), row(4, 3, 3, 0.1);
  if (tail) row(5, 1, 1.4, 0);
  writeFile(path, csv);
  return path;
}

}  // namespace

TEST_CASE("a benchmark bag is scored by clear_mot.py's rules, computed by hand",
          "[eval_cli][benchmark]") {
  const std::string dir = freshDir("eval_benchmark");
  const std::string bag = writeBenchmarkBag(dir), tracks = writeTracks(dir);
  // 7 truths; 6 matches (0.05 + 0.1 + 0.2 + 0.1 + 0 + 0 = 0.45 m); 1 miss (scan 2, person 8);
  // 1 false positive (scan 1, track 3); 2 ID switches. MOTA = 1 - 4/7, MOTP = 0.075 m.
  const auto r = runHost({"eval", "--truth", bag, "--tracks", tracks, "--json"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(jsonNumber(r.output, "truths") == 7);
  CHECK(jsonNumber(r.output, "misses") == 1);
  CHECK(jsonNumber(r.output, "false_positives") == 1);
  CHECK(jsonNumber(r.output, "id_switches") == 2);
  CHECK(jsonNumber(r.output, "mota") == Approx(3.0 / 7));
  CHECK(jsonNumber(r.output, "motp_m") == Approx(0.075));
  CHECK(jsonNumber(r.output, "scans") == 4);
  CHECK(jsonNumber(r.output, "non_target_tracks_per_scan") == Approx(0.25));
  // Following: the annotated people are the followed one; false positives are not counted.
  const auto f = runHost({"eval", "--truth", bag, "--tracks", tracks, "--following", "--json"});
  INFO(f.output);
  REQUIRE(f.exit_code == 0);
  CHECK(jsonNumber(f.output, "mota") == Approx(4.0 / 7));
  CHECK(jsonNumber(f.output, "non_target_tracks_per_scan") == Approx(0.25));
  // Bearings -80..12 deg drop track 3 (45 deg): no false positive left.
  const auto w =
      runHost({"eval", "--truth", bag, "--tracks", tracks, "--angles", "-80,12", "--json"});
  INFO(w.output);
  REQUIRE(w.exit_code == 0);
  CHECK(jsonNumber(w.output, "false_positives") == 0);
  CHECK(jsonNumber(w.output, "mota") == Approx(4.0 / 7));
  // Two bags pooled: every count doubles, the ratios stay.
  const auto p = runHost(
      {"eval", "--truth", bag, "--tracks", tracks, "--truth", bag, "--tracks", tracks, "--json"});
  INFO(p.output);
  REQUIRE(p.exit_code == 0);
  CHECK(jsonNumber(p.output, "truths") == 14);
  CHECK(jsonNumber(p.output, "id_switches") == 4);
  CHECK(jsonNumber(p.output, "mota") == Approx(3.0 / 7));
  // Bad input: one line, exit 2.
  const auto bad = runHost({"eval", "--truth", bag, "--tracks", tracks, "--angles", "12"});
  CHECK(bad.exit_code == 2);
  CHECK(lines(bad.output).size() == 1);
}

TEST_CASE("after a bag's last annotation no track is judged target or not",
          "[eval_cli][benchmark]") {
  // The bag above with two more scans nobody annotated, and track 1 still there in the first:
  // a track on no annotated person per scan counts it (2 rows in 6 scans); up to the last
  // annotated scan it does not (1 row, track 3 in scan 1, in 4 scans).
  const std::string dir = freshDir("eval_benchmark_tail");
  const std::string bag = writeBenchmarkBag(dir, 2), tracks = writeTracks(dir, true);
  const auto r = runHost({"eval", "--truth", bag, "--tracks", tracks, "--following", "--json"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(jsonNumber(r.output, "scans") == 6);
  CHECK(jsonNumber(r.output, "non_target_track_rows") == 2);
  CHECK(jsonNumber(r.output, "non_target_tracks_per_scan") == Approx(2.0 / 6));
  CHECK(jsonNumber(r.output, "annotated_scans") == 4);
  CHECK(jsonNumber(r.output, "non_target_track_rows_annotated") == 1);
  CHECK(jsonNumber(r.output, "non_target_tracks_per_annotated_scan") == Approx(0.25));
  CHECK(jsonNumber(r.output, "mota") == Approx(4.0 / 7));  // the score itself is unchanged
}

TEST_CASE("a message is read from its own definition", "[eval_cli][benchmark]") {
  using pedtrack::cli::RosMessageSchema;
  leg_tracker::Person p;
  p.pose.position.x = 1.5;
  p.pose.position.y = -2.25;
  p.id = 42;
  std::vector<std::uint8_t> bytes(ros::serialization::serializationLength(p));
  ros::serialization::OStream os(bytes.data(), std::uint32_t(bytes.size()));
  ros::serialization::serialize(os, p);
  const RosMessageSchema schema("leg_tracker/Person",
                                ros::message_traits::Definition<leg_tracker::Person>::value());
  const auto f = schema.numbers(bytes.data(), bytes.size());
  CHECK(f.at("pose.position.x") == 1.5);
  CHECK(f.at("pose.position.y") == -2.25);
  CHECK(f.at("id") == 42);
  CHECK(f.at("pose.orientation.w") == 0);
  // Cut short, or a type the definition does not define: DataError naming it.
  CHECK_THROWS_WITH(schema.numbers(bytes.data(), bytes.size() - 2),
                    Catch::Contains("the message ends inside id"));
  CHECK_THROWS_WITH(RosMessageSchema("a/B", "Thing t\n"), Catch::Contains("a/Thing"));
  // Arrays with a count, strings, a Header.
  const RosMessageSchema arrays("a/C",
                                "Header header\nstring name\nfloat32[] v\nint16[2] w\n"
                                "====\nMSG: std_msgs/Header\nuint32 seq\ntime stamp\n"
                                "string frame_id\n");
  const std::vector<std::uint8_t> raw = {
      1, 0, 0,    0,   2,   0,   0,    0,    0,
      0, 0, 0,    1,   0,   0,   0,    'f',   // header: seq 1, stamp 2 s, "f"
      2, 0, 0,    0,   'a', 'b',              // name "ab"
      1, 0, 0,    0,   0,   0,   0x80, 0x3f,  // v = {1.0f}
      3, 0, 0xfd, 0xff};                      // w = {3, -3}
  const auto g = arrays.numbers(raw.data(), raw.size());
  CHECK(g.at("header.seq") == 1);
  CHECK(g.at("header.stamp") == 2);
  CHECK(g.at("v[0]") == 1);
  CHECK(g.at("w[1]") == -3);
  const std::vector<std::uint8_t> huge = {1, 0, 0, 0, 2, 0, 0, 0, 0,    0,    0,    0,
                                          0, 0, 0, 0, 0, 0, 0, 0, 0xff, 0xff, 0xff, 0x7f};
  CHECK_THROWS_WITH(arrays.numbers(huge.data(), huge.size()), Catch::Contains("does not fit"));
}
