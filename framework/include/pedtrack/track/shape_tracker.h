#pragma once
// Several people tracked by their torso (P1 §III–IV, P0): clusters with points in the torso band
// are assigned to tracks by the Hungarian method on the distance to the prediction; tracks are
// confirmed M-of-N and deleted after a run of misses. What a track estimates and how is its
// TorsoEstimator's: by default an IMM over observation models (shape_imm_estimator.h; `imm_shape`
// (P1) uses three, `kf_bb` and `kf_circle` (P0's baselines) one each), or P0's moving-horizon
// estimator (`mhe_mlesac`).
#include <Eigen/Core>
#include <optional>
#include <random>
#include <vector>

#include "pedtrack/frame.h"
#include "pedtrack/param_table.h"
#include "pedtrack/params.h"
#include "pedtrack/plugin.h"
#include "pedtrack/track/management.h"
#include "pedtrack/track/shape_observation.h"
#include "pedtrack/track/static_scene.h"
#include "pedtrack/track/torso_estimator.h"
#include "pedtrack/track/tracker_base.h"

namespace pedtrack::track {

struct ShapeTrackerParams {
  std::vector<ShapeModel> models{ShapeModel::Ellipse, ShapeModel::Box, ShapeModel::Cog};
  Eigen::MatrixXd transition;  ///< Π (models × models); identity when empty and one model
  ShapeObservationParams observation;
  /// Variance rates of [x, y, θ, v, α, β] per second (P1 Table I's Q per 0.1 s frame × 10).
  Eigen::VectorXd q_rates;
  double q_person = 0.5, q_min = 0.2;  ///< score to start a track / to feed one
  double gate = 1.0;                   ///< largest track–cluster distance (m)
  /// Ours (#45): m added to a tentative track's association cost, so a confirmed track keeps its
  /// person's cluster unless a tentative one is this much nearer. 0: off (P1).
  double tentative_penalty = 0;
  int confirm_hits = 3, confirm_window = 5, max_misses = 10;
  /// > 0: a track is confirmed by accumulated classifier evidence (ScoreEvidence) instead of
  /// M-of-N: log-odds to confirm; a tentative track is deleted when its evidence falls to half
  /// of it below zero or after confirm_window - confirm_hits + 1 misses in a row.
  double confirm_evidence = 0;
  double evidence_miss = -1;  ///< log-odds a missed scan adds to a tentative track's evidence
  double fit_min_height = 0.6, fit_max_height = 2.2;  ///< points the shapes are fitted to (m)
  /// The PC-COG model's fixed alpha (P1); its beta is observation.cog_beta.
  double cog_alpha = 0.17;
  double init_speed_sigma = 1.0;  ///< a new track's speed uncertainty (m/s)
  int birth_points = 10;          ///< torso-band points a cluster needs to start a track (N_b)
  /// Ours (#45): a cluster with fewer torso-band points than birth_points (a person far away or
  /// mostly hidden) also starts a track when it scores at least this and no confirmed track is
  /// within gate of it (0: never, P1). A track fed only by such clusters never keeps the static
  /// grid from learning its returns.
  double small_birth_score = 0;
  double flip_speed = 0.2;  ///< walking "backwards" faster than this turns the heading round (m/s)
  unsigned seed = 1;        ///< RANSAC sampling
  bool report_tentative = false;
  /// Ours (#45): a grid of the fixed frame learns where the clusters' returns stay put (walls,
  /// posts, parked cars, bushes); a cluster with static_share of its torso points on it starts
  /// no track and (static_feeds false) updates none. Returns near any track (confirmed or not)
  /// are not learned.
  bool static_scene = false;
  double static_share = 0.5;
  bool static_feeds = false;  ///< a cluster on the static scene still updates tracks
  /// m: a torso point counts as on the static scene when a static cell lies within this
  /// distance of it. Foliage (hedges, bushes) is porous: each scan's returns scatter through
  /// its depth, and a tentative track on a fragment keeps the returns within
  /// scene.exclusion_radius of it unlearned, so the cells under the next fragment there rarely
  /// become static; the hedge on either side, out of that disc, does. 0: the point's own cell.
  double static_radius = 0.3;
  /// Ours (#45), m: with this ≥ 0, a torso point counts as on the static scene only when its
  /// height lies within this margin of the heights the static cells round it were hit at (the
  /// grid is 2D: without heights a sitter against a bench back, or a person beside a car, is
  /// on static cells). < 0: heights ignored.
  double static_height_margin = -1;
  /// Ours (#45): a confirmed track deleted after max_misses is kept lost (not reported) until it
  /// has been unseen this many seconds; a new track confirmed within its re-identification radius
  /// takes its id back (the identity only: what is reported and when is unchanged). The radius is
  /// `gate` plus reidentify_speed times the time unseen, at most reidentify_max more; distances are
  /// to where the person was last seen and to where their last velocity carried them. 0: off (P1).
  double reidentify_time = 0;
  /// Ours (#45): a cluster scoring at least this, off the static scene and clear of every
  /// confirmed track's gate, within a lost track's re-identification radius (reidentify_time)
  /// brings that track back at once, confirmed, whatever its size. A person hidden behind others
  /// for longer than max_misses scans comes back into view a few returns at a time: such
  /// clusters start no track (birth_points) or one that takes a second to confirm, and the
  /// person went unreported meanwhile. With static_scene on, only within the grid's range
  /// (scene.max_range): beyond it no cluster is known to be static. 0: off (a lost person's id
  /// only returns with a new track's confirmation).
  double revive_score = 0;
  /// Ours (#45): s. A confirmed track that has stayed within unmoved_distance of where it was
  /// born for this long, and whose detections' mean classifier score is below unmoved_score,
  /// no longer keeps the static grid from learning its returns (static_scene): a bin or a post
  /// taken for a person at start-up then becomes static scene, which feeds and starts no track.
  /// A person who walked, or whose detections score as a person's, keeps their place however
  /// long they stand. 0: off (every track keeps the grid off).
  double unmoved_time = 0;
  double unmoved_distance = 0.5;  ///< m, see unmoved_time
  double unmoved_score = 0.8;     ///< see unmoved_time
  double reidentify_speed = 1.0, reidentify_max = 1.0;
  StaticScene::Options scene = [] {
    StaticScene::Options o;
    o.cell = 0.1;  // a torso is ~0.45 x 0.3 m; 3D returns are sparser than a 2D scan's
    o.max_range = 20;
    o.extent = 25;
    return o;
  }();
  ShapeTrackerParams();
};

class ShapeTracker {
 public:
  /// The IMM over `params.models` (std::invalid_argument for an inconsistent Π).
  explicit ShapeTracker(ShapeTrackerParams params);
  /// Tracks estimated by the estimators `estimators` makes (models and Π unused).
  ShapeTracker(ShapeTrackerParams params, TorsoEstimatorFactory estimators);
  /// Predicts, associates the frame's detections (their clusters' points), updates, manages
  /// and appends the reported tracks to f.tracks.
  void process(Frame& f);

