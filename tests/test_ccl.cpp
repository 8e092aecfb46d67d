// Voxel connected components (6/18/26 on hand-made grids, and against a breadth-first search on
// random grids) and P2's cluster features by hand.
#include <algorithm>
#include <catch2/catch.hpp>
#include <map>
#include <queue>
#include <random>
#include <set>

#include "pedtrack/seg/cluster_features.h"
#include "voxel_ccl/voxel_labelling.h"

using namespace pedtrack;
using seg::Connectivity;
using seg::Voxel;

namespace {

int count(const std::vector<Voxel>& v, Connectivity c, std::vector<int>* comp = nullptr) {
  seg::VoxelLabeler l;
  std::vector<int> out;
  const int n = l.label(v, c, out);
  if (comp) *comp = out;
  return n;
}

// Independent reference: breadth-first search over the occupied set, components numbered by
// their lowest voxel (std::set visits voxels in (x, y, z) order), each point's component.
std::vector<int> bfsComponents(const std::vector<Voxel>& v, Connectivity c) {
  std::set<Voxel> occupied(v.begin(), v.end()), seen;
  std::map<Voxel, int> comp;
  int n = 0;
  for (const Voxel& s : occupied) {
    if (seen.count(s)) continue;
    ++n;
    comp[s] = n - 1;
    std::queue<Voxel> q;
    q.push(s);
    seen.insert(s);
    while (!q.empty()) {
      const Voxel a = q.front();
      q.pop();
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz) {
            const int l1 = std::abs(dx) + std::abs(dy) + std::abs(dz);
            if (l1 == 0 || (c == Connectivity::Six && l1 > 1) ||
                (c == Connectivity::Eighteen && l1 > 2))
              continue;
            const Voxel b = {a[0] + dx, a[1] + dy, a[2] + dz};
            if (occupied.count(b) && !seen.count(b)) {
              seen.insert(b);
              comp[b] = n - 1;
              q.push(b);
            }
          }
    }
  }
  std::vector<int> out;
  for (const Voxel& p : v) out.push_back(comp[p]);
  return out;
}

}  // namespace

TEST_CASE("CCL: face, edge and corner neighbours under 6, 18 and 26-connectivity", "[ccl]") {
  CHECK(seg::forwardNeighbours(Connectivity::Six).size() == 3);
  CHECK(seg::forwardNeighbours(Connectivity::Eighteen).size() == 9);
  CHECK(seg::forwardNeighbours(Connectivity::TwentySix).size() == 13);
  const std::vector<Voxel> face = {{0, 0, 0}, {0, 0, 1}}, edge = {{0, 0, 0}, {1, 0, -1}},
                           corner = {{0, 0, 0}, {-1, 1, 1}};
  CHECK(count(face, Connectivity::Six) == 1);
  CHECK(count(edge, Connectivity::Six) == 2);
  CHECK(count(edge, Connectivity::Eighteen) == 1);
  CHECK(count(corner, Connectivity::Eighteen) == 2);
  CHECK(count(corner, Connectivity::TwentySix) == 1);
}

TEST_CASE("CCL on a hand-made grid: components, numbering and each point's label", "[ccl]") {
  // A: an L of three voxels joined by faces; B: two voxels touching A's end only at a corner;
  // C: an isolated voxel far away; D: two voxels joined by an edge. Points repeat voxels.
  const std::vector<Voxel> v = {
      {0, 0, 0},    {1, 0, 0}, {1, 1, 0}, {1, 1, 0},  // A (points 0-3)
      {2, 2, 1},    {3, 2, 1},                        // B (4-5): corner to A's (1, 1, 0)
      {10, 10, 10},                                   // C (6)
      {5, 0, 0},    {6, 1, 0},                        // D (7-8): edge neighbours
  };
  std::vector<int> comp;
  CHECK(count(v, Connectivity::Six, &comp) == 5);  // A, B, C, D split in two
  CHECK(comp == std::vector<int>{0, 0, 0, 0, 1, 1, 4, 2, 3});
  CHECK(count(v, Connectivity::Eighteen, &comp) == 4);  // D joins
  CHECK(comp == std::vector<int>{0, 0, 0, 0, 1, 1, 3, 2, 2});
  CHECK(count(v, Connectivity::TwentySix, &comp) == 3);  // and B joins A
  CHECK(comp == std::vector<int>{0, 0, 0, 0, 0, 0, 2, 1, 1});
  CHECK(count({}, Connectivity::TwentySix) == 0);
  // Negative and large coordinates pack like any others.
  CHECK(count({{-500000, 3, -7}, {-499999, 4, -6}, {400000, 0, 0}}, Connectivity::TwentySix) == 2);
}

