// The segmentation plugins on hand-made frames, driven through a pipeline's stages as a run
// drives them: what each labels, the clusters it makes, and bad points that must not stop it.
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "pedtrack/pipeline.h"
#include "pedtrack/seg/cluster_features.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;

namespace {

const std::string kSena = mrptDataset("2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog");

// A pipeline of `stages` after a rawlog source the test never reads.
struct Stages : DrivenStages {
  Stages(const std::string& stages, const std::string& sections)
      : DrivenStages("[pipeline]\nstages = source " + stages +
                     "\n[source]\nplugin = rawlog\nfile = " + kSena + "\n" + sections) {}
};

Frame cloudFrame(const std::vector<std::array<float, 3>>& pts) {
  auto obs = mrpt::obs::CObservationPointCloud::Create();
  auto map = mrpt::maps::CSimplePointsMap::Create();
  for (const auto& p : pts) map->insertPointFast(p[0], p[1], p[2]);
  obs->pointcloud = map;
  Frame f;
  f.observations.push_back(obs);
  return f;
}

}  // namespace

TEST_CASE("height_band keeps a height band and a sector of ranges", "[plugins][band]") {
  Stages s("band",
           "[band]\nplugin = height_band\nmin_height = 0.6\nmax_height = 2.0\nmin_range = 1\n"
           "max_range = 10\nfov = 180\nheading = 0\n");
  // No ground stage: heights are robot-frame z. Ahead (+x) unless said otherwise.
  Frame f = cloudFrame({{3, 0, 1.0},      // kept
                        {3, 0, 0.3},      // too low (legs)
                        {3, 0, 2.5},      // too high
                        {0.5, 0, 1.0},    // too near
                        {12, 0, 1.0},     // too far
                        {-3, 0.1, 1.0},   // behind: outside the 180° sector
                        {0.2, 3, 1.0}});  // at 86° left: inside
  REQUIRE(f.cloud().size() == 7);
  s.run(f);
  std::vector<PointLabel> want(7, PointLabel::Removed);
  want[0] = want[6] = PointLabel::Kept;
  CHECK(f.point_labels == want);
}

TEST_CASE("height_band removes the robot's footprint", "[plugins][band]") {
  Stages s("band",
           "[band]\nplugin = height_band\nmin_height = -10\nmax_height = 10\n"
           "footprint = -0.3 1.0 -0.36 0.36\n");
  Frame f = cloudFrame({{0.9, 0.1, 0.2},    // the user's feet between the front scanners
                        {-0.2, -0.3, 0.2},  // the chair's frame
                        {1.1, 0.1, 0.2},    // just ahead of the footprint: kept
                        {0.2, 0.5, 0.2}});  // beside it: kept
  s.run(f);
  CHECK(f.point_labels == std::vector<PointLabel>{PointLabel::Removed, PointLabel::Removed,
                                                  PointLabel::Kept, PointLabel::Kept});
  CHECK_THROWS_WITH(Stages("band", "[band]\nplugin = height_band\nfootprint = 1 0 0 1\n"),
                    Catch::Contains("footprint"));
}

