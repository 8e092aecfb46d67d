// ekf_motion (P2 §3.4–3.5): the motion-based second stage of P2's person classifier. Objects
// the appearance classifier scores Q ≥ Q_P start a one-step track in T; associated again in the
// next frame, the track is promoted to T_EKF with an extended Kalman filter over [x, y, θ, v]
// (the unicycle of eq. 13, Jacobians of eq. 15); unassociated, it is deleted. Established tracks
// also accept objects with Q > Q_min (hysteresis), so a person the appearance classifier loses
// (partly occluded, at the edge of the view) stays a person. T_EKF tracks are the persons.
#include <cmath>
#include <memory>
#include <vector>

#include "pedtrack/errors.h"
#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"
#include "pedtrack/track/box_filter.h"
#include "pedtrack/track/gnn.h"
#include "pedtrack/track/kalman.h"
#include "pedtrack/track/management.h"
#include "pedtrack/track/tracker_base.h"

namespace pedtrack::ekfmotion {
namespace {

using namespace pedtrack::track;

struct MotionTrack {
  long id = 0;
  bool established = false;                   // in T_EKF (else in T: one detection, no filter yet)
  Gaussian g;                                 // EKF state [x, y, θ, v] once established
  double last_x = 0, last_y = 0, last_t = 0;  // the last associated detection
  double score = 0;
  int misses = 0;
  int cluster = -1;
  BoxFilter box;  // a 3D detector's box, smoothed
};

struct EkfMotionParams {
  double q_person = 0.5;      // P2's Q_P
  double q_min = 0.0;         // P2's Q_min
  double max_distance = 1.0;  // m, association gate
  double sigma = 0.1;         // m, detection position noise
  double q_theta = 1.0;       // rad²/s, heading random walk
  double q_v = 0.5;           // m²/s³, speed random walk
  double max_speed = 3.0;     // m/s, cap of finite-difference speeds
  int max_misses = 0;         // P2 deletes an unassociated track at once
  bool report_tentative = false;
};

const ParamTable<EkfMotionParams>& table() {
  using P = EkfMotionParams;
  static const auto t =
      ParamTable<P>()
          .real(&P::q_person, "q_person", "", 0, 1,
                "Q_P: detections scoring at least this are persons (start and feed tracks)")
          .real(&P::q_min, "q_min", "", 0, 1,
                "Q_min: an established track also takes detections scoring above this")
          .real(&P::max_distance, "max_distance", "m", 0.01, 20,
                "association gate: largest distance from a track's prediction")
          .real(&P::sigma, "sigma", "m", 1e-4, 10,
                "detection position noise (standard deviation of x and y)")
          .real(&P::q_theta, "q_theta", "rad^2/s", 0, 1e4,
                "heading random-walk rate (process noise of theta)")
          .real(&P::q_v, "q_v", "m^2/s^3", 0, 1e4, "speed random-walk rate (process noise of v)")
          .real(&P::max_speed, "max_speed", "m/s", 0.1, 50,
                "finite-difference speeds are capped here (a pedestrian's top speed)")
          .integer(&P::max_misses, "max_misses", "", 0, 1000,
                   "frames an established track survives without association (P2: 0)")
          .boolean(&P::report_tentative, "report_tentative",
                   "also write the one-step tracks of T to tracks.csv (status tentative)")
          .check(&P::q_min, [](const P& p) {
            return p.q_min > p.q_person
                       ? "must not exceed q_person (" + shortestNumber(p.q_person) + ")"
                       : std::string();
          });
  return t;
}

class EkfMotion : public Tracker {
 public:
  explicit EkfMotion(const PluginContext& ctx) : EkfMotion(table().read(ctx.params)) {}
  explicit EkfMotion(const EkfMotionParams& p)
      : model_(p.q_theta, p.q_v),
        max_distance_(p.max_distance),
        sigma_(p.sigma),
        max_speed_(p.max_speed),
        max_misses_(p.max_misses),
        report_tentative_(p.report_tentative) {
    gate_.q_person = p.q_person;
    gate_.q_min = p.q_min;
  }

  void process(Frame& f) override {
    const double dt = clock_.step(f.t);
    for (MotionTrack& t : tracks_)
      if (t.established) kalmanPredict(t.g, model_, dt);
    const std::size_t M = f.detections.size();
    std::vector<char> taken(M, 0);

    // 1. T_EKF tracks: persons (Q ≥ Q_P) first, then the hysteresis band Q_min < Q < Q_P.
    std::vector<int> ekf, young;
    for (std::size_t k = 0; k < tracks_.size(); ++k)
      (tracks_[k].established ? ekf : young).push_back(int(k));
    std::vector<char> updated(tracks_.size(), 0);
    for (bool persons : {true, false}) {
      std::vector<int> open;
      for (int k : ekf)
        if (!updated[k]) open.push_back(k);
      associate(f, open, taken, updated, [&](double q) {
        return persons ? q >= gate_.q_person : gate_.accepts(q, true) && q < gate_.q_person;
      });
    }
    // 2. T tracks: persons remaining; success promotes the track to T_EKF.
    associate(f, young, taken, updated, [&](double q) { return q >= gate_.q_person; });

    // Deletion: P2 deletes an unassociated track at once (max_misses = 0).
    std::vector<MotionTrack> kept;
    for (std::size_t k = 0; k < tracks_.size(); ++k) {
      MotionTrack& t = tracks_[k];
      if (!updated[k]) {
        t.cluster = -1;
        if (!t.established || ++t.misses > max_misses_) continue;
      }
      kept.push_back(std::move(t));
    }
    tracks_ = std::move(kept);
    // 3. Persons no track took start new tracks in T.
    for (std::size_t i = 0; i < M; ++i) {
      const Detection& d = f.detections[i];
      if (taken[i] || !(d.score >= gate_.q_person)) continue;
      MotionTrack t;
      t.id = ids_.next();
      t.last_x = d.x, t.last_y = d.y, t.last_t = f.t;
      t.score = d.score;
      t.cluster = d.cluster;
      t.box.update(d.box, d.yaw, d.score, 1);
      tracks_.push_back(t);
    }
    report(f);
  }