TEST_CASE("CCL labels every point as a breadth-first search does, on random grids", "[ccl]") {
  std::mt19937 rng(8);
  for (int trial = 0; trial < 60; ++trial) {
    std::uniform_int_distribution<int> c(-6, 6);
    std::vector<Voxel> v;
    const int n = 20 + trial * 5;
    for (int i = 0; i < n; ++i) v.push_back({c(rng), c(rng), c(rng) / 2});
    for (auto conn : {Connectivity::Six, Connectivity::Eighteen, Connectivity::TwentySix}) {
      std::vector<int> comp;
      const std::vector<int> bfs = bfsComponents(v, conn);
      CHECK(count(v, conn, &comp) == *std::max_element(bfs.begin(), bfs.end()) + 1);
      CHECK(comp == bfs);
    }
  }
}

TEST_CASE("P2 features of a hand-made cluster", "[ccl][features]") {
  // Level ground, sensor at the origin, cluster 5 m ahead: width across y, depth along x.
  const std::vector<Eigen::Vector3d> pts = {
      {5.0, -0.1, 0.2}, {5.0, 0.1, 0.2}, {5.2, 0.0, 1.05}, {5.0, 0.0, 1.55}};
  const seg::P2Features f = seg::p2Features(pts, 0, 0, 0.25);
  CHECK(f.h == Approx(1.55));
  CHECK(f.w == Approx(0.2));
  CHECK(f.d == Approx(0.2));
  CHECK(f.v == Approx(0.2 * 0.2 * 1.35));
  CHECK(f.lambda == Approx(0.5));  // 1.05 and 1.55 are above h/2 = 0.775
  // Width-height image at 0.25 m: 1 column × 6 rows, rows 0, 3 and 5 occupied.
  CHECK(f.rho == Approx(0.5));
  // A ground-aligned frame of a tilted plane puts a point on it at height 0.
  GroundPlane g;
  g.valid = true;
  const Eigen::Vector3d n = Eigen::Vector3d(-0.1, 0, 1).normalized();
  g.nx = n.x();
  g.ny = n.y();
  g.nz = n.z();
  g.d = -n.z() * 0.3;  // through (0, 0, 0.3)
  const seg::GroundAligned a(g);
  CHECK(a(2, 5, 0.5)(2) == Approx(0).margin(1e-12));  // z = 0.1·2 + 0.3 on the plane
  CHECK(a(2, 5, 1.5)(2) == Approx(n.z()).margin(1e-12));
}

TEST_CASE("shape features tell an upright person from a post and a car", "[ccl][features]") {
  // A person 5 m ahead: legs (two columns 0.2 m apart) to 0.9 m, a 0.4 m-wide torso to 1.5 m, a
  // 0.2 m head to 1.75 m; a post: one thin column to 2.5 m; a car: a 4 x 1.8 m box 0.3-1.4 m.
  std::vector<Eigen::Vector3d> person, post, car;
  for (double z = 0.05; z < 1.76; z += 0.05) {
    const double half = z < 0.9 ? 0.1 : z < 1.5 ? 0.2 : 0.1;
    for (double y = -half; y <= half + 1e-9; y += z < 0.9 ? 0.2 : 0.05) person.push_back({5, y, z});
  }
  for (double z = 0.05; z < 2.5; z += 0.05) post.push_back({5, 0, z});
  for (double z = 0.3; z < 1.41; z += 0.1)
    for (double y = -2; y <= 2; y += 0.1) car.push_back({5, y, z});
  std::vector<double> fp, fo, fc;
  seg::appendShapeFeatures(person, 0, 0, fp);
  seg::appendShapeFeatures(post, 0, 0, fo);
  seg::appendShapeFeatures(car, 0, 0, fc);
  const auto& names = seg::shapeFeatureNames();
  REQUIRE(fp.size() == names.size());
  auto at = [&](const std::vector<double>& f, const std::string& n) {
    return f[std::size_t(std::find(names.begin(), names.end(), n) - names.begin())];
  };
  CHECK(at(fp, "range") == Approx(5));
  CHECK(at(fp, "zmin") == Approx(0.05));
  CHECK(at(fo, "vertical") == Approx(1).margin(1e-6));   // a post's main axis is upright
  CHECK(at(fo, "linearity") == Approx(1).margin(1e-6));  // ... and it is a line
  CHECK(at(fc, "vertical") < 0.1);                       // a car's is along it
  CHECK(at(fp, "w3") == Approx(0.4));                    // the torso slice 1.2-1.6 m
  CHECK(at(fp, "w0") == Approx(0.2));                    // the legs
  CHECK(at(fo, "w2") == Approx(0));
  CHECK(at(fp, "head") == Approx(0.2 / 0.4));  // head 0.2 m over shoulders 0.4 m
  CHECK(at(fo, "head") == Approx(1));
  CHECK(at(fc, "p4") == 0);  // nothing of a car above 1.6 m
  double share = 0;
  for (int k = 0; k < 5; ++k) share += at(fp, "p" + std::to_string(k));
  CHECK(share == Approx(1));
}