TEST_CASE("irls_ground then voxel_ccl: ground labelled, two people, P2 features", "[plugins]") {
  Stages s("ground clusters",
           "[ground]\nplugin = irls_ground\n[clusters]\nplugin = voxel_ccl\nvoxel = 0.15\n"
           "voxel_height = 1.0\nmin_points = 5\n");
  std::vector<std::array<float, 3>> pts;
  for (int i = -40; i <= 40; ++i)  // ground, 10 cm grid out to 4 m
    for (int j = -40; j <= 40; ++j) pts.push_back({0.1f * i, 0.1f * j, 0.0f});
  const std::size_t ground = pts.size();
  for (float cx : {2.0f, -2.0f})  // two 1.7 m "people": a column of points every 5 cm
    for (int k = 2; k <= 34; ++k)
      for (float dy : {-0.1f, 0.0f, 0.1f}) pts.push_back({cx, dy + 1.0f, 0.05f * k});
  Frame f = cloudFrame(pts);
  s.run(f);
  REQUIRE(f.ground.valid);
  CHECK(f.ground.nz == Approx(1).margin(1e-6));
  CHECK(f.ground.d == Approx(0).margin(0.01));
  for (std::size_t i = 0; i < ground; ++i) REQUIRE(f.point_labels[i] == PointLabel::Ground);
  REQUIRE(f.clusters.size() == 2);
  REQUIRE(f.cluster_feature_names);
  // P2's six first (the shipped P2 models read them by name), then the shape features.
  REQUIRE(f.cluster_feature_names->size() == 6 + seg::shapeFeatureNames().size());
  CHECK(std::vector<std::string>(f.cluster_feature_names->begin(),
                                 f.cluster_feature_names->begin() + 6) ==
        std::vector<std::string>{"h", "w", "d", "v", "lambda", "rho"});
  CHECK(f.clusterFeatureIndex("head") == int(f.cluster_feature_names->size()) - 1);
  CHECK(f.clusterFeatureIndex("h") == 0);
  CHECK(f.clusterFeatureIndex("rho") == 5);
  CHECK(f.clusterFeatureIndex("width") == -1);
  CHECK(Frame().clusterFeatureIndex("h") == -1);  // clusters without features
  for (const Cluster& c : f.clusters) {
    CHECK(c.indices.size() == 33 * 3);  // rows at 0.10 ... 1.70 m, all above the 5 cm band
    CHECK(std::abs(c.cx) == Approx(2.0).margin(1e-5));
    CHECK(c.cy == Approx(1.0).margin(1e-5));
    CHECK(c.size_z == Approx(1.7 - 0.1).margin(1e-5));
    CHECK(c.features[0] == Approx(1.7).margin(1e-5));  // h
    CHECK(c.features[4] == Approx(0.5).margin(0.05));  // λ: half the column above h/2
  }
}

TEST_CASE("bad points do not stop the segmenters: NaN and far points are removed", "[plugins]") {
  Stages s("ground clusters", "[ground]\nplugin = irls_ground\n[clusters]\nplugin = voxel_ccl\n");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<std::array<float, 3>> pts = {
      {nan, 0, 1}, {1, nan, 1}, {1, 1, nan}, {1e30f, 0, 1}, {3, 0, 1.0}};
  for (int i = 0; i < 10; ++i) pts.push_back({3, 0.02f * i, 1.0f});
  Frame f = cloudFrame(pts);
  REQUIRE(f.cloud().size() == pts.size());  // MRPT keeps the bad points in the cloud
  REQUIRE_NOTHROW(s.run(f));
  REQUIRE(f.point_labels.size() == pts.size());
  for (std::size_t i = 0; i < 4; ++i) CHECK(f.point_labels[i] != PointLabel::Kept);
  CHECK(f.clusters.size() == 1);
  // An empty frame too.
  Frame empty = cloudFrame({});
  REQUIRE_NOTHROW(s.run(empty));
  CHECK(empty.clusters.empty());
}

TEST_CASE("scan_segments then leg_circles: two legs found and paired", "[plugins][legs]") {
  Stages s("segments legs", "[segments]\nplugin = scan_segments\n[legs]\nplugin = leg_circles\n");
  // A 0.25° scan with two 5 cm legs 2 m ahead, 0.3 m apart, and a wall at 4 m.
  auto scan = mrpt::obs::CObservation2DRangeScan::Create();
  const int n = 241;
  scan->aperture = float(60 * M_PI / 180);
  scan->rightToLeft = true;
  scan->maxRange = 30;
  scan->resizeScan(n);
  for (int i = 0; i < n; ++i) {
    const double a = -scan->aperture / 2 + scan->aperture * i / (n - 1);
    const double c = std::cos(a), s2 = std::sin(a);
    double r = 4.0 / c;                // the wall x = 4
    for (double ly : {-0.15, 0.15}) {  // ray-circle intersection with each leg
      const double b = c * 2.0 + s2 * ly, disc = b * b - (4.0 + ly * ly - 0.0025);
      if (disc >= 0 && b - std::sqrt(disc) > 0) r = std::min(r, b - std::sqrt(disc));
    }
    scan->setScanRange(i, float(r));
    scan->setScanRangeValidity(i, true);
  }
  Frame f;
  f.observations.push_back(scan);
  s.run(f);
  REQUIRE(f.clusters.size() == 2);
  for (std::size_t k = 0; k < 2; ++k) {
    CHECK(f.clusters[k].cx == Approx(2.0).margin(0.005));
    CHECK(std::abs(f.clusters[k].cy) == Approx(0.15).margin(0.005));
    CHECK(f.clusters[k].pair == int(1 - k));
    CHECK(f.clusters[k].features.back() < 0.005);  // leg_residual
  }
  CHECK(f.cluster_feature_names->back() == "leg_residual");
}

