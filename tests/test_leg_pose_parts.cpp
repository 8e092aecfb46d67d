// P3's leg-pair pose parts against known values: the gait fit (eq. 3) recovers the parameters of
// a synthetic gait with both solvers and keeps P3's bounds, the zoning (§2.3) gives the expected
// zone and orientation on hand-made leg pairs, the hidden leg follows eq. 6-7, and the pose
// filter's noise is eq. 4's. The estimator on synthetic walks: test_leg_pose_estimator.cpp; the
// multi-person tracker: test_legs.cpp.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "leg_walker.h"
#include "pedtrack/ipopt/gait_fit.h"
#include "pedtrack/track/gait_model.h"
#include "pedtrack/track/leg_pose_estimator.h"
#include "pedtrack/track/leg_zoning.h"
#include "pedtrack/track/motion_models.h"

using namespace pedtrack::track;
using Catch::Detail::Approx;
using pedtrack::test::angleDiff;

namespace {

std::vector<gait::Sample> synthetic(double l0, double f, double phi_now, double b, int n,
                                    double t_now, double dt) {
  std::vector<gait::Sample> s;
  for (int j = 0; j < n; ++j) {  // newest first
    const double t = t_now - j * dt;
    s.push_back({t, l0 * std::cos(2 * M_PI * f * (t - t_now) + phi_now) + b});
  }
  return s;
}

}  // namespace

TEST_CASE("the gait fit recovers known L0, f, phi and b", "[legs]") {
  const gait::Bounds bounds;
  const auto s = synthetic(0.3, 0.9, 1.2, 0.05, 20, 1000.0, 0.1);
  const gait::Params vp = gait::fitVarPro(s, bounds);
  REQUIRE(vp.valid);
  CHECK(vp.l0 == Approx(0.3).margin(1e-4));
  CHECK(vp.f == Approx(0.9).margin(1e-4));
  CHECK(angleDiff(vp.phi, 1.2) < 1e-3);
  CHECK(vp.b == Approx(0.05).margin(1e-4));
  CHECK(vp.at(1000.1) == Approx(0.3 * std::cos(2 * M_PI * 0.9 * 0.1 + 1.2) + 0.05).margin(1e-4));
  // Ipopt from the middle of the bounds finds the same optimum.
  const gait::Params ip = gait::fitIpopt(s, bounds, gait::Params{});
  REQUIRE(ip.valid);
  CHECK(ip.l0 == Approx(0.3).margin(1e-3));
  CHECK(ip.f == Approx(0.9).margin(1e-3));
  CHECK(angleDiff(ip.phi, 1.2) < 1e-2);
  CHECK(ip.b == Approx(0.05).margin(1e-3));
}

TEST_CASE("the gait fit keeps P3's bounds", "[legs]") {
  const gait::Bounds bounds;
  // A 0.8 m amplitude with a negative offset: both outside eq. 3's box.
  const auto s = synthetic(0.8, 1.0, 0.0, -0.2, 20, 5.0, 0.1);
  const gait::Params vp = gait::fitVarPro(s, bounds);
  REQUIRE(vp.valid);
  CHECK(vp.l0 <= bounds.l0_max + 1e-12);
  CHECK(vp.b >= bounds.b_min - 1e-12);
  CHECK(vp.f >= bounds.f_min);
  CHECK(vp.f <= bounds.f_max);
  CHECK_FALSE(gait::fitVarPro(std::vector<gait::Sample>(4), bounds).valid);
}