  /// The keys every shape tracker plugin declares (association, management, motion noise `q`,
  /// height band, seed) and the groups of the ellipse, box and circle observation models, each
  /// with its rules (a minimum not above its maximum); a plugin appends the groups it observes.
  static const ParamTable<ShapeTrackerParams>& commonTable();
  static const ParamTable<ShapeTrackerParams>& ellipseTable();
  static const ParamTable<ShapeTrackerParams>& boxTable();
  static const ParamTable<ShapeTrackerParams>& circleTable();

 private:
  struct Candidate {
    int detection = -1, cluster = -1;
    double score = 0;
    ShapeCloud cloud;
    std::vector<float> heights;  // of cloud.points, above the ground (none without a cluster)
    Eigen::Vector2d position;
    bool full = false;  // birth_points or more fit-band points: a shape can be fitted
  };
  struct ShapeTrack {
    long id = 0;
    std::unique_ptr<TorsoEstimator> estimate;
    MOfN life;
    ScoreEvidence evidence;
    bool confirmed = false;  // latched
    int misses = 0;
    double score = 0;
    int cluster = -1;
    Eigen::Vector2d seen_at{0, 0};  ///< the estimate's position after its last update
    double last_seen = 0;
    // unmoved_time: where and when it was born, how far it has been from there, and the sum and
    // count of its detections' scores.
    Eigen::Vector2d born_at{0, 0};
    double born = 0, moved = 0, score_sum = 0;
    int score_n = 0;
    bool fed_full = false;  // some cluster of its had birth_points or more fit-band points
  };
  // A confirmed track deleted for misses, kept for re-identification (reidentify_time).
  struct LostTrack {
    long id = 0;
    Eigen::Vector2d seen_at, seen_v;
    double last_seen = 0;
    bool fed_full = false;  // ShapeTrack::fed_full, which a revived track keeps
  };

  std::vector<Candidate> candidates(const Frame& f) const;
  ShapeTrack birth(const Candidate& c);
  // One scan of a track's management (associated with a detection scoring q, or missed): its
  // status by M-of-N or by evidence (confirm_evidence); false when it is deleted.
  bool step(ShapeTrack& t, bool associated, double q) const;
  void report(Frame& f);
  // The lost track nearest q (fixed frame) within its re-identification radius at time t,
  // taken out of lost_; none when there is none.
  std::optional<LostTrack> takeLost(const Eigen::Vector2d& q, double t);
  // Static scene: whether a candidate lies on it, and the frame's returns learned into it.
  bool onStaticScene(const Candidate& c, double t) const;
  void learnStaticScene(const Frame& f);
  // Whether the static grid vouches for c not being static scene (revive_score): it lies within
  // the grid's range, or there is no grid.
  bool vouched(const Candidate& c) const;
  // Whether a confirmed track's estimate lies within radius of q.
  bool nearTrack(const Eigen::Vector2d& q, double radius) const;
  // Whether t keeps the static grid from learning its returns (unmoved_time).
  bool holdsPlace(const ShapeTrack& t, double now) const;

  ShapeTrackerParams p_;
  std::optional<StaticScene> scene_;
  TorsoEstimatorFactory estimators_;
  ScoreHysteresis accept_;
  FrameClock clock_;
  TrackIds ids_;
  std::mt19937 rng_;
  std::vector<ShapeTrack> tracks_;
  std::vector<LostTrack> lost_;
  std::vector<Eigen::Vector2d> obstacles_, people_;  ///< scratch for learnStaticScene
  std::vector<float> obstacle_z_;                    ///< heights of obstacles_, scratch too
};

/// The tracker stage of a shape-tracker plugin: the common parameters read from `params`, then
/// `models` with transition matrix `transition` (imm_shape, kf_bb and kf_circle differ only in
/// these two and in the parameter groups they declare).
class ShapeTrackerStage : public Tracker {
 public:
  explicit ShapeTrackerStage(ShapeTrackerParams params) : tracker_(std::move(params)) {}
  /// A stage whose tracks are estimated by `estimators` (the common parameters still apply).
  ShapeTrackerStage(ShapeTrackerParams params, TorsoEstimatorFactory estimators)
      : tracker_(std::move(params), std::move(estimators)) {}
  void process(Frame& f) override { tracker_.process(f); }

 private:
  ShapeTracker tracker_;
};

}  // namespace pedtrack::track