namespace {

// A 0.25° scan over 180° from a scanner mounted at `mount` on the robot: a 5 cm leg at (2, 0.1)
// and a wall at x = 4, robot frame.
mrpt::obs::CObservation2DRangeScan::Ptr scanFrom(const mrpt::poses::CPose3D& mount,
                                                 const std::string& label) {
  auto scan = mrpt::obs::CObservation2DRangeScan::Create();
  const int n = 721;
  scan->aperture = float(M_PI);
  scan->rightToLeft = true;
  scan->maxRange = 30;
  scan->sensorPose = mount;
  scan->sensorLabel = label;
  scan->resizeScan(n);
  const double lx = 2.0 - mount.x(), ly = 0.1 - mount.y();  // the leg, from the scanner
  for (int i = 0; i < n; ++i) {
    const double a = mount.yaw() - scan->aperture / 2 + scan->aperture * i / (n - 1);
    const double c = std::cos(a), s = std::sin(a);
    double r = c > 1e-6 ? (4.0 - mount.x()) / c : 1e9;
    const double b = c * lx + s * ly, disc = b * b - (lx * lx + ly * ly - 0.0025);
    if (disc >= 0 && b - std::sqrt(disc) > 0) r = std::min(r, b - std::sqrt(disc));
    scan->setScanRange(i, float(std::min(r, 40.0)));
    scan->setScanRangeValidity(i, r < scan->maxRange);
  }
  return scan;
}

}  // namespace

TEST_CASE("merging two scanners puts a shared leg at one place", "[plugins][legs]") {
  // Front-left and front-right scanners of a wheelchair, one sensory frame in a rawlog.
  const mrpt::poses::CPose3D left(0.8, 0.25, 0.18, M_PI / 4, 0, 0),
      right(0.8, -0.25, 0.18, -M_PI / 4, 0, 0);
  const std::string log = freshDir("two_scanners") + "/two.rawlog";
  {
    mrpt::obs::CSensoryFrame sf;
    sf.insert(scanFrom(left, "LEFT"));
    sf.insert(scanFrom(right, "RIGHT"));
    mrpt::io::CFileGZOutputStream out(log);
    mrpt::serialization::archiveFrom(out) << sf;
  }
  const auto frames =
      readAllFrames("[pipeline]\nstages = source\n[source]\nplugin = rawlog\nfile = " + log + "\n");
  REQUIRE(frames.size() == 1);
  const Frame& read = frames[0];
  REQUIRE(read.observations.size() == 2);
  REQUIRE(read.sensors.size() == 2);
  CHECK(read.sensors[0].label == "LEFT");
  CHECK(read.sensors[1].label == "RIGHT");
  CHECK(read.sensors[0].pose.distanceTo(left) < 1e-6);  // no odometry: robot = fixed frame
  CHECK(read.sensors[1].pose.distanceTo(right) < 1e-6);
  CHECK(read.sensor_pose.distanceTo(left) < 1e-6);

  const std::string stages = "[segments]\nplugin = scan_segments\n[legs]\nplugin = leg_circles\n";
  Frame f = read;
  Stages("segments legs", stages).run(f);
  REQUIRE(f.clusters.size() == 1);
  CHECK(f.clusters[0].cx == Approx(2.0).margin(0.01));
  CHECK(f.clusters[0].cy == Approx(0.1).margin(0.01));
  CHECK(f.clusters[0].pair == -1);
  CHECK(f.clusters[0].features.back() < 0.005);  // leg_residual of the refit on both arcs
  // Both scans' returns off the leg are in the one cluster.
  std::size_t from_left = 0;
  for (std::uint32_t i : f.clusters[0].indices) from_left += i < read.cloudSpans()[1].first;
  CHECK(from_left > 3);
  CHECK(f.clusters[0].indices.size() - from_left > 3);
  // Without merging the one leg is two clusters that pair up as a person.
  Frame twice = read;
  Stages("segments legs", stages + "merge_distance = 0\n").run(twice);
  REQUIRE(twice.clusters.size() == 2);
  CHECK(twice.clusters[0].pair == 1);
}
