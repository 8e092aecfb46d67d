// The torso-shape tracking parts: P1's motion model, the observation models with their
// dimension switching (eq. 18), and the shape tracker's IMM on synthetic torso clouds.
#include <mrpt/obs/CObservationPointCloud.h>

#include <Eigen/Dense>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "pedtrack/track/kalman.h"
#include "pedtrack/track/shape_tracker.h"

using namespace pedtrack;
using namespace pedtrack::track;

namespace {

// Points of the near side of a torso ellipse (P1 convention: α across the facing direction θ,
// β along it) seen from the origin, on `rings` heights, with σ noise.
std::vector<std::array<float, 3>> torso(double cx, double cy, double theta, double alpha,
                                        double beta, int per_ring, int rings, std::mt19937& rng,
                                        double sigma = 0.005) {
  std::normal_distribution<double> n(0, sigma);
  std::vector<std::array<float, 3>> out;
  const Eigen::Vector2d u(std::cos(theta), std::sin(theta)), w(-std::sin(theta), std::cos(theta));
  const Eigen::Vector2d c(cx, cy);
  std::vector<Eigen::Vector2d> visible;
  for (int k = 0; k < 720; ++k) {
    const double phi = k * M_PI / 360;
    const Eigen::Vector2d p = c + beta * std::cos(phi) * u + alpha * std::sin(phi) * w;
    const Eigen::Vector2d normal = std::cos(phi) / beta * u + std::sin(phi) / alpha * w;
    if (normal.dot(-p) > 0) visible.push_back(p);
  }
  for (int r = 0; r < rings; ++r)
    for (int i = 0; i < per_ring; ++i) {
      const Eigen::Vector2d& p = visible[(visible.size() - 1) * i / std::max(per_ring - 1, 1)];
      out.push_back({float(p.x() + n(rng)), float(p.y() + n(rng)), float(0.9 + 0.15 * r)});
    }
  return out;
}

// A frame at time t whose cloud is `pts` (robot = fixed frame, sensor at the origin), with one
// cluster of all the points and one detection of it.
Frame torsoFrame(double t, const std::vector<std::array<float, 3>>& pts, double score = 0.9) {
  auto obs = mrpt::obs::CObservationPointCloud::Create();
  auto map = mrpt::maps::CSimplePointsMap::Create();
  for (const auto& p : pts) map->insertPointFast(p[0], p[1], p[2]);
  obs->pointcloud = map;
  Frame f;
  f.t = t;
  f.observations.push_back(obs);
  Cluster c;
  for (std::uint32_t i = 0; i < pts.size(); ++i) c.indices.push_back(i);
  f.clusters.push_back(c);
  Detection d;
  d.cluster = 0;
  d.score = score;
  d.x = pts.empty() ? 0 : pts[0][0];
  d.y = pts.empty() ? 0 : pts[0][1];
  f.detections.push_back(d);
  return f;
}

// A frame with one cluster per point set, each with a detection scoring scores[k].
Frame clustersFrame(double t, const std::vector<std::vector<std::array<float, 3>>>& sets,
                    const std::vector<double>& scores) {
  std::vector<std::array<float, 3>> all;
  for (const auto& set : sets) all.insert(all.end(), set.begin(), set.end());
  Frame f = torsoFrame(t, all);
  f.clusters.clear();
  f.detections.clear();
  std::uint32_t next = 0;
  for (std::size_t k = 0; k < sets.size(); ++k) {
    Cluster c;
    for (std::size_t i = 0; i < sets[k].size(); ++i) c.indices.push_back(next++);
    f.clusters.push_back(c);
    Detection d;
    d.cluster = int(k);
    d.score = scores[k];
    f.detections.push_back(d);
  }
  return f;
}

ShapeCloud cloudOf(const std::vector<std::array<float, 3>>& pts) {
  ShapeCloud c;
  for (const auto& p : pts) c.points.emplace_back(p[0], p[1]);
  return c;
}

}  // namespace

