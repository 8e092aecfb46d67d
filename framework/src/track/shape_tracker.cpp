#include "pedtrack/track/shape_tracker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "pedtrack/track/gnn.h"
#include "pedtrack/track/shape_imm_estimator.h"

namespace pedtrack::track {

ShapeTrackerParams::ShapeTrackerParams() {
  // P1 Table I lists Q per 0.1 s frame; the heading and speed random walks get its unit
  // entries, the semi-axes its 10⁻⁴ (see README "Torso shape tracking").
  q_rates = (Eigen::VectorXd(6) << 0, 0, 10, 10, 1e-3, 1e-3).finished();
  transition = (Eigen::MatrixXd(3, 3) << 0.99, 0.005, 0.005, 0.005, 0.99, 0.005, 0.005, 0.005, 0.99)
                   .finished();
}

ShapeTracker::ShapeTracker(ShapeTrackerParams params)
    : ShapeTracker(params, immTorsoEstimators(params)) {}

ShapeTracker::ShapeTracker(ShapeTrackerParams params, TorsoEstimatorFactory estimators)
    : p_(std::move(params)), estimators_(std::move(estimators)), rng_(p_.seed) {
  accept_.q_person = p_.q_person;
  accept_.q_min = p_.q_min;
  if (p_.static_scene) {
    StaticScene::Options o = p_.scene;
    o.extent = std::max(o.extent, o.max_range + 5);  // the grid holds every return learned
    scene_.emplace(o);
  }
}

std::vector<ShapeTracker::Candidate> ShapeTracker::candidates(const Frame& f) const {
  std::vector<Candidate> out;
  const auto& cloud = f.cloud();
  const auto& xs = cloud.getPointsBufferRef_x();
  const auto& ys = cloud.getPointsBufferRef_y();
  const Eigen::Vector2d origin(f.sensor_pose.x(), f.sensor_pose.y());
  const double c = std::cos(f.robot_pose.yaw()), s = std::sin(f.robot_pose.yaw());
  const double rx = f.robot_pose.x(), ry = f.robot_pose.y();
  for (std::size_t i = 0; i < f.detections.size(); ++i) {
    const Detection& d = f.detections[i];
    if (!accept_.accepts(d.score, true)) continue;
    Candidate cand;
    cand.detection = int(i);
    cand.cluster = d.cluster;
    cand.score = d.score;
    cand.cloud.origin = origin;
    if (d.cluster >= 0 && std::size_t(d.cluster) < f.clusters.size()) {
      // The torso band (P0 drops the legs below 0.6 m). A cluster with no point in it (a low
      // box, a kerb, the top of a hedge) has no torso: it is no person, whatever its score.
      for (std::uint32_t k : f.clusters[d.cluster].indices) {
        if (k >= xs.size()) continue;
        const double h = f.heightOf(k);
        if (h < p_.fit_min_height || h > p_.fit_max_height) continue;
        // Robot frame → fixed frame (the robot's planar pose; its tilt is the ground stage's).
        cand.cloud.points.emplace_back(rx + c * xs[k] - s * ys[k], ry + s * xs[k] + c * ys[k]);
        cand.heights.push_back(float(h));
      }
      if (cand.cloud.points.empty()) continue;
    } else {
      cand.cloud.points.emplace_back(d.x, d.y);  // a detection without points: its position
    }
    cand.position = fit::centroidBehindSurface(cand.cloud.points, origin, p_.observation.cog_beta);
    cand.full = int(cand.cloud.points.size()) >= p_.birth_points;
    out.push_back(std::move(cand));
  }
  return out;
}

ShapeTracker::ShapeTrack ShapeTracker::birth(const Candidate& c) {
  ShapeTrack t{ids_.next(), estimators_(c.cloud, c.position, rng_),
               MOfN(p_.confirm_hits, p_.confirm_window, p_.max_misses),
               ScoreEvidence(p_.confirm_evidence, p_.evidence_miss)};
  step(t, true, c.score);
  t.score = c.score;
  t.cluster = c.cluster;
  return t;
}

void ShapeTracker::process(Frame& f) {
  const double dt = clock_.step(f.t);
  // The fixed frame jumped by an unknown amount: what the grid learned, and where lost people
  // were last seen, may lie anywhere.
  if (f.motion_unknown) {
    if (scene_) scene_->forget();
    lost_.clear();
  }
  // Lost tracks unseen longer than reidentify_time are gone for good.
  lost_.erase(
      std::remove_if(lost_.begin(), lost_.end(),
                     [&](const LostTrack& l) { return f.t - l.last_seen > p_.reidentify_time; }),
      lost_.end());
  for (ShapeTrack& t : tracks_) t.estimate->predict(dt);
  const std::vector<Candidate> cands = candidates(f);
  std::vector<Eigen::Vector2d> predicted;
  for (const ShapeTrack& t : tracks_) predicted.push_back(t.estimate->position());
  // A cluster on the learned static scene is a bin, a post or a hedge: it starts no track, and
  // (static_feeds off) updates none, so a track that strayed onto it from a person passing by
  // coasts and ends there instead of living on it.
  std::vector<char> on_static(cands.size(), 0);
  for (std::size_t i = 0; i < cands.size(); ++i) on_static[i] = onStaticScene(cands[i], f.t);
  const Assignment a = gnnAssociate(
      int(tracks_.size()), int(cands.size()),
      [&](int r, int i) {
        // A tentative track pays tentative_penalty: it wins a cluster from a confirmed track
        // only when that much nearer (often it was born on the person's split piece, or on the
        // clutter beside them, while their confirmed track missed a scan).
        const double d = (cands[i].position - predicted[r]).norm();
        if (d > p_.gate || (on_static[i] && !p_.static_feeds)) return double(INFINITY);
        return tracks_[r].confirmed ? d : d + p_.tentative_penalty;
      },
      p_.gate + p_.tentative_penalty);
  std::vector<char> taken(cands.size(), 0);
  std::vector<ShapeTrack> kept;
  for (std::size_t k = 0; k < tracks_.size(); ++k) {
    ShapeTrack& t = tracks_[k];
    const int i = a.row_to_col[k];
    if (i >= 0) {
      taken[i] = 1;
      t.estimate->update(cands[i].cloud, rng_);
      t.misses = 0;
      const bool was_confirmed = t.confirmed;
      step(t, true, cands[i].score);
      // A person confirmed where one was lost is that person back (their id kept).
      if (t.confirmed && !was_confirmed)
        if (const auto lost = takeLost(t.estimate->position(), f.t)) t.id = lost->id;
      t.score = cands[i].score;
      t.cluster = cands[i].cluster;
      t.seen_at = t.estimate->position();
      t.last_seen = f.t;
      t.moved = std::max(t.moved, (t.seen_at - t.born_at).norm());
      t.score_sum += cands[i].score;
      ++t.score_n;
      t.fed_full = t.fed_full || cands[i].full;
    } else {
      t.estimate->miss();
      ++t.misses;
      t.cluster = -1;
      const bool was_confirmed = t.confirmed;  // M-of-N's deletion clears it
      if (!step(t, false, 0)) {
        if (was_confirmed && p_.reidentify_time > 0) {
          const Track r = t.estimate->row();  // coasting keeps the last velocity
          lost_.push_back({t.id, t.seen_at, Eigen::Vector2d(r.vx, r.vy), t.last_seen, t.fed_full});
        }
        continue;
      }
    }
    kept.push_back(std::move(t));
  }
  tracks_ = std::move(kept);
  // A cluster too small for a shape fit (birth_points) starts a track only on a score that small
  // non-person clusters rarely reach, and only clear of every confirmed track's gate (there it
  // is more likely a piece of that person than someone else). One where a person was lost
  // brings them back (revive_score), whatever its size, with the same clearance.
  for (std::size_t i = 0; i < cands.size(); ++i) {
    if (taken[i] || on_static[i]) continue;
    const Candidate& c = cands[i];
    const bool small_birth = !c.full && p_.small_birth_score > 0 && c.score >= p_.small_birth_score;
    const bool may_revive = p_.revive_score > 0 && c.score >= p_.revive_score && vouched(c);
    // The clearance is looked up only for a cluster that needs it (every track, per cluster).
    const bool clear = (small_birth || may_revive) && !nearTrack(c.position, p_.gate);
    std::optional<LostTrack> revived;
    if (may_revive && clear) revived = takeLost(c.position, f.t);
    const bool born = c.score >= p_.q_person && (c.full || (small_birth && clear));
    if (!born && !revived) continue;
    ShapeTrack t = birth(c);
    if (revived) {
      t.id = revived->id;
      t.life.confirm();
      t.confirmed = true;
    } else if (t.confirmed) {  // M-of-N with one hit
      if (const auto lost = takeLost(t.estimate->position(), f.t)) t.id = lost->id;
    }
    t.seen_at = t.born_at = t.estimate->position();
    t.last_seen = t.born = f.t;
    t.score_sum = c.score;
    t.score_n = 1;
    t.fed_full = c.full || (revived && revived->fed_full);
    tracks_.push_back(std::move(t));
  }
  if (scene_ && !f.motion_unknown) learnStaticScene(f);
  report(f);
}

bool ShapeTracker::vouched(const Candidate& c) const {
  // Beyond the static grid's range nothing is learned: a wall or bush fragment there scoring
  // revive_score would bring a person lost nearby back onto it for good (P1's corridor: a walker
  // lost at 25 m, revived on the wall beside them, held 12 s).
  return !scene_ || (c.position - c.cloud.origin).norm() <= p_.scene.max_range;
}

bool ShapeTracker::nearTrack(const Eigen::Vector2d& q, double radius) const {
  for (const ShapeTrack& t : tracks_)
    if (t.confirmed && (t.estimate->position() - q).norm() < radius) return true;
  return false;
}

std::optional<ShapeTracker::LostTrack> ShapeTracker::takeLost(const Eigen::Vector2d& q, double t) {
  // The nearest lost person by the distance to where they were last seen (they stopped) or to
  // where their last velocity carried them (they walked on behind whoever hid them), within
  // gate plus what they may have walked since, capped.
  const Reidentification reid{p_.reidentify_speed, p_.reidentify_max};
  int best = -1;
  double best_cost = 1;
  for (std::size_t r = 0; r < lost_.size(); ++r) {
    const LostTrack& l = lost_[r];
    const double unseen = t - l.last_seen;
    const double d = Reidentification::lostDistance(l.seen_at, l.seen_v, unseen, q);
    const double cost = d / reid.radius(p_.gate, unseen);
    if (cost < best_cost) best = int(r), best_cost = cost;
  }
  if (best < 0) return std::nullopt;
  const LostTrack lost = lost_[std::size_t(best)];
  lost_.erase(lost_.begin() + best);
  return lost;
}

bool ShapeTracker::onStaticScene(const Candidate& c, double t) const {
  if (!scene_ || c.cloud.points.empty()) return false;
  std::size_t on = 0;
  // A point above (or below) every height the static cells round it were hit at is no part of
  // them: a sitter's head over the bench back, a person's shoulders over a car bonnet.
  const bool by_height = p_.static_height_margin >= 0;
  for (std::size_t k = 0; k < c.cloud.points.size(); ++k) {
    const Eigen::Vector2d& q = c.cloud.points[k];
    // A detection without points has no height (k beyond heights): tested in 2D.
    const double z = by_height && k < c.heights.size() ? double(c.heights[k]) : NAN;
    on += scene_->isStatic(q.x(), q.y(), z, p_.static_height_margin, t, p_.static_radius);
  }
  return double(on) >= p_.static_share * double(c.cloud.points.size());
}

void ShapeTracker::learnStaticScene(const Frame& f) {
  // Every clustered return (ground and what is above a head already removed), fixed frame.
  const auto& cloud = f.cloud();
  const auto& xs = cloud.getPointsBufferRef_x();
  const auto& ys = cloud.getPointsBufferRef_y();
  const double c = std::cos(f.robot_pose.yaw()), s = std::sin(f.robot_pose.yaw());
  const double rx = f.robot_pose.x(), ry = f.robot_pose.y();
  // Their heights only when the static test reads them (static_height_margin).
  const bool by_height = p_.static_height_margin >= 0;
  obstacles_.clear();
  obstacle_z_.clear();
  for (const Cluster& cl : f.clusters)
    for (std::uint32_t k : cl.indices)
      if (k < xs.size()) {
        obstacles_.emplace_back(rx + c * xs[k] - s * ys[k], ry + s * xs[k] + c * ys[k]);
        if (by_height) obstacle_z_.push_back(float(f.heightOf(k)));
      }
  // A person walking with the robot, or standing while tracked, is never learned: their
  // track (confirmed or not) holds their place.
  people_.clear();
  for (const ShapeTrack& t : tracks_)
    if (holdsPlace(t, f.t)) people_.push_back(t.estimate->position());
  scene_->updatePoints(f.t, {f.sensor_pose.x(), f.sensor_pose.y()}, obstacles_, people_,
                       by_height ? &obstacle_z_ : nullptr);
}

bool ShapeTracker::step(ShapeTrack& t, bool associated, double q) const {
  const TrackStatus s = t.life.step(associated);
  if (p_.confirm_evidence <= 0) {
    t.confirmed = s == TrackStatus::Confirmed;
    return s != TrackStatus::Deleted;
  }
  // Evidence decides confirmation; a confirmed track goes after max_misses misses in a row.
  if (t.confirmed) return t.misses < std::max(1, p_.max_misses);
  t.evidence.add(associated, q);
  if (t.evidence.confirmed()) t.confirmed = true;
  return !t.evidence.refuted() && t.misses <= p_.confirm_window - p_.confirm_hits;
}

void ShapeTracker::report(Frame& f) {
  for (ShapeTrack& t : tracks_) {
    const bool confirmed = t.confirmed;
    if (!confirmed && !p_.report_tentative) continue;
    Track row = t.estimate->row();
    row.id = t.id;
    row.score = t.score;
    row.status = !confirmed ? "tentative" : t.misses ? "coasting" : "confirmed";
    row.cluster = t.cluster;
    f.tracks.push_back(std::move(row));
  }
}

bool ShapeTracker::holdsPlace(const ShapeTrack& t, double now) const {
  // A track fed only by small clusters (small_birth_score) never holds its place: on a few
  // returns the classifier's score says little, so a post or a bush piece far away that scores
  // high once must still become static scene; a walker's returns move and are never learned.
  if (!t.fed_full) return false;
  if (p_.unmoved_time <= 0 || !t.confirmed || t.moved >= p_.unmoved_distance) return true;
  if (now - t.born < p_.unmoved_time) return true;
  return t.score_sum >= p_.unmoved_score * std::max(1, t.score_n);
}

}  // namespace pedtrack::track