TEST_CASE("zoning gives the expected zone and orientation", "[legs]") {
  const ZoningParams zp;  // band ±15 % of W0, side step |d_u| ≤ 0.3 W0, slight turn ≤ 45°
  const double w0 = 0.2;
  // Facing +x (yaw 0): left leg at +y. Walking straight: frontal W0, sagittal swing.
  ZoneResult z = zoneOrientation({0.15, 0.1}, {-0.15, -0.1}, 0, w0, zp);
  CHECK(z.zone == MotionZone::GoStraight);
  CHECK(z.frontal == Approx(0.2));
  CHECK(z.sagittal == Approx(0.3));
  // The same legs seen 5° off: the band is kept, the two-line refinement measures the 5°.
  z = zoneOrientation({0.15, 0.1}, {-0.15, -0.1}, 5 * M_PI / 180, w0, zp);
  CHECK(z.zone == MotionZone::GoStraight);
  CHECK(angleDiff(z.yaw, 0) < 1e-9);
  ZoningParams literal = zp;
  literal.refine_straight = false;  // P3: constant orientation in the go-straight zone
  CHECK(angleDiff(zoneOrientation({0.15, 0.1}, {-0.15, -0.1}, 5 * M_PI / 180, w0, literal).yaw,
                  5 * M_PI / 180) < 1e-12);
  // Legs apart side by side, 0.4 m: a side step, orientation kept.
  z = zoneOrientation({0, 0.2}, {0, -0.2}, 0, w0, zp);
  CHECK(z.zone == MotionZone::Sideways);
  CHECK(z.yaw == 0);
  // A person facing 20° with legs W0 apart frontally and 0.3 m sagittally, seen from yaw 0:
  // the frontal distance leaves the band, two lines W0 apart give the 20° turn.
  const double a = 20 * M_PI / 180;
  const Eigen::Vector2d fwd(std::cos(a), std::sin(a)), left(-std::sin(a), std::cos(a));
  const Eigen::Vector2d d = 0.3 * fwd + w0 * left;
  z = zoneOrientation(0.5 * d, -0.5 * d, 0, w0, zp);
  CHECK(z.zone == MotionZone::SlightTurn);
  CHECK(z.yaw == Approx(a).margin(1e-9));
  // Turned 90° in place (legs side by side along x): the sagittal axis is perpendicular to them.
  z = zoneOrientation({0.1, 0}, {-0.1, 0}, 0, w0, zp);
  CHECK(z.zone == MotionZone::TurnInPlace);
  CHECK(z.yaw == Approx(-M_PI / 2));
  // Legs merged into one place: no orientation.
  CHECK_FALSE(zoneOrientation({0.01, 0}, {0, 0}, 0, w0, zp).observable);
}

TEST_CASE("a hidden leg follows eq. 6 and 7", "[legs]") {
  const Eigen::Vector2d sensor(0, 0), visible(2, 0), predicted(2, 0.3);
  const double w0 = 0.2;
  // Eq. 6: R_o = S + (W0/|SL| + 1) SL = (2.2, 0). Eq. 7 with α = e^{−T_o}.
  for (double t_o : {0.0, 0.1, 1.0, 10.0}) {
    const double alpha = std::exp(-t_o);
    const Eigen::Vector2d r = LegPoseEstimator::hiddenLeg(sensor, visible, predicted, w0, t_o);
    CHECK(r.x() == Approx(alpha * 2 + (1 - alpha) * 2.2));
    CHECK(r.y() == Approx(alpha * 0.3).margin(1e-12));
  }
}

TEST_CASE("P3's pose filter noise is the discrete white-noise acceleration of eq. 4", "[legs]") {
  const PoseConstantAcceleration m(100, 100, M_PI * M_PI);
  const Eigen::MatrixXd Q = m.noise(Eigen::VectorXd::Zero(9), 0.1);
  CHECK(Q(0, 0) == Approx(100 * 0.005 * 0.005));  // (Δt²/2)² σ²
  CHECK(Q(0, 3) == Approx(100 * 0.005 * 0.1));
  CHECK(Q(8, 8) == Approx(M_PI * M_PI));
  CHECK(Q(0, 1) == 0);  // axes independent
  const Eigen::MatrixXd F = m.jacobian(Eigen::VectorXd::Zero(9), 0.1);
  CHECK(F(0, 6) == Approx(0.005));
  CHECK(F(3, 6) == Approx(0.1));
}