TEST_CASE("P1's shape unicycle: prediction, Jacobian against numeric, additive noise",
          "[shape][motion]") {
  const Eigen::VectorXd rates = (Eigen::VectorXd(6) << 0, 0, 10, 10, 1e-3, 2e-3).finished();
  ShapeUnicycle m(rates);
  Eigen::VectorXd x(6);
  x << 1, 2, 0.5, 1.2, 0.18, 0.09;
  const Eigen::VectorXd y = m.predict(x, 0.1);
  CHECK(y(0) == Approx(1 + 0.12 * std::cos(0.5)));
  CHECK(y(1) == Approx(2 + 0.12 * std::sin(0.5)));
  CHECK(y.tail<4>() == x.tail<4>());
  const Eigen::MatrixXd F = m.jacobian(x, 0.1);
  for (int k = 0; k < 6; ++k) {
    Eigen::VectorXd e = Eigen::VectorXd::Zero(6);
    e(k) = 1e-6;
    const Eigen::VectorXd col = (m.predict(x + e, 0.1) - m.predict(x - e, 0.1)) / 2e-6;
    CHECK((col - F.col(k)).norm() < 1e-6);
  }
  CHECK(m.noise(x, 0.1).diagonal().isApprox(rates * 0.1));
  CHECK_THROWS_AS(ShapeUnicycle(Eigen::VectorXd::Ones(4)), std::invalid_argument);
}

TEST_CASE("observation dimension switches with the point count (P1 eq. 18)", "[shape][obs]") {
  std::mt19937 gen(3), rng(4);
  ShapeObservationParams p;  // N_e = 40, N_b = 10
  const Eigen::VectorXd prior = (Eigen::VectorXd(6) << 5, 0, M_PI, 0, 0.18, 0.09).finished();
  auto dims = [&](int per_ring, int rings) {
    const ShapeCloud c = cloudOf(torso(5, 0, M_PI, 0.18, 0.09, per_ring, rings, gen));
    ShapeFits fits(c, prior, p, rng);
    std::array<int, 3> d{};
    int k = 0;
    for (ShapeModel m : {ShapeModel::Ellipse, ShapeModel::Box, ShapeModel::Cog}) {
      const auto meas = fits.measure(m);
      d[k++] = meas ? int(meas->z.size()) : 0;
    }
    return d;
  };
  CHECK(dims(20, 3) == std::array<int, 3>{5, 5, 2});  // 60 points
  CHECK(dims(10, 2) == std::array<int, 3>{2, 5, 2});  // 20 points: N_b ≤ M < N_e
  CHECK(dims(3, 2) == std::array<int, 3>{0, 0, 2});   // 6 points: below N_b, the COG only
  CHECK(dims(1, 1) == std::array<int, 3>{0, 0, 2});   // 1 point: the COG only
}

TEST_CASE("shape measurements: heading nearest the prior modulo pi, box axes, COG offset",
          "[shape][obs]") {
  std::mt19937 gen(5), rng(6);
  ShapeObservationParams p;
  // A person 5 m ahead facing the sensor (θ = π), seen from the front: dense cloud.
  const ShapeCloud c = cloudOf(torso(5, 0, M_PI, 0.18, 0.09, 20, 3, gen, 0.002));
  // The prior says θ ≈ 0 (walking away, back seen): the ellipse's θ must come out near 0, not π.
  const Eigen::VectorXd prior = (Eigen::VectorXd(6) << 5, 0, 0.1, 1, 0.18, 0.09).finished();
  ShapeFits fits(c, prior, p, rng);
  const auto e = fits.measure(ShapeModel::Ellipse);
  REQUIRE(e);
  CHECK(std::abs(e->z(2)) < 0.2);
  CHECK(e->z(0) == Approx(5).margin(0.03));
  CHECK(e->z(3) == Approx(0.18).margin(0.03));  // α: across the shoulders
  CHECK(e->z(4) == Approx(0.09).margin(0.03));
  // The box's heading axis is the one nearer the prior; α is its half-side across.
  const auto b = fits.measure(ShapeModel::Box);
  REQUIRE(b);
  CHECK(std::abs(b->z(2)) < 0.2);
  CHECK(b->z(3) > b->z(4));
  // The COG moves back from the near surface by the prior's β.
  const auto g = fits.measure(ShapeModel::Cog);
  REQUIRE(g);
  const Eigen::Vector2d mean = fit::centroid(c.points);
  const Eigen::Vector2d want = mean + 0.09 * mean.normalized();  // the sensor is at the origin
  CHECK(g->z(0) == Approx(want.x()).margin(1e-9));
  CHECK(g->z(1) == Approx(want.y()).margin(1e-9));
}

