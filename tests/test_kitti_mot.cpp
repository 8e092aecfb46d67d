// KITTI's 3D tracking evaluation (eval/kitti_mot.h, kitti_boxes.h): box geometry and IoU, and a
// tiny labelled sequence whose counts, MOTA and sAMOTA are worked out by hand below.
#include <catch2/catch.hpp>
#include <cmath>

#include "pedtrack/eval/kitti_boxes.h"
#include "pedtrack/eval/kitti_mot.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::eval;

namespace {

KittiCameraBox box(double x, double z, double y = 1.5, double ry = 0) {
  KittiCameraBox b;
  b.h = 2, b.w = 1, b.l = 2, b.x = x, b.y = y, b.z = z, b.ry = ry;
  return b;
}

KittiTrackRow row(long frame, long id, const std::string& type, double x, double z,
                  double score = 1, double pixels = 100) {
  KittiTrackRow r;
  r.frame = frame, r.id = id, r.type = type, r.box = box(x, z), r.score = score;
  r.x1 = 100, r.x2 = 150, r.y1 = 100, r.y2 = 100 + pixels;
  return r;
}

}  // namespace

TEST_CASE("KITTI boxes: corners, image box, alpha and 3D IoU", "[kitti_mot]") {
  // 2 x 2 x 1 boxes: shifted by half their length (1 m along x at ry = 0) they share 1 x 1 x 2 =
  // 2 m^3 of 4 + 4 - 2 = 6: IoU 1/3. Shifted 1 m down (half their height): the same.
  CHECK(kittiIou3d(box(0, 10), box(0, 10)) == Approx(1));
  CHECK(kittiIou3d(box(0, 10), box(1, 10)) == Approx(1.0 / 3).epsilon(1e-5));
  CHECK(kittiIou3d(box(0, 10), box(0, 10, 2.5)) == Approx(1.0 / 3).epsilon(1e-5));
  CHECK(kittiIou3d(box(0, 10), box(5, 10)) == 0);
  // Turned by 90 degrees the 2 x 1 footprint becomes 1 x 2: they share 1 x 1 of 2 + 2 - 1.
  CHECK(kittiIouBev(box(0, 10), box(0, 10, 1.5, M_PI / 2)) == Approx(1.0 / 3).epsilon(1e-5));
  // rotation_y turns the length axis from x towards -z (KITTI's roty).
  const auto c = kittiCorners(box(0, 10, 1.5, M_PI / 2));
  CHECK(c[0].x() == Approx(0.5).margin(1e-9));
  CHECK(c[0].z() == Approx(9).margin(1e-9));
  CHECK(c[4].y() == Approx(-0.5));
  // Straight ahead alpha is rotation_y; a box 45 degrees to the right has alpha = ry - pi/4.
  CHECK(kittiAlpha(box(0, 10, 1.5, 0.3)) == Approx(0.3));
  CHECK(kittiAlpha(box(10, 10, 1.5, 0.3)) == Approx(0.3 - M_PI / 4));
  // The image box of a box 10 m ahead through a camera of focal 700 px, centre (600, 180).
  KittiCalib cal;
  cal.P2 << 700, 0, 600, 0, 0, 700, 180, 0, 0, 0, 1, 0;
  std::array<double, 4> xyxy{};
  REQUIRE(kittiImageBox(cal, box(0, 10), xyxy));
  // Nearest face at z = 9.5: x +-1 m -> 600 +- 700/9.5; y from 1.5 up to -0.5.
  CHECK(xyxy[0] == Approx(600 - 700 / 9.5));
  CHECK(xyxy[2] == Approx(600 + 700 / 9.5));
  CHECK(xyxy[1] == Approx(180 - 0.5 * 700 / 9.5));
  CHECK(xyxy[3] == Approx(180 + 1.5 * 700 / 9.5));
  CHECK_FALSE(kittiImageBox(cal, box(0, -5), xyxy));
  CHECK_FALSE(kittiImageBox(cal, box(30, 5), xyxy));  // wholly right of the 1,242 px image
  // Footprints overlapping 1 x 0.5 m diagonally: 1 m^3 of 4 + 4 - 1. Touching edges: nothing.
  CHECK(kittiIou3d(box(0, 10), box(1, 10.5)) == Approx(1.0 / 7).epsilon(1e-9));
  CHECK(kittiIou3d(box(0, 10), box(2, 10)) == Approx(0).margin(1e-12));
  // A box turned 45 degrees inside a bigger one's footprint: IoU = its volume / the big one's.
  KittiCameraBox big = box(0, 10);
  big.l = 4, big.w = 4;
  KittiCameraBox turned = box(0, 10, 1.5, M_PI / 4);
  CHECK(kittiIou3d(big, turned) == Approx(2.0 / 16).epsilon(1e-9));
}

