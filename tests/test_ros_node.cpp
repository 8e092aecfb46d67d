// `pedtrack ros` against a real ROS1 graph: a roscore on a free loopback port, the leg_tracker
// demo bag (and bags of simulated LaserScans and VLP-16 PointCloud2s, which CI has without the
// shared data) played into it with `rosbag play`, and this test subscribed (roscpp) to what the
// node publishes. Every scan must come out as one PoseArray (plus a people cloud and a MarkerArray)
// stamped with the scan's time, in the configured frame, carrying the same tracks as
// `pedtrack run` of the same bag. Every child process is killed when the test ends, also on
// failure. ros::init runs once per process: ctest runs each case in a process of its own.
#include <fcntl.h>
#include <geometry_msgs/PoseArray.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/ros1bridge/laser_scan.h>
#include <mrpt/ros1bridge/point_cloud2.h>
#include <mrpt/ros1bridge/pose.h>
#include <nav_msgs/Odometry.h>
#include <netinet/in.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>
#include <visualization_msgs/MarkerArray.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include "pedtrack/frame.h"
#include "pedtrack/sim/simulator.h"
#include "test_support.h"

using namespace pedtrack::test;
using Clock = std::chrono::steady_clock;

namespace {

const std::string kConfigs = std::string(PEDTRACK_SOURCE_DIR) + "/configs/";
// 8x real time: the 126 s bag plays in about 16 s; the node keeps up with tens of ms to spare
// per scan, and the test's live queue absorbs bursts of a loaded machine.
const char* kRate = "8";
const char* kFrameId = "pedtrack_test_frame";

// A free TCP port on loopback for this test's own roscore (another may run on 11311).
int freePort() {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = 0;
  socklen_t len = sizeof a;
  const bool ok = ::bind(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0 &&
                  ::getsockname(s, reinterpret_cast<sockaddr*>(&a), &len) == 0;
  ::close(s);
  return ok ? ntohs(a.sin_port) : -1;
}

// A child process in its own process group (roscore starts rosmaster and rosout under it),
// output to `log`. Destruction ends the whole group: SIGINT, then SIGKILL after 5 s.
class Child {
 public:
  Child(const std::vector<std::string>& argv, const std::string& log) : log_(log) {
    pid_ = ::fork();
    if (pid_ == 0) {
      ::setpgid(0, 0);
      const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      ::dup2(fd, 1);
      ::dup2(fd, 2);
      std::vector<char*> args;
      for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
      args.push_back(nullptr);
      ::execvp(args[0], args.data());
      std::perror("execvp");
      ::_exit(127);
    }
    if (pid_ > 0) ::setpgid(pid_, pid_);  // also here: no race with a kill before the child's
  }
  ~Child() { stop(); }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  /// Waits up to `seconds` for the child to exit; its exit code, or -1 while it still runs.
  int wait(double seconds) {
    const auto end = Clock::now() + std::chrono::duration<double>(seconds);
    do {
      if (exited()) return code_;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    } while (Clock::now() < end);
    return exited() ? code_ : -1;
  }
  bool running() { return !exited(); }
  void stop() {
    if (pid_ <= 0) return;
    if (!exited()) {
      ::kill(-pid_, SIGINT);
      if (wait(5) < 0) ::kill(-pid_, SIGKILL);
      if (!exited()) {
        int st = 0;
        ::waitpid(pid_, &st, 0);
      }
    }
    ::kill(-pid_, SIGKILL);  // grandchildren that outlived their parent
    pid_ = -1;
  }
  std::string log() const { return readFile(log_); }

 private:
  bool exited() {
    if (done_) return true;
    int st = 0;
    if (::waitpid(pid_, &st, WNOHANG) != pid_) return false;
    done_ = true;
    code_ = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
    return true;
  }
  pid_t pid_ = -1;
  std::string log_;
  bool done_ = false;
  int code_ = -1;
};

// What this test receives, filled by roscpp's spinner thread.
struct Received {
  std::mutex m;
  std::vector<ros::Time> scans;
  std::vector<geometry_msgs::PoseArray> tracks;
  std::vector<sensor_msgs::PointCloud2> people;
  std::vector<visualization_msgs::MarkerArray> markers;
  std::size_t total() {
    std::lock_guard<std::mutex> lk(m);
    return scans.size() + tracks.size() + people.size() + markers.size();
  }
};

// One person of the people cloud.
struct Person {
  int id = 0;
  float x = 0, y = 0;
  std::uint8_t status = 0;
};
std::vector<Person> people(const sensor_msgs::PointCloud2& c) {
  std::map<std::string, std::uint32_t> at;
  for (const auto& f : c.fields) at[f.name] = f.offset;
  std::vector<Person> out;
  for (std::uint32_t i = 0; i < c.width; ++i) {
    const std::uint8_t* p = c.data.data() + i * c.point_step;
    Person q;
    std::memcpy(&q.id, p + at.at("id"), 4);
    std::memcpy(&q.x, p + at.at("x"), 4);
    std::memcpy(&q.y, p + at.at("y"), 4);
    q.status = p[at.at("status")];
    out.push_back(q);
  }
  return out;
}

// tracks.csv rows by frame time: id, x, y, status.
struct RefTrack {
  int id;
  double x, y;
  std::string status;
};
std::map<double, std::vector<RefTrack>> tracksByTime(const std::string& csv) {
  std::map<double, std::vector<RefTrack>> out;
  const auto rows = lines(csv);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    std::vector<std::string> f;
    std::stringstream ss(rows[i]);
    std::string cell;
    while (std::getline(ss, cell, ',')) f.push_back(cell);
    if (f.size() < 18) continue;
    out[std::stod(f[0])].push_back({std::stoi(f[2]), std::stod(f[3]), std::stod(f[4]), f[17]});
  }
  return out;
}

// The reference rows of the frame at time t (tracks.csv writes 1 µs; no rows: no tracks).
const std::vector<RefTrack>* refAt(const std::map<double, std::vector<RefTrack>>& ref, double t) {
  static const std::vector<RefTrack> none;
  auto it = ref.lower_bound(t - 2e-6);
  if (it != ref.end() && std::abs(it->first - t) <= 2e-6) return &it->second;
  return &none;
}

// What a run plays and expects: the bag's scans are on `topic` (PointCloud2 when `cloud`, else
// LaserScan), run through `pipeline`; `min_scans`: how many the bag has at least;
// `expect_following`: the pipeline follows the nearest person (leg_people's `follow`) and
// someone is followed.
struct NodeCase {
  std::string bag, tag, pipeline = "people_2d_legs.ini", topic = "/scan";
  std::size_t min_scans = 1;
  bool cloud = false, expect_following = false;
  bool poses = false;  // the topic carries a detector's PoseArray (source.detections = true)
  std::vector<std::string> sets;  // --set options given to both the run and the node
  bool odometry = false;          // robot poses come from /odom (the bag has no /tf)
};

// Plays the case's bag into a private ROS graph running `pedtrack ros` and checks every scan
// against `pedtrack run` of the same bag.
void checkNodeAgainstRun(const NodeCase& c) {
  const std::string& bag = c.bag;
  const std::vector<std::string> follow =
      c.expect_following ? std::vector<std::string>{"--set", "track.follow=nearest"}
                         : std::vector<std::string>{};
  const auto t0 = Clock::now();
  REQUIRE(runShell("command -v roscore && command -v rosbag").exit_code == 0);

  // The reference: the same pipeline replaying the bag.
  const std::string dir = freshDir(c.tag);
  // A pipeline by name is a shipped one; a path, the test's own.
  const std::string pipeline = c.pipeline[0] == '/' ? c.pipeline : kConfigs + c.pipeline;
  std::vector<std::string> ref_args{"run",   pipeline, "--input",    bag, "--topic",
                                    c.topic, "--out",  dir + "/ref", "-q"};
  ref_args.insert(ref_args.end(), follow.begin(), follow.end());
  ref_args.insert(ref_args.end(), c.sets.begin(), c.sets.end());
  const auto ref_run = runHost(ref_args);
  INFO(ref_run.output);
  REQUIRE(ref_run.exit_code == 0);
  const std::string ref_csv = readFile(dir + "/ref/tracks.csv");
  const auto ref = tracksByTime(ref_csv);
  const auto scans_in_bag =
      static_cast<std::size_t>(jsonNumber(readFile(dir + "/ref/run.json"), "frames_read"));
  REQUIRE(scans_in_bag >= c.min_scans);

  // A private ROS graph: its own master port, home and logs; loopback only.
  const int port = freePort();
  REQUIRE(port > 0);
  const std::string uri = "http://127.0.0.1:" + std::to_string(port);
  ::setenv("ROS_MASTER_URI", uri.c_str(), 1);
  ::setenv("ROS_IP", "127.0.0.1", 1);
  ::unsetenv("ROS_HOSTNAME");
  ::setenv("ROS_HOME", dir.c_str(), 1);
  ::setenv("ROS_LOG_DIR", (dir + "/log").c_str(), 1);
  Child roscore({"roscore", "-p", std::to_string(port)}, dir + "/roscore.log");
  ros::init(ros::M_string(), "pedtrack_ros_node_test", ros::init_options::NoSigintHandler);
  // Declared after roscore: shuts this node down while the master still answers.
  struct RosShutdown {
    ~RosShutdown() { ros::shutdown(); }
  } ros_shutdown;
  const auto master_deadline = Clock::now() + std::chrono::seconds(20);
  while (!ros::master::check() && Clock::now() < master_deadline && roscore.running())
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  INFO("roscore: " << roscore.log());
  REQUIRE(ros::master::check());

  Received got;
  ros::NodeHandle nh;
  const std::uint32_t q = 5000;  // this test must not drop what it counts
  auto on_scan = [&](const ros::Time& stamp) {
    std::lock_guard<std::mutex> lk(got.m);
    got.scans.push_back(stamp);
  };
  ros::Subscriber scan_sub =
      c.poses ? nh.subscribe<geometry_msgs::PoseArray>(
                    c.topic, q,
                    [&](const geometry_msgs::PoseArray::ConstPtr& m) { on_scan(m->header.stamp); })
      : c.cloud
          ? nh.subscribe<sensor_msgs::PointCloud2>(
                c.topic, q,
                [&](const sensor_msgs::PointCloud2::ConstPtr& m) { on_scan(m->header.stamp); })
          : nh.subscribe<sensor_msgs::LaserScan>(
                c.topic, q,
                [&](const sensor_msgs::LaserScan::ConstPtr& m) { on_scan(m->header.stamp); });
  auto tracks_sub = nh.subscribe<geometry_msgs::PoseArray>(
      "/pedtrack/tracks", q, [&](const geometry_msgs::PoseArray::ConstPtr& m) {
        std::lock_guard<std::mutex> lk(got.m);
        got.tracks.push_back(*m);
      });
  auto people_sub = nh.subscribe<sensor_msgs::PointCloud2>(
      "/pedtrack/people", q, [&](const sensor_msgs::PointCloud2::ConstPtr& m) {
        std::lock_guard<std::mutex> lk(got.m);
        got.people.push_back(*m);
      });
  auto markers_sub = nh.subscribe<visualization_msgs::MarkerArray>(
      "/pedtrack/markers", q, [&](const visualization_msgs::MarkerArray::ConstPtr& m) {
        std::lock_guard<std::mutex> lk(got.m);
        got.markers.push_back(*m);
      });
  ros::AsyncSpinner spinner(1);
  spinner.start();

  // The node ends by itself 4 s after the last scan (end_on_idle). Its queues (2000 messages,
  // 2000 frames) hold more than the whole bag, so that a loaded machine delays scans rather than
  // drops them: every scan must come out. (With 200 frames, 2.5 s of the bag at 8x, a CI machine
  // whose node ran slower than the bag filled the queue and dropped one.)
  std::vector<std::string> node_args{PEDTRACK_BIN,
                                     "ros",
                                     pipeline,
                                     "--topic",
                                     c.topic,
                                     "--set",
                                     "source.idle_timeout=4",
                                     "--set",
                                     "source.end_on_idle=true",
                                     "--set",
                                     std::string("publish.frame_id=") + kFrameId,
                                     "--set",
                                     "source.queue_size=2000",
                                     "--live-queue",
                                     "2000",
                                     "--out",
                                     dir + "/node",
                                     "-q"};
  node_args.insert(node_args.end(), follow.begin(), follow.end());
  node_args.insert(node_args.end(), c.sets.begin(), c.sets.end());
  if (c.poses) node_args.insert(node_args.end(), {"--set", "source.detections=true"});
  Child node(node_args, dir + "/node.log");
  // Its publishers appear once its source has subscribed (plugins are created in stage order),
  // and this test is connected to them before the first scan.
  const auto up_deadline = Clock::now() + std::chrono::seconds(30);
  while ((tracks_sub.getNumPublishers() == 0 || people_sub.getNumPublishers() == 0 ||
          markers_sub.getNumPublishers() == 0) &&
         Clock::now() < up_deadline && node.running())
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  INFO("node: " << node.log());
  REQUIRE(tracks_sub.getNumPublishers() == 1);
  REQUIRE(people_sub.getNumPublishers() == 1);
  REQUIRE(markers_sub.getNumPublishers() == 1);

  // -d 1: a second after advertising /scan for the node and this test to connect.
  Child play({"rosbag", "play", "-q", "-r", kRate, "-d", "1", bag}, dir + "/rosbag.log");
  const int play_code = play.wait(60);
  INFO("rosbag play: " << play.log());
  REQUIRE(play_code == 0);
  const int node_code = node.wait(30);
  INFO("node: " << node.log());
  REQUIRE(node_code == 0);
  // Messages still in this test's sockets: wait until nothing new arrives for half a second.
  std::size_t before = got.total();
  for (int i = 0; i < 50; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const std::size_t now = got.total();
    if (now == before && i >= 5) break;
    before = now;
  }
  spinner.stop();
  std::lock_guard<std::mutex> lk(got.m);

  // Every scan played reached this test and the node, and none was dropped on the way.
  const std::string run_json = readFile(dir + "/node/run.json");
  INFO("node run.json: " << run_json);
  CHECK(got.scans.size() == scans_in_bag);
  CHECK(jsonNumber(run_json, "frames_read") == scans_in_bag);
  CHECK(jsonNumber(run_json, "frames_dropped") == 0);
  CHECK(jsonNumber(run_json, "frames_processed") == scans_in_bag);
  CHECK(run_json.find("\"status\": \"ok\"") != std::string::npos);
  // Every scan placed by odometry: the robot moved in the fixed frame, no /tf said so.
  if (c.odometry) CHECK(jsonNumber(run_json, "odom_poses") == scans_in_bag);

  // One PoseArray, people cloud and MarkerArray per scan, stamped with the scan, in order.
  REQUIRE(got.tracks.size() == got.scans.size());
  REQUIRE(got.people.size() == got.scans.size());
  REQUIRE(got.markers.size() == got.scans.size());
  std::size_t stamps_equal = 0, tracks_equal = 0, following = 0, ref_following = 0;
  double worst_stamp = 0;
  for (std::size_t i = 0; i < got.scans.size(); ++i) {
    const auto& pa = got.tracks[i];
    const double dt = std::abs((pa.header.stamp - got.scans[i]).toSec());
    worst_stamp = std::max(worst_stamp, dt);
    // A stamp goes through frame time (double UNIX seconds): equal to well under 1 µs.
    if (dt <= 1e-6) ++stamps_equal;
    CHECK(pa.header.frame_id == kFrameId);
    CHECK(got.people[i].header.stamp == pa.header.stamp);
    CHECK(got.people[i].header.frame_id == kFrameId);
    CHECK(got.markers[i].markers.front().action == visualization_msgs::Marker::DELETEALL);

    // The same tracks as pedtrack run at that time: ids (people cloud), positions (PoseArray).
    const auto persons = people(got.people[i]);
    REQUIRE(persons.size() == pa.poses.size());
    const std::vector<RefTrack>& want = *refAt(ref, pa.header.stamp.toSec());
    bool same = want.size() == pa.poses.size();
    std::size_t id_markers = 0;
    for (const auto& m : got.markers[i].markers) id_markers += m.ns == "id";
    CHECK(id_markers == pa.poses.size());
    for (std::size_t k = 0; same && k < want.size(); ++k) {
      same = persons[k].id == want[k].id && std::abs(pa.poses[k].position.x - want[k].x) < 1e-3 &&
             std::abs(pa.poses[k].position.y - want[k].y) < 1e-3 &&
             std::abs(persons[k].x - want[k].x) < 1e-3 &&
             (persons[k].status == 3) == (want[k].status == "following");
    }
    for (const auto& p : persons) following += p.status == 3;
    for (const auto& w : want) ref_following += w.status == "following";
    tracks_equal += same;
  }
  const double secs = std::chrono::duration<double>(Clock::now() - t0).count();
  std::cout << "ros node: " << scans_in_bag << " scans in the bag, " << got.scans.size()
            << " played, " << got.tracks.size() << " PoseArrays received, " << stamps_equal
            << " with the scan's stamp (worst " << worst_stamp * 1e9 << " ns), " << tracks_equal
            << " with pedtrack run's tracks, " << following
            << " followed-person entries (run: " << ref_following << "), "
            << jsonNumber(run_json, "frames_dropped") << " frames dropped; " << secs << " s\n";
  CHECK(stamps_equal == got.scans.size());
  CHECK(tracks_equal == got.scans.size());
  CHECK(following == ref_following);
  if (c.expect_following) CHECK(following > 0);
  std::size_t poses = 0;
  for (const auto& pa : got.tracks) poses += pa.poses.size();
  CHECK(poses > got.scans.size() / 4);  // people were tracked, not only nothing compared
  // With no scan dropped the node's own tracks.csv is the replay's, byte for byte.
  CHECK(readFile(dir + "/node/tracks.csv") == ref_csv);
}

// A bag of simulated leg-height scans on /scan, written with rosbag: the node runs in CI, where
// the shared data is absent. `mounts` given: the robot's wheel odometry goes on /odom too
// (nav_msgs/Odometry, odom → base_link; no /tf at all) and `mounts` receives the source key that
// places the laser on the robot.
std::string writeSimulatedBag(const std::string& path, int scans, const std::string& scenario,
                              std::string* mounts = nullptr) {
  pedtrack::sim::Simulator sim(pedtrack::sim::loadScenario(kConfigs + "scenarios/" + scenario));
  sim.setPointTruth(false);
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  pedtrack::sim::SimFrame f;
  for (int i = 0; i < scans && sim.next(f); ++i) {
    const auto* scan =
        dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(f.observations.back().get());
    REQUIRE(scan != nullptr);
    sensor_msgs::LaserScan msg;
    REQUIRE(mrpt::ros1bridge::toROS(*scan, msg));
    msg.header.stamp = ros::Time(f.t);
    msg.header.frame_id = "laser";
    msg.header.seq = static_cast<std::uint32_t>(i);
    if (mounts) {
      nav_msgs::Odometry odom;
      odom.header.stamp = msg.header.stamp;
      odom.header.frame_id = "odom";
      odom.child_frame_id = "base_link";
      odom.pose.pose = mrpt::ros1bridge::toROS_Pose(f.robot_odometry);
      bag.write("/odom", odom.header.stamp, odom);
      if (i == 0) {
        const mrpt::poses::CPose3D m = f.sensor_true - f.robot_true;
        std::ostringstream o;
        o << "/scan: " << m.x() << " " << m.y() << " " << m.z() << " " << m.yaw() * 180 / M_PI;
        *mounts = o.str();
      }
    }
    bag.write("/scan", msg.header.stamp, msg);
  }
  bag.close();
  return path;
}

// A detector's output as a bag: two people walking past each other 4 m ahead of a scanner, as a
// geometry_msgs/PoseArray at 10 Hz in the laser's frame (no /tf: the laser is the fixed frame).
std::string writeDetectionsBag(const std::string& path, int messages) {
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  for (int i = 0; i < messages; ++i) {
    geometry_msgs::PoseArray a;
    a.header.stamp = ros::Time(1600000000.0 + 0.1 * i);
    a.header.frame_id = "laser";
    a.header.seq = static_cast<std::uint32_t>(i);
    for (double dir : {1.0, -1.0}) {
      geometry_msgs::Pose p;
      p.position.x = 4 + 0.5 * dir;
      p.position.y = dir * (-3 + 0.12 * i);
      p.orientation.w = 1;
      a.poses.push_back(p);
    }
    bag.write("/people", a.header.stamp, a);
  }
  bag.close();
  return path;
}

// A bag of simulated VLP-16 revolutions (crowd.ini: 20 walkers) as PointCloud2 messages, the
// points of each revolution in the sensor's frame.
std::string writeSimulatedCloudBag(const std::string& path, int revolutions) {
  pedtrack::sim::Simulator sim(pedtrack::sim::loadScenario(kConfigs + "scenarios/crowd.ini"));
  sim.setPointTruth(false);
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  pedtrack::sim::SimFrame f;
  for (int i = 0; i < revolutions && sim.next(f); ++i) {
    pedtrack::Frame frame;
    frame.observations.push_back(f.observations.back());
    std_msgs::Header header;
    header.stamp = ros::Time(f.t);
    header.frame_id = "velodyne";
    header.seq = static_cast<std::uint32_t>(i);
    sensor_msgs::PointCloud2 msg;
    REQUIRE(mrpt::ros1bridge::toROS(frame.cloud(), header, msg));
    bag.write("/velodyne_points", header.stamp, msg);
  }
  bag.close();
  return path;
}

}  // namespace