TEST_CASE("IMM model probabilities move to the PC-COG model when points fall below N_b",
          "[shape][imm]") {
  ShapeTrackerParams p;  // P1: ellipse, box, cog with Table I's Q, R, Π
  p.report_tentative = true;
  ShapeTracker tracker(p);
  std::mt19937 gen(7);
  // A person walking away along +x at 1 m/s from 4 m, facing +x (the back is seen).
  auto probs = [&](double t, int per_ring, int rings) {
    Frame f = torsoFrame(t, torso(4 + t, 0.5, 0, 0.18, 0.09, per_ring, rings, gen));
    tracker.process(f);
    REQUIRE(f.tracks.size() == 1);
    return f.tracks[0].model_probs;
  };
  std::vector<double> dense, sparse;
  for (int k = 0; k < 40; ++k) dense = probs(0.1 * k, 20, 3);   // 60 points
  CHECK(dense[0] > 0.5);                                        // the ellipse leads when dense
  for (int k = 40; k < 80; ++k) sparse = probs(0.1 * k, 3, 2);  // 6 points: below N_b
  CHECK(sparse[2] > dense[2]);
  CHECK(sparse[2] > sparse[0]);
  CHECK(sparse[2] > sparse[1]);
}

TEST_CASE("one walker: one confirmed track, position, heading and size recovered",
          "[shape][tracker]") {
  ShapeTrackerParams p;
  ShapeTracker tracker(p);
  std::mt19937 gen(8);
  Frame last;
  for (int k = 0; k < 60; ++k) {
    const double t = 0.1 * k;
    // Walking diagonally away (θ = 0.5) at 1 m/s, so the sensor sees the back and a shoulder.
    last = torsoFrame(
        t, torso(3 + t * std::cos(0.5), 1 + t * std::sin(0.5), 0.5, 0.18, 0.09, 20, 3, gen));
    tracker.process(last);
  }
  REQUIRE(last.tracks.size() == 1);
  const Track& tr = last.tracks[0];
  CHECK(tr.status == "confirmed");
  CHECK(tr.id == 1);
  const double t = 5.9;
  CHECK(tr.x == Approx(3 + t * std::cos(0.5)).margin(0.05));
  CHECK(tr.y == Approx(1 + t * std::sin(0.5)).margin(0.05));
  CHECK(std::abs(wrapAngle(tr.yaw - 0.5)) < 0.15);  // facing the walking direction
  CHECK(std::hypot(tr.vx, tr.vy) == Approx(1).margin(0.15));
  CHECK(tr.alpha == Approx(0.18).margin(0.04));
  CHECK(tr.beta == Approx(0.09).margin(0.04));
  REQUIRE(tr.model_probs.size() == 3);
}