TEST_CASE("a tiny KITTI sequence scored by hand", "[kitti_mot]") {
  KittiSequence s;
  s.name = "tiny";
  // Truths 1 and 2 in frames 0-3. Track 10 follows 1; 20 follows 2 in frames 0-1 and 21 takes
  // over in 2-3: one ID switch (consecutive matched appearances, other ids) and one
  // fragmentation. Track 30 (score 0.5) is a false positive in frame 1; track 31 is 20 px high
  // (ignored); track 32 lies in a DontCare area (ignored); truth 3 is occluded 3 (ignored: its
  // miss is no miss).
  for (long f = 0; f < 4; ++f) {
    s.truth.push_back(row(f, 1, "pedestrian", 0, 10));
    s.truth.push_back(row(f, 2, "pedestrian", 5, 10));
    s.tracks.push_back(row(f, 10, "pedestrian", 0, 10));
    s.tracks.push_back(row(f, f < 2 ? 20 : 21, "pedestrian", 5, 10));
  }
  auto hidden = row(2, 3, "pedestrian", -5, 20);
  hidden.occluded = 3;
  s.truth.push_back(hidden);
  auto dontcare = row(3, -1, "dontcare", 0, 0);
  dontcare.x1 = 0, dontcare.x2 = 1000, dontcare.y1 = 300, dontcare.y2 = 400;
  s.truth.push_back(dontcare);
  s.tracks.push_back(row(1, 30, "pedestrian", 10, 30, 0.5));
  s.tracks.push_back(row(2, 31, "pedestrian", -10, 30, 0.5, 20));
  auto in_dontcare = row(3, 32, "pedestrian", -10, 40, 0.5);
  in_dontcare.y1 = 310, in_dontcare.y2 = 390;
  s.tracks.push_back(in_dontcare);

  KittiMotOptions o;
  const KittiMotResult r = evaluateKittiMot({s}, o);
  // Every track of score 1 kept: 8 matches of IoU 1, no miss, no false positive, one switch.
  // The 8 matched scores are all 1 and num_gt = 8: recall steps of 1/8 place the levels 0,
  // 1/40, ..., 7/40 each at the next match; level 0 is dropped: 7 levels at threshold 1.
  CHECK(r.levels == 7);
  CHECK(r.threshold == 1);
  CHECK(r.best.tp == 8);
  CHECK(r.best.fn == 0);
  CHECK(r.best.fp == 0);
  CHECK(r.best.ids == 1);
  CHECK(r.best.frag == 1);
  CHECK(r.best.n_gt == 8);
  CHECK(r.best.mota() == Approx(1 - 1.0 / 8));
  CHECK(r.best.motp() == Approx(1));
  // sMOTA(r) = clip(1 - (1 - (1 - r) 8) / (8 r)) = clip(7 / (8 r)) = 1 at each r <= 7/40; the
  // sum over 7 levels is divided by 40.
  CHECK(r.samota == Approx(7.0 / 40));
  CHECK(r.amota == Approx(7 * 0.875 / 40));
  // With every track kept (a threshold below 0.5) the false positive counts; the low box and
  // the box in the DontCare area do not, nor does the occluded truth's miss.
  KittiMotCounts c;
  c.n_gt = 8, c.fn = 0, c.fp = 1, c.ids = 1;
  CHECK(c.mota() == Approx(0.75));
  CHECK(c.smota(0.9) == Approx(1 - (2 - 0.1 * 8) / (0.9 * 8)));  // 0.833
  CHECK(c.smota(0.5) == 1);                                      // clipped
  // Matching by bird's-eye distance instead: the same matches, MOTP 0 m.
  o.max_distance = 1;
  const KittiMotResult d = evaluateKittiMot({s}, o);
  CHECK(d.best.tp == 8);
  CHECK(d.best.motp() == Approx(0).margin(1e-12));
}