TEST_CASE("pedtrack ros publishes the tracks of every scan played from a bag, as pedtrack run") {
  const std::string data = sharedDataDir();
  const std::string bag =
      data.empty() ? "" : data + "/leg_tracker/demo_stationary_simple_environment.bag";
  requireData(bag);
  NodeCase c;
  c.bag = bag;
  c.tag = "ros_node";
  c.min_scans = 1000;
  c.expect_following = true;
  checkNodeAgainstRun(c);
}

TEST_CASE("pedtrack ros publishes the tracks of every simulated scan, as pedtrack run") {
  NodeCase c;
  // legs_standing_60s: a person walks in and stands, another passes.
  c.bag =
      writeSimulatedBag(freshDir("ros_node_sim_bag") + "/legs.bag", 200, "legs_standing_60s.ini");
  c.tag = "ros_node_sim";
  c.min_scans = 200;
  // Nobody is in the follow zone in front of the scanner here: following is not checked.
  checkNodeAgainstRun(c);
}

TEST_CASE("pedtrack ros places a robot without /tf by its /odom odometry, as pedtrack run") {
  NodeCase c;
  std::string mounts;
  // legs_crowd_10_moving: the robot drives through a crowd; it publishes no /tf.
  c.bag = writeSimulatedBag(freshDir("ros_node_odom_bag") + "/odom.bag", 200,
                            "legs_crowd_10_moving.ini", &mounts);
  c.tag = "ros_node_odom";
  c.min_scans = 200;
  c.sets = {"--set", "source.mounts=" + mounts};
  c.odometry = true;
  checkNodeAgainstRun(c);
}

TEST_CASE("pedtrack ros tracks a detector's PoseArray topic, as pedtrack run") {
  NodeCase c;
  const std::string dir = freshDir("ros_node_poses_bag");
  c.bag = writeDetectionsBag(dir + "/people.bag", 60);
  c.tag = "ros_node_poses";
  c.pipeline = dir + "/track.ini";
  writeFile(c.pipeline,
            "[pipeline]\nstages = source track\n[source]\nplugin = rosbag\nfile = people.bag\n"
            "topic = /people\n[track]\nplugin = kf_hungarian\n");
  c.topic = "/people";
  c.poses = true;
  c.min_scans = 60;
  checkNodeAgainstRun(c);
}

TEST_CASE("pedtrack ros tracks PointCloud2 revolutions of a simulated VLP-16, as pedtrack run") {
  NodeCase c;
  c.bag = writeSimulatedCloudBag(freshDir("ros_node_cloud_bag") + "/vlp16.bag", 40);
  c.tag = "ros_node_cloud";
  c.pipeline = "people_3d_vlp16.ini";
  c.topic = "/velodyne_points";
  c.cloud = true;
  c.min_scans = 40;
  checkNodeAgainstRun(c);
}