TEST_CASE("shape tracker: low scores start nothing; a lost track is deleted after max_misses",
          "[shape][tracker]") {
  ShapeTrackerParams p;
  p.max_misses = 3;
  ShapeTracker tracker(p);
  std::mt19937 gen(9);
  for (int k = 0; k < 5; ++k) {
    Frame f = torsoFrame(0.1 * k, torso(5, 0, M_PI, 0.18, 0.09, 20, 3, gen), 0.3);
    tracker.process(f);
    CHECK(f.tracks.empty());  // 0.3 < q_person = 0.5: no track starts
  }
  int reported = 0;
  for (int k = 5; k < 15; ++k) {
    Frame f = torsoFrame(0.1 * k, torso(5, 0, M_PI, 0.18, 0.09, 20, 3, gen));
    tracker.process(f);
    reported = int(f.tracks.size());
  }
  CHECK(reported == 1);
  std::vector<std::size_t> counts;
  for (int k = 15; k < 21; ++k) {
    Frame f;  // nothing seen
    f.t = 0.1 * k;
    tracker.process(f);
    counts.push_back(f.tracks.size());
  }
  CHECK(counts == std::vector<std::size_t>{1, 1, 0, 0, 0, 0});  // the 3rd miss in a row deletes
}

TEST_CASE("shape tracker static scene: a post learned starts no track; a tracked person stays",
          "[shape][tracker][static]") {
  // A post (0.2 m across) scoring 0.3 for 4 s, then 0.9: P1's tracker (static_scene off) starts
  // and confirms a track on it once it scores high; with the grid, its cells have been occupied
  // for longer than static_persist (3 s) away from any track, and nothing starts.
  auto run = [](bool static_scene) {
    ShapeTrackerParams p;
    p.static_scene = static_scene;
    ShapeTracker tracker(p);
    std::mt19937 gen(4);
    std::size_t reported = 0;
    for (int k = 0; k < 60; ++k) {
      Frame f = torsoFrame(0.1 * k, torso(5, 0, M_PI, 0.1, 0.1, 10, 6, gen), k < 40 ? 0.3 : 0.9);
      tracker.process(f);
      reported = std::max(reported, f.tracks.size());
    }
    return reported;
  };
  CHECK(run(false) == 1);
  CHECK(run(true) == 0);

  // A person standing still from the start is tracked at once: the track holds their place,
  // so 10 s of standing never makes them static scene. Lost for longer than max_misses (track
  // deleted) and back, they start a new track; with no exclusion round tracks (control) their
  // place was learned and nothing starts.
  auto standing = [](double exclusion) {
    ShapeTrackerParams p;
    p.static_scene = true;
    p.scene.exclusion_radius = exclusion;
    ShapeTracker tracker(p);
    std::mt19937 gen(5);
    std::vector<std::size_t> counts;
    for (int k = 0; k < 100; ++k) {
      Frame f = torsoFrame(0.1 * k, torso(4, 1, M_PI, 0.18, 0.09, 20, 3, gen));
      tracker.process(f);
      if (k % 20 == 19) counts.push_back(f.tracks.size());
    }
    for (int k = 100; k < 115; ++k) {  // not seen: deleted after max_misses (10)
      Frame f;
      f.t = 0.1 * k;
      tracker.process(f);
    }
    std::size_t back = 0;
    for (int k = 115; k < 125; ++k) {
      Frame f = torsoFrame(0.1 * k, torso(4, 1, M_PI, 0.18, 0.09, 20, 3, gen));
      tracker.process(f);
      back = f.tracks.size();
    }
    counts.push_back(back);
    return counts;
  };
  CHECK(standing(0.4) == std::vector<std::size_t>{1, 1, 1, 1, 1, 1});
  CHECK(standing(0).back() == 0);

  // Foliage: the returns of a bush scatter, and where they fall this scan (0.2-0.4 m beside
  // where they fell for 4 s) no cell is static yet. Read on each point's own cell, the fragment
  // starts a track; with static_radius (0.3 m) its points lie by the learned cells, and it does
  // not.
  auto beside = [](double radius) {
    ShapeTrackerParams p;
    p.static_scene = true;
    p.static_radius = radius;
    ShapeTracker tracker(p);
    std::mt19937 gen(7);
    std::size_t reported = 0;
    for (int k = 0; k < 60; ++k) {
      const double y = k < 40 ? 0.0 : 0.3;
      Frame f = torsoFrame(0.1 * k, torso(5, y, M_PI, 0.1, 0.1, 10, 6, gen), k < 40 ? 0.3 : 0.9);
      tracker.process(f);
      reported = std::max(reported, f.tracks.size());
    }
    return reported;
  };
  CHECK(beside(0) == 1);
  CHECK(beside(0.3) == 0);

  // The fixed frame jumps (motion unknown): the grid forgets, and a place learned starts tracks
  // again.
  ShapeTrackerParams p;
  p.static_scene = true;
  ShapeTracker tracker(p);
  std::mt19937 gen(6);
  for (int k = 0; k < 40; ++k) {
    Frame f = torsoFrame(0.1 * k, torso(5, 0, M_PI, 0.1, 0.1, 10, 6, gen), 0.3);
    tracker.process(f);
  }
  std::size_t after = 0;
  for (int k = 40; k < 50; ++k) {
    Frame f = torsoFrame(0.1 * k, torso(5, 0, M_PI, 0.1, 0.1, 10, 6, gen), 0.9);
    f.motion_unknown = k == 40;
    tracker.process(f);
    after = f.tracks.size();
  }
  CHECK(after == 1);
}