TEST_CASE("evaluate.py's score drift drops a track at the threshold its own mean set",
          "[kitti_mot]") {
  // 11 boxes scoring 0.3: their mean is 0.29999999999999993, and the mean of 11 copies of that
  // is 0.2999999999999999, below it. Re-averaged in every pass as evaluate.py does, the track
  // fails each recall level's threshold: every level scores 0.
  KittiSequence s;
  s.name = "drift";
  for (long f = 0; f < 11; ++f) {
    s.truth.push_back(row(f, 1, "pedestrian", 0, 10));
    s.tracks.push_back(row(f, 5, "pedestrian", 0, 10, 0.3));
  }
  KittiMotOptions o;
  const KittiMotResult plain = evaluateKittiMot({s}, o);
  CHECK(plain.samota > 0.2);
  CHECK(plain.best.mota() == 1);
  o.score_drift = true;
  const KittiMotResult drift = evaluateKittiMot({s}, o);
  CHECK(drift.levels == plain.levels);
  CHECK(drift.samota == Approx(0).margin(1e-9));  // each level: 1 - 11 r / (11 r)
  CHECK(drift.amota == Approx(0).margin(1e-9));
  // No level gave a positive MOTA: the reported pass keeps every track.
  CHECK(drift.threshold == -1e4);
  CHECK(drift.best.mota() == 1);
}

TEST_CASE("an ID switch across a missed frame is no switch, as KITTI counts", "[kitti_mot]") {
  KittiSequence s;
  s.name = "gap";
  for (long f = 0; f < 3; ++f) s.truth.push_back(row(f, 1, "pedestrian", 0, 10));
  s.tracks.push_back(row(0, 10, "pedestrian", 0, 10));
  s.tracks.push_back(row(2, 11, "pedestrian", 0, 10));  // frame 1 missed
  const KittiMotResult r = evaluateKittiMot({s}, KittiMotOptions{});
  CHECK(r.best.ids == 0);
  CHECK(r.best.fn == 1);
  CHECK(r.best.frag == 1);  // the last appearance resumes after a miss
  CHECK(r.best.mostly_tracked == 0);
  CHECK(r.best.partly_tracked == 1);  // 2 of 3
}

TEST_CASE("KITTI results files are read and refused naming file and line", "[kitti_mot]") {
  const std::string dir = test::freshDir("kitti_mot_files");
  test::writeFile(
      dir + "/ok.txt",
      "0 2 Pedestrian 0 0 -2.5 1106 166 1204 323 1.71 0.77 0.97 6.3 1.65 8.46 -1.9 "
      "0.8\n\n1 -1 DontCare -1 -1 -10 220 130 387 230 -1000 -1000 -1000 -10 -1 -1 -1\n");
  const auto rows = readKittiTrackFile(dir + "/ok.txt");
  REQUIRE(rows.size() == 2);
  CHECK(rows[0].type == "pedestrian");
  CHECK(rows[0].score == Approx(0.8));
  CHECK(rows[0].box.z == Approx(8.46));
  CHECK(rows[1].score == -1);
  test::writeFile(dir + "/bad.txt",
                  "0 2 Pedestrian 0 0 -2.5 1106 166 1204 323 1.71 0.77 x 6.3 "
                  "1.65 8.46 -1.9\n");
  CHECK_THROWS_WITH(readKittiTrackFile(dir + "/bad.txt"),
                    Catch::Contains("bad.txt: line 1: value 13 'x' is not a number"));
  test::writeFile(dir + "/short.txt", "0 2 Pedestrian 0 0\n");
  CHECK_THROWS_WITH(readKittiTrackFile(dir + "/short.txt"),
                    Catch::Contains("short.txt: line 1: expected 17 or 18 values"));
}