 private:
  // GNN on the distance to each track's prediction (P2: "a maximum distance threshold").
  template <class Accept>
  void associate(Frame& f, const std::vector<int>& which, std::vector<char>& taken,
                 std::vector<char>& updated, Accept accept) {
    if (which.empty()) return;
    const auto& dets = f.detections;
    const Assignment a = gnnAssociate(
        int(which.size()), int(dets.size()),
        [&](int r, int i) {
          if (taken[i] || !accept(dets[i].score)) return std::nan("");
          const MotionTrack& t = tracks_[which[r]];
          const double px = t.established ? t.g.x(0) : t.last_x;
          const double py = t.established ? t.g.x(1) : t.last_y;
          return std::hypot(dets[i].x - px, dets[i].y - py);
        },
        max_distance_);
    for (const auto& [r, i] : a.pairs()) {
      taken[i] = 1;
      updated[which[r]] = 1;
      measure(tracks_[which[r]], dets[i], f.t);
    }
  }

  // z = [x, y, θ, v] (eq. 16): the detection's position, heading and speed from the finite
  // difference to the previous associated detection. R follows from the position noise σ: the
  // difference of two positions has variance 2σ², so σ_v² = 2σ²/Δt² and σ_θ² = 2σ²/d² (capped).
  void measure(MotionTrack& t, const Detection& d, double now) {
    const double dt = std::max(now - t.last_t, 1e-3);
    const double dx = d.x - t.last_x, dy = d.y - t.last_y, dist = std::hypot(dx, dy);
    const double v = std::min(dist / dt, max_speed_);
    const double theta = std::atan2(dy, dx);
    const double var_p = sigma_ * sigma_;
    const double var_theta = std::min(2 * var_p / std::max(dist * dist, 1e-9), M_PI * M_PI);
    LinearMeasurement m;
    m.H = Eigen::MatrixXd::Identity(4, 4);
    m.R = Eigen::Vector4d(var_p, var_p, var_theta, 2 * var_p / (dt * dt)).asDiagonal();
    m.angle_rows = {2};
    const Eigen::Vector4d z(d.x, d.y, theta, v);
    if (!t.established) {
      t.g.x = z;  // promotion to T_EKF: the filter starts at the measurement
      t.g.P = m.R;
      t.established = true;
    } else {
      kalmanUpdate(t.g, m, z);
      t.g.x(2) = wrapAngle(t.g.x(2));
      if (t.g.x(3) < 0) t.g.x(3) = -t.g.x(3), t.g.x(2) = wrapAngle(t.g.x(2) + M_PI);
    }
    t.last_x = d.x, t.last_y = d.y, t.last_t = now;
    t.score = d.score;
    t.misses = 0;
    t.cluster = d.cluster;
    t.box.update(d.box, d.yaw, d.score, 1);
  }

  void report(Frame& f) {
    for (const MotionTrack& t : tracks_) {
      if (!t.established && !report_tentative_) continue;
      Track row;
      if (t.established) {
        row = trackRow(t.id, t.g, model_);
        // trackRow's covariance is the position block of [x, y, θ, v]: what tracks.csv wants.
        row.yaw = t.g.x(2);
      } else {
        row.id = t.id;
        row.x = t.last_x;
        row.y = t.last_y;
      }
      row.score = t.score;
      row.status = t.established ? (t.misses ? "coasting" : "confirmed") : "tentative";
      row.cluster = t.cluster;
      row.box = t.box.box;
      if (row.box.known()) row.yaw = t.box.yaw;  // a 3D detector's heading, not the velocity's
      f.tracks.push_back(std::move(row));
    }
  }

  Unicycle model_;
  ScoreHysteresis gate_;
  double max_distance_, sigma_, max_speed_;
  int max_misses_;
  bool report_tentative_;
  FrameClock clock_;
  TrackIds ids_;
  std::vector<MotionTrack> tracks_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Tracker;
  d.doc =
      "P2's motion classifier: one-step tracks promoted to EKF tracks [x,y,theta,v], Q "
      "hysteresis";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<EkfMotion>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::ekfmotion

PEDTRACK_PLUGIN("ekf_motion", pedtrack::ekfmotion::describe)