TEST_CASE("shape tracker static scene: a person beside a low static object is no part of it",
          "[shape][tracker][static]") {
  // A bench back (returns at 0.6, 0.75 and 0.85 m along 1.8 m, scoring 0.3) is learned for 4 s;
  // then a sitter, 0.1-0.2 m in front of it with torso returns from 0.9 to 1.65 m, scores 0.9.
  // Read in 2D every return of theirs lies within static_radius of the back's cells and no
  // track starts; with static_height_margin (0.25 m) the four rings above 1.1 m are not the
  // back's, and the sitter is tracked. A detection without points beside them (no height)
  // starts nothing and costs nothing.
  auto run = [](double margin) {
    ShapeTrackerParams p;
    p.static_scene = true;
    p.static_height_margin = margin;
    ShapeTracker tracker(p);
    std::mt19937 gen(8);
    std::vector<std::array<float, 3>> back;
    for (double y = -0.9; y <= 0.9; y += 0.05)
      for (const float z : {0.6f, 0.75f, 0.85f}) back.push_back({5.0f, float(y), z});
    std::size_t reported = 0;
    for (int k = 0; k < 60; ++k) {
      std::vector<std::vector<std::array<float, 3>>> sets{back};
      std::vector<double> scores{0.3};
      if (k >= 40) {
        sets.push_back(torso(4.9, 0, M_PI, 0.18, 0.09, 10, 6, gen));
        scores.push_back(0.9);
      }
      Frame f = clustersFrame(0.1 * k, sets, scores);
      Detection pointless;
      pointless.x = 4.9;
      pointless.y = 3.0;
      pointless.score = 0.9;
      f.detections.push_back(pointless);
      tracker.process(f);
      reported = std::max(reported, f.tracks.size());
    }
    return reported;
  };
  CHECK(run(-1) == 0);
  CHECK(run(0.25) == 1);
}

TEST_CASE("shape tracker static scene: an unmoved track that scores low gives its place up",
          "[shape][tracker][static]") {
  // A bin scoring 0.6 from the first scan (above q_person) gets a confirmed track at start-up,
  // which keeps the grid from learning it. With unmoved_time 3 s it stops doing so 3 s after its
  // birth (never 0.5 m from there, mean score under 0.8); its cells are static after
  // static_persist (3 s) more, the bin then feeds the track no longer, and it ends after
  // max_misses (1 s): nothing is reported from then on. A person standing as long, scoring 0.9,
  // keeps their track: their detections score as a person's.
  auto run = [](double unmoved_time, double score) {
    ShapeTrackerParams p;
    p.static_scene = true;
    p.unmoved_time = unmoved_time;
    ShapeTracker tracker(p);
    std::mt19937 gen(8);
    std::vector<std::size_t> counts;
    for (int k = 0; k < 120; ++k) {
      Frame f = torsoFrame(0.1 * k, torso(5, 0, M_PI, 0.18, 0.09, 20, 3, gen), score);
      tracker.process(f);
      if (k % 20 == 19) counts.push_back(f.tracks.size());
    }
    return counts;
  };
  CHECK(run(0, 0.6) == std::vector<std::size_t>{1, 1, 1, 1, 1, 1});
  CHECK(run(3, 0.6) == std::vector<std::size_t>{1, 1, 1, 0, 0, 0});
  CHECK(run(3, 0.9) == std::vector<std::size_t>{1, 1, 1, 1, 1, 1});
}

