// Crowd splitting (voxel_ccl's split): hand-built point sets whose answer is known — two people
// shoulder to shoulder, a child beside an adult, one person with a raised arm, a pram or a bag,
// a flat-topped wall, a bush cut by the sensor's top beam, and heads closer than a shoulder.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <set>

#include "voxel_ccl/crowd_split.h"

using pedtrack::voxelccl::CrowdSplitParams;
using pedtrack::voxelccl::splitCrowd;
using Points = std::vector<Eigen::Vector3d>;

namespace {

const Eigen::Vector3d kSensor(0, 0, 1.0);  // a VLP-16 1 m above the ground at the origin

// A person as a sensor sees one: returns on the near half of an elliptic body (an adult's
// torso 0.22 x 0.14 m semi-axes, a child's in proportion) every 5 cm up to the shoulders, and
// a head (0.09 m) up to `height`.
void addPerson(Points& p, double x, double y, double height) {
  const double shoulder = 0.82 * height;
  for (double z = 0.05; z <= height; z += 0.05) {
    const bool head = z > shoulder;
    const double scale = height / 1.75;
    const double a = head ? 0.09 : 0.22 * scale, b = head ? 0.09 : 0.14 * scale;
    for (double t = -1.5; t <= 1.5; t += 0.15)  // the half facing the sensor at -x
      p.emplace_back(x - b * std::cos(t), y + a * std::sin(t), z);
  }
}

std::set<int> partsOf(const std::vector<int>& part, std::size_t from, std::size_t to) {
  return {part.begin() + long(from), part.begin() + long(to)};
}

}  // namespace

TEST_CASE("two adults shoulder to shoulder are split, each whole", "[crowd_split]") {
  Points p;
  addPerson(p, 5, 0, 1.75);
  const std::size_t first = p.size();
  addPerson(p, 5, 0.5, 1.70);  // torsos 0.06 m apart: one voxel component
  std::vector<int> part;
  REQUIRE(splitCrowd(p, kSensor, CrowdSplitParams{}, part) == 2);
  const auto a = partsOf(part, 0, first), b = partsOf(part, first, p.size());
  CHECK(a.size() == 1);
  CHECK(b.size() == 1);
  CHECK(*a.begin() != *b.begin());
}

TEST_CASE("a child beside an adult is a person of their own", "[crowd_split]") {
  Points p;
  addPerson(p, 4, 0, 1.80);
  const std::size_t first = p.size();
  addPerson(p, 4, 0.5, 1.15);
  std::vector<int> part;
  REQUIRE(splitCrowd(p, kSensor, CrowdSplitParams{}, part) == 2);
  CHECK(partsOf(part, 0, first).size() == 1);
  CHECK(partsOf(part, first, p.size()).size() == 1);
  // Below min_head the child is not a head: one cluster, as P2 makes it.
  CrowdSplitParams tall;
  tall.min_head = 1.3;
  CHECK(splitCrowd(p, kSensor, tall, part) == 1);
}

TEST_CASE("one person with a raised arm, a pram or a bag stays one", "[crowd_split]") {
  Points p;
  addPerson(p, 5, 0, 1.75);
  for (double z = 1.0; z <= 1.55; z += 0.05) p.emplace_back(4.9, 0.3, z);  // arm, to the side
  // A pram ahead: a box 0.6 m long up to its handle at 1.0 m, held at the person's front.
  const std::size_t person = p.size();
  for (double x = 4.1; x <= 4.86; x += 0.05)
    for (double y = -0.2; y <= 0.2; y += 0.05) p.emplace_back(x, y, 1.0);
  std::vector<int> part;
  CHECK(splitCrowd(p, kSensor, CrowdSplitParams{}, part) == 1);
  CHECK(partsOf(part, 0, p.size()) == std::set<int>{0});
  // Let go of, the pram is an object of its own (the classifier's to judge); the person,
  // arm included, stays whole.
  p.erase(p.begin() + long(person), p.end());
  for (double x = 4.1; x <= 4.6; x += 0.05)
    for (double y = -0.2; y <= 0.2; y += 0.05) p.emplace_back(x, y, 1.0);
  CHECK(splitCrowd(p, kSensor, CrowdSplitParams{}, part) == 2);
  CHECK(partsOf(part, 0, person).size() == 1);
  // A raised hand at 1.70 m, 0.3 m above the shoulder (more than head_dip of its height), is
  // a peak of its own. The component is narrower than min_extent, so it is one person anyway;
  // with that rule loosened, the hand is nearer the head than min_spacing.
  Points q;
  addPerson(q, 5, 0, 1.75);
  for (double z = 1.3; z <= 1.705; z += 0.05) q.emplace_back(4.95, 0.32, z);
  CHECK(splitCrowd(q, kSensor, CrowdSplitParams{}, part) == 1);
  CrowdSplitParams loose;
  loose.min_extent = 0.3;
  CHECK(splitCrowd(q, kSensor, loose, part) == 1);
  loose.min_spacing = 0.2;  // control: without the spacing rule the hand is a person
  CHECK(splitCrowd(q, kSensor, loose, part) == 2);
}

