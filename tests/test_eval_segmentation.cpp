// Segmentation scored point by point: a hand-made frame with every outcome, and the file-level
// matching of a run's labels to the truth.
#include <catch2/catch.hpp>
#include <cmath>

#include "pedtrack/errors.h"
#include "pedtrack/eval/segmentation.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::eval;

namespace {

constexpr std::int32_t G = run_label::kGround, U = run_label::kUnclustered;

// Truth: person 1 (5 points), 2 (3), object 1, ground, 3 (3), 4 (3), 5 (2), 6 (3), 7 (3).
LabelFrame handTruth() {
  LabelFrame t;
  t.index = 0;
  t.labels = {1, 1, 1, 1, 1, 2, 2, 2, -1, -1, 0, 0, 3, 3, 3, 4, 4, 4, 5, 5, 6, 6, 6, 7, 7, 7};
  t.plane.valid = true;  // level ground, z = 0
  t.people = {{1, 0.6f}, {2, 0.1f}, {3, 1.0f}, {4, 2.0f}, {5, 2.0f}, {6, 0.3f}, {7, 0.3f}};
  return t;
}

// Run: person 1 split over clusters 0 and 1; 2 merged with the object in cluster 2 (which also
// took a ground point); 3 alone in cluster 3; 4 removed as ground; 6 and 7 together in cluster 4.
LabelFrame handRun() {
  LabelFrame r;
  r.index = 0;
  r.labels = {0, 0, 0, 1, 1, 2, 2, 2, 2, 2, G, 2, 3, 3, 3, G, G, G, U, U, 4, 4, 4, 4, 4, 4};
  r.plane.valid = true;  // tilted by 1° about the x axis
  r.plane.ny = -std::sin(M_PI / 180);
  r.plane.nz = std::cos(M_PI / 180);
  r.plane.d = -0.01;
  return r;
}

}  // namespace

TEST_CASE("segmentation outcomes on a hand-made frame", "[eval][segmentation]") {
  SegmentationOptions o;
  o.min_points = 3;
  o.fragment = 2;
  o.isolation = 0.5;
  SegmentationReport r;
  scoreSegmentationFrame(handTruth(), handRun(), o, r);
  CHECK(r.frames == 1);
  CHECK(r.ground_points == 2);
  CHECK(r.ground_removed == 1);
  CHECK(r.ground_in_clusters == 1);
  CHECK(r.person_points == 22);
  CHECK(r.person_as_ground == 3);
  CHECK(r.person_in_clusters == 17);
  CHECK(r.object_points == 2);
  // Person 5 has 2 points (< 3): not scored. Six samples.
  CHECK(r.all.samples == 6);
  CHECK(r.all.correct == 1);        // person 3
  CHECK(r.all.split == 1);          // person 1
  CHECK(r.all.merged_object == 1);  // person 2
  CHECK(r.all.missed == 1);         // person 4
  CHECK(r.all.merged_person == 2);  // persons 6 and 7
  // Isolated (clearance >= 0.5): persons 1, 3 and 4.
  CHECK(r.isolated.samples == 3);
  CHECK(r.isolated.correct == 1);
  CHECK(r.isolated.split == 1);
  CHECK(r.isolated.missed == 1);
  REQUIRE(r.plane_angle_deg.size() == 1);
  CHECK(r.plane_angle_deg[0] == Approx(1.0).epsilon(1e-9));
  CHECK(r.plane_offset[0] == Approx(0.01 / std::cos(M_PI / 180)).epsilon(1e-9));
  // A cluster must hold `fragment` points of a person to count: with 3, person 1's two-point
  // part no longer splits it.
  o.fragment = 3;
  SegmentationReport r3;
  scoreSegmentationFrame(handTruth(), handRun(), o, r3);
  CHECK(r3.all.split == 0);
  CHECK(r3.all.merged_object == 0);  // the object's 2 points no longer count either
}

TEST_CASE("segmentation files: frames by index, missing run frames, bad input",
          "[eval][segmentation]") {
  const std::string dir = test::freshDir("eval_segmentation");
  {
    LabelFileWriter t(dir + "/truth_points.bin", LabelKind::Truth);
    LabelFileWriter r(dir + "/point_labels.bin", LabelKind::Run);
    for (std::uint64_t k = 0; k < 4; ++k) {
      LabelFrame tf = handTruth(), rf = handRun();
      tf.index = rf.index = k;
      t.write(tf);
      if (k != 2) r.write(rf);  // the run failed frame 2
    }
  }
  SegmentationOptions o;
  o.min_points = 3;
  o.fragment = 2;
  const SegmentationReport r =
      evaluateSegmentation(dir + "/truth_points.bin", dir + "/point_labels.bin", o);
  CHECK(r.frames == 3);
  CHECK(r.truth_only_frames == 1);
  CHECK(r.all.samples == 18);
  CHECK(r.per_person.size() == 6);
  CHECK(r.per_person.front().first == 1);
  CHECK(r.per_person.front().second.split == 3);
  CHECK_THROWS_AS(evaluateSegmentation(dir + "/point_labels.bin", dir + "/truth_points.bin", o),
                  ConfigError);
  {
    LabelFileWriter r(dir + "/short.bin", LabelKind::Run);
    LabelFrame rf = handRun();
    rf.labels.pop_back();
    r.write(rf);
  }
  CHECK_THROWS_WITH(evaluateSegmentation(dir + "/truth_points.bin", dir + "/short.bin", o),
                    Catch::Contains("frame 0 has 25 points, the truth 26"));
}