TEST_CASE("shape tracker: small clusters start tracks only on a high score, clear of others",
          "[shape][tracker]") {
  // A walker far away gives 6 torso points (under N_b = 10): P1 never starts a track on them;
  // with small_birth_score 0.9 a cluster scoring 0.95 does (M-of-N confirms it), one scoring
  // 0.85 does not.
  auto far_walker = [](double small_birth_score, double score) {
    ShapeTrackerParams p;
    p.small_birth_score = small_birth_score;
    ShapeTracker tracker(p);
    std::mt19937 gen(5);
    std::size_t reported = 0;
    for (int k = 0; k < 20; ++k) {
      Frame f = torsoFrame(0.1 * k, torso(15, -1 + 0.1 * k, M_PI, 0.18, 0.09, 3, 2, gen), score);
      tracker.process(f);
      reported = std::max(reported, f.tracks.size());
    }
    return reported;
  };
  CHECK(far_walker(0, 0.95) == 0);
  CHECK(far_walker(0.9, 0.95) == 1);
  CHECK(far_walker(0.9, 0.85) == 0);
  // The same small cluster 0.6 m beside a confirmed person (within the 1 m gate; from the 6th
  // scan, the person's track confirmed by then): a piece of them or someone behind them, it
  // starts nothing.
  ShapeTrackerParams p;
  p.small_birth_score = 0.9;
  ShapeTracker tracker(p);
  std::mt19937 gen(6);
  std::size_t most = 0;
  for (int k = 0; k < 20; ++k) {
    const auto person = torso(5, 0, M_PI, 0.18, 0.09, 20, 3, gen);
    Frame f = k < 5 ? clustersFrame(0.1 * k, {person}, {0.95})
                    : clustersFrame(0.1 * k, {person, torso(5.6, 0, M_PI, 0.18, 0.09, 3, 2, gen)},
                                    {0.95, 0.95});
    tracker.process(f);
    most = std::max(most, f.tracks.size());
  }
  CHECK(most == 1);
}

TEST_CASE("shape tracker static scene: a track fed only by small clusters holds no place",
          "[shape][tracker][static]") {
  // A far post's 6 points score 0.95 from the first scan: its track starts and is confirmed,
  // but does not keep the grid from learning the post, so after static_persist (3 s) the post
  // feeds it no longer and it ends after max_misses (1 s). A small walker's returns move and are
  // never learned: their track lives on. A full-size cluster standing there keeps its track.
  auto run = [](double y_step, int per_ring) {
    ShapeTrackerParams p;
    p.static_scene = true;
    p.small_birth_score = 0.9;
    ShapeTracker tracker(p);
    std::mt19937 gen(7);
    std::vector<std::size_t> counts;
    for (int k = 0; k < 100; ++k) {
      Frame f =
          torsoFrame(0.1 * k, torso(15, -3 + y_step * k, M_PI, 0.18, 0.09, per_ring, 2, gen), 0.95);
      tracker.process(f);
      if (k % 20 == 19) counts.push_back(f.tracks.size());
    }
    return counts;
  };
  CHECK(run(0, 3) == std::vector<std::size_t>{1, 1, 0, 0, 0});
  CHECK(run(0.06, 3) == std::vector<std::size_t>{1, 1, 1, 1, 1});
  CHECK(run(0, 10) == std::vector<std::size_t>{1, 1, 1, 1, 1});
}