TEST_CASE("a flat-topped wall and a hedge too wide stay whole", "[crowd_split]") {
  Points wall;
  for (double y = -1.5; y <= 1.5; y += 0.05)
    for (double z = 0.1; z <= 2.2; z += 0.1) wall.emplace_back(6, y, z);
  std::vector<int> part;
  CHECK(splitCrowd(wall, kSensor, CrowdSplitParams{}, part) == 1);
  // Bumps 0.5 m high on a 7 m hedge would be heads; it is wider than max_extent.
  Points hedge;
  for (double y = -3.5; y <= 3.5; y += 0.05)
    for (double z = 0.1; z <= 1.2 + 0.5 * (std::fmod(y + 3.5, 1.0) < 0.2); z += 0.1)
      hedge.emplace_back(6, y, z);
  CHECK(splitCrowd(hedge, kSensor, CrowdSplitParams{}, part) == 1);
  CrowdSplitParams wide;
  wide.max_extent = 10;
  CHECK(splitCrowd(hedge, kSensor, wide, part) > 1);
}

TEST_CASE("heads closer than min_spacing are one person's", "[crowd_split]") {
  Points p;
  addPerson(p, 5, 0, 1.75);
  addPerson(p, 5, 0.5, 1.70);
  std::vector<int> part;
  CrowdSplitParams close;
  close.min_spacing = 0.6;
  CHECK(splitCrowd(p, kSensor, close, part) == 1);
  CHECK(splitCrowd(p, kSensor, CrowdSplitParams{}, part) == 2);  // 0.5 m apart: two
  CHECK(splitCrowd({}, kSensor, CrowdSplitParams{}, part) == 1);
  CHECK(part.empty());
}

TEST_CASE("peaks the sensor's top beam cut are no heads", "[crowd_split]") {
  // Two adults 1.2 m from a VLP-16 1 m up: its top beam (15 deg) reaches 1.32 m there, so all
  // it sees of them ends at that height. Without the limit the cut tops look like two heads.
  Points p;
  for (const double y : {-0.35, 0.35}) {
    Points one;
    addPerson(one, 1.2, y, 1.75);
    for (const auto& q : one)
      if (std::atan2(q.z() - 1.0, std::hypot(q.x(), q.y())) <= 15 * M_PI / 180) p.push_back(q);
  }
  std::vector<int> part;
  CHECK(splitCrowd(p, kSensor, CrowdSplitParams{}, part) == 2);
  CrowdSplitParams vlp16;
  vlp16.top_elevation = 15;
  CHECK(splitCrowd(p, kSensor, vlp16, part) == 1);
  // Farther out the same two people are seen whole and split.
  Points far;
  addPerson(far, 6, -0.25, 1.75);
  addPerson(far, 6, 0.25, 1.7);
  CHECK(splitCrowd(far, kSensor, vlp16, part) == 2);
}

TEST_CASE("non-finite points leave a component whole", "[crowd_split]") {
  Points p;
  addPerson(p, 5, 0, 1.75);
  addPerson(p, 5, 0.5, 1.70);
  p[7].x() = std::numeric_limits<double>::quiet_NaN();
  std::vector<int> part;
  CHECK(splitCrowd(p, kSensor, CrowdSplitParams{}, part) == 1);
  CHECK(partsOf(part, 0, p.size()) == std::set<int>{0});
}
