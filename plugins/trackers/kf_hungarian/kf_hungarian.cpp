// kf_hungarian: the plain baseline of tracking-by-detection (SORT, AB3DMOT): one constant-
// velocity Kalman filter per person, detections assigned to the predictions by the Hungarian
// method within a distance gate, tracks confirmed by M-of-N hits and deleted after a few misses.
// Built from the framework's parts only; no paper's method, the yardstick for those that are.
#include <cmath>
#include <memory>
#include <vector>

#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"
#include "pedtrack/track/box_filter.h"
#include "pedtrack/track/gnn.h"
#include "pedtrack/track/kalman.h"
#include "pedtrack/track/management.h"
#include "pedtrack/track/motion_models.h"
#include "pedtrack/track/tracker_base.h"

namespace pedtrack::kfhungarian {
namespace {

using namespace pedtrack::track;

struct Settings {
  double sigma = 0.15;           // m, a detection's x and y
  double q = 1;                  // m²/s³, acceleration noise
  double init_speed_sigma = 1;   // m/s
  double gate = 2;               // m, largest distance of a detection from a prediction
  int min_hits = 3, window = 3;  // confirmed by min_hits associations within its first window
  int max_misses = 2;
  double min_score = 0;
  bool report_coasting = true, report_tentative = false;
};

const ParamTable<Settings>& table() {
  using P = Settings;
  static const auto t =
      ParamTable<P>()
          .real(&P::sigma, "sigma", "m", 1e-4, 10, "standard deviation of a detection's x and y")
          .real(&P::q, "q", "m^2/s^3", 0, 1e4, "acceleration noise of the constant-velocity model")
          .real(&P::init_speed_sigma, "init_speed_sigma", "m/s", 0.01, 100,
                "standard deviation of a new track's velocity (it starts at rest)")
          .real(&P::gate, "gate", "m", 0.01, 100,
                "a detection farther than this from a track's prediction is not its")
          .integer(&P::min_hits, "min_hits", "", 1, 32,
                   "associations that confirm a track (within its first `window` frames)")
          .integer(&P::window, "window", "", 1, 32, "frames a new track has to reach min_hits")
          .integer(&P::max_misses, "max_misses", "", 0, 1000,
                   "frames in a row without a detection after which a confirmed track is deleted")
          .real(&P::min_score, "min_score", "", -1e9, 1e9, "detections scoring below are ignored")
          .boolean(&P::report_coasting, "report_coasting",
                   "write confirmed tracks also in frames they had no detection (predicted)")
          .boolean(&P::report_tentative, "report_tentative", "also write tentative tracks")
          .check(&P::window, [](const P& p) {
            return p.window < p.min_hits
                       ? "must be at least min_hits (" + std::to_string(p.min_hits) + ")"
                       : std::string();
          });
  return t;
}

struct KfTrack {
  long id = 0;
  Gaussian g;
  MOfN life{3, 3, 2};
  bool updated = false;
  int cluster = -1;
  BoxFilter box;
};

class KfHungarian : public Tracker {
 public:
  explicit KfHungarian(const PluginContext& ctx)
      : s_(table().read(ctx.params)), model_(s_.q), meas_(positionMeasurement(4, s_.sigma)) {}

  void process(Frame& f) override {
    const double dt = clock_.step(f.t);
    for (KfTrack& t : tracks_) kalmanPredict(t.g, model_, dt);
    std::vector<const Detection*> dets;
    for (const Detection& d : f.detections)
      if (d.score >= s_.min_score) dets.push_back(&d);
    const Assignment a = gnnAssociate(
        int(tracks_.size()), int(dets.size()),
        [&](int t, int i) {
          return std::hypot(dets[std::size_t(i)]->x - tracks_[std::size_t(t)].g.x(0),
                            dets[std::size_t(i)]->y - tracks_[std::size_t(t)].g.x(1));
        },
        s_.gate);
    std::vector<char> taken(dets.size(), 0);
    std::vector<KfTrack> kept;
    for (std::size_t t = 0; t < tracks_.size(); ++t) {
      KfTrack& tr = tracks_[t];
      const int i = a.row_to_col.empty() ? -1 : a.row_to_col[t];
      tr.updated = i >= 0;
      tr.cluster = -1;
      if (i >= 0) {
        const Detection& d = *dets[std::size_t(i)];
        taken[std::size_t(i)] = 1;
        kalmanUpdate(tr.g, meas_, Eigen::Vector2d(d.x, d.y));
        tr.box.update(d.box, d.yaw, d.score, 1);
        tr.cluster = d.cluster;
      }
      if (tr.life.step(tr.updated) != TrackStatus::Deleted) kept.push_back(std::move(tr));
    }
    tracks_ = std::move(kept);
    for (std::size_t i = 0; i < dets.size(); ++i) {
      if (taken[i]) continue;
      const Detection& d = *dets[i];
      KfTrack t{ids_.next(), {}, MOfN(s_.min_hits, s_.window, s_.max_misses), true, d.cluster, {}};
      const double v = s_.init_speed_sigma * s_.init_speed_sigma, p = s_.sigma * s_.sigma;
      t.g.x = Eigen::Vector4d(d.x, d.y, 0, 0);
      t.g.P = Eigen::Vector4d(p, p, v, v).asDiagonal();
      t.life.step(true);
      t.box.update(d.box, d.yaw, d.score, 1);
      tracks_.push_back(std::move(t));
    }
    for (const KfTrack& t : tracks_) {
      const bool confirmed = t.life.status() == TrackStatus::Confirmed;
      if (!(confirmed ? t.updated || s_.report_coasting : s_.report_tentative)) continue;
      Track row = trackRow(t.id, t.g, model_);
      row.score = t.box.score;
      row.status = !confirmed ? "tentative" : t.updated ? "confirmed" : "coasting";
      row.cluster = t.cluster;
      row.box = t.box.box;
      if (row.box.known()) row.yaw = t.box.yaw;  // a 3D detector's heading, not the velocity's
      f.tracks.push_back(std::move(row));
    }
  }

 private:
  Settings s_;
  ConstantVelocity model_;
  LinearMeasurement meas_;
  FrameClock clock_;
  TrackIds ids_;
  std::vector<KfTrack> tracks_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Tracker;
  d.doc = "Baseline: constant-velocity Kalman filters, Hungarian assignment, M-of-N confirmation";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<KfHungarian>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::kfhungarian

PEDTRACK_PLUGIN("kf_hungarian", pedtrack::kfhungarian::describe)