TEST_CASE("shape tracker static scene: a track that strays onto a learned post ends there",
          "[shape][tracker][static]") {
  // A post at (5, 0), scoring 0.3, learned over 4 s. A person (scoring 0.9) walks up to it from
  // (5, 1.6) at 0.5 m/s and vanishes 0.35 m short of it, while the post now scores 0.9 (a bin the
  // classifier takes for a child). With static_feeds the person's track lives on on the post;
  // without, the post updates nothing, and the track coasts and ends after max_misses.
  auto run = [](bool feeds) {
    ShapeTrackerParams p;
    p.static_scene = true;
    p.static_feeds = feeds;
    ShapeTracker tracker(p);
    std::mt19937 gen(8);
    std::size_t end = 0, while_walking = 0;
    for (int k = 0; k < 100; ++k) {
      const auto post = torso(5, 0, M_PI, 0.1, 0.1, 10, 6, gen);
      const double y = 1.6 - 0.05 * (k - 40);
      Frame f = k < 40   ? clustersFrame(0.1 * k, {post}, {0.3})
                : k < 66 ? clustersFrame(0.1 * k, {post, torso(5, y, M_PI, 0.18, 0.09, 20, 3, gen)},
                                         {0.3, 0.9})
                         : clustersFrame(0.1 * k, {post}, {0.9});
      tracker.process(f);
      if (k == 60) while_walking = f.tracks.size();
      end = f.tracks.size();
    }
    return std::make_pair(while_walking, end);
  };
  CHECK(run(true) == std::make_pair(std::size_t(1), std::size_t(1)));
  CHECK(run(false) == std::make_pair(std::size_t(1), std::size_t(0)));
}

TEST_CASE("shape tracker re-identification: a person lost and back keeps their id",
          "[shape][tracker][reid]") {
  // A walker at 1 m/s along x, confirmed, hidden for `hidden` s (deleted after max_misses = 10
  // scans), then seen again `offset` m beside where their walk carried them. Returns the ids of
  // the confirmed rows before and after.
  auto run = [](double reidentify_time, double hidden, double offset, bool jump = false) {
    ShapeTrackerParams p;
    p.reidentify_time = reidentify_time;
    ShapeTracker tracker(p);
    std::mt19937 gen(11);
    std::vector<long> ids;
    const int gap = int(std::lround(hidden / 0.1));
    for (int k = 0; k < 40 + gap; ++k) {
      const double t = 0.1 * k, x = 3 + t;
      const bool seen = k < 20 || k >= 20 + gap;
      Frame f =
          seen ? torsoFrame(t, torso(x, k < 20 ? 0 : offset, 0, 0.18, 0.09, 20, 3, gen)) : Frame();
      f.t = t;
      f.motion_unknown = jump && k == 18 + gap;  // after the deletion (k = 29)
      tracker.process(f);
      for (const Track& tr : f.tracks)
        if (tr.status == "confirmed" && (ids.empty() || ids.back() != tr.id)) ids.push_back(tr.id);
    }
    return ids;
  };
  CHECK(run(4, 1.5, 0) == std::vector<long>{1});           // back where they walked to: the same id
  CHECK(run(4, 1.5, 1.2) == std::vector<long>{1});         // 1.2 m off: inside gate + 1.5 s x 1 m/s
  CHECK(run(0, 1.5, 0) == std::vector<long>{1, 2});        // off (P1): a new person
  CHECK(run(4, 1.5, 3.0) == std::vector<long>{1, 2});      // beyond gate + reidentify_max (2 m)
  CHECK(run(1, 1.5, 0) == std::vector<long>{1, 2});        // confirmed again 1.8 s after last seen
  CHECK(run(4, 1.5, 0, true) == std::vector<long>{1, 2});  // the fixed frame jumped meanwhile
}

TEST_CASE("shape tracker revive_score: a lost person seen again by a few returns is back at once",
          "[shape][tracker][reid]") {
  // A walker at 1 m/s along x, confirmed on 20 full clusters, hidden 1.5 s (deleted after
  // max_misses = 10 scans, kept lost), then seen `offset` m beside where their walk carried them
  // by 6 points (under N_b = 10) scoring 0.6 for 10 scans. Returns the confirmed rows' ids on
  // those 10 scans. `x0`: where the walk starts; `grid`: with the static scene on.
  auto back = [](double revive_score, double reidentify_time, double offset, double x0 = 3,
                 bool grid = false) {
    ShapeTrackerParams p;
    p.reidentify_time = reidentify_time;
    p.revive_score = revive_score;
    p.static_scene = grid;
    ShapeTracker tracker(p);
    std::mt19937 gen(12);
    std::vector<long> ids;
    for (int k = 0; k < 45; ++k) {
      const double t = 0.1 * k, x = x0 + t;
      Frame f;
      if (k < 20)
        f = torsoFrame(t, torso(x, 0, 0, 0.18, 0.09, 20, 3, gen));
      else if (k >= 35)
        f = torsoFrame(t, torso(x, offset, 0, 0.18, 0.09, 3, 2, gen), 0.6);
      f.t = t;
      tracker.process(f);
      if (k >= 35)
        for (const Track& tr : f.tracks)
          if (tr.status == "confirmed") ids.push_back(tr.id);
    }
    return ids;
  };
  // Back on the first scan, with their id, on every one of the 10.
  CHECK(back(0.5, 4, 0) == std::vector<long>(10, 1));
  // Off: 6 points start nothing (N_b), and nothing is reported.
  CHECK(back(0, 4, 0).empty());
  // A score under revive_score, or no lost track kept (reidentify_time 0): nothing.
  CHECK(back(0.7, 4, 0).empty());
  CHECK(back(0.5, 0, 0).empty());
  // 3 m off: beyond gate + reidentify_max (2 m): someone else.
  CHECK(back(0.5, 4, 3).empty());
  // With the static scene on: back within the grid's range (20 m), not beyond it, where a wall
  // or bush fragment cannot be told from them.
  CHECK(back(0.5, 4, 0, 3, true) == std::vector<long>(10, 1));
  CHECK(back(0.5, 4, 0, 21, true).empty());
  CHECK(back(0.5, 4, 0, 21, false) == std::vector<long>(10, 1));
}

TEST_CASE("shape tracker: a confirmed track keeps its cluster from a nearer tentative one",
          "[shape][tracker]") {
  // A person standing at (5, 0), tracked (id 1); then a second cluster (a bag put down, a split
  // piece) at (5, 0.8) starts a tentative track. One scan later a single cluster at (5, 0.45):
  // 0.45 m from the person's track, 0.35 m from the tentative one. Returns the id of the track
  // that cluster updated, 0 when no reported track took it.
  auto run = [](double penalty) {
    ShapeTrackerParams p;
    p.tentative_penalty = penalty;
    ShapeTracker tracker(p);
    std::mt19937 gen(12);
    auto frame = [&](double t, const std::vector<double>& ys) {
      std::vector<std::vector<std::array<float, 3>>> people;
      for (double y : ys) people.push_back(torso(5, y, M_PI, 0.18, 0.09, 20, 3, gen));
      return clustersFrame(t, people, std::vector<double>(ys.size(), 0.9));
    };
    for (int k = 0; k < 20; ++k) {
      Frame f = frame(0.1 * k, {0.0});
      tracker.process(f);
    }
    Frame f = frame(2.0, {0.0, 0.8});
    tracker.process(f);
    f = frame(2.1, {0.45});
    tracker.process(f);
    for (const Track& tr : f.tracks)
      if (tr.cluster == 0) return tr.id;
    return 0L;
  };
  CHECK(run(0) == 0);    // P1: the tentative track took it, the person's track coasts
  CHECK(run(0.6) == 1);  // the person's track keeps it
}
