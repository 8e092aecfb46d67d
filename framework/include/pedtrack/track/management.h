#pragma once
// Track-management policies a tracker composes: when a track is confirmed and when it is
// deleted, and where a lost one may be found again. Each is a small value type a tracker keeps
// per track (or, for re-identification's rule, once).
#include <Eigen/Core>
#include <string>

namespace pedtrack::track {

enum class TrackStatus { Tentative, Confirmed, Deleted };
const char* toString(TrackStatus s);  ///< "tentative", "confirmed", "deleted"

/// M-of-N: confirmed once M of the last N scans had an association; a confirmed track is
/// deleted after `max_misses` scans in a row without one, a tentative one as soon as M can no
/// longer be reached within its first N scans.
class MOfN {
 public:
  MOfN(int m, int n, int max_misses) : m_(m), n_(n), max_misses_(max_misses) {}
  TrackStatus step(bool associated);
  TrackStatus status() const { return status_; }
  /// Confirmed from now on, without its M hits (a lost track brought back: its past is the
  /// evidence); deleted after max_misses misses in a row as any confirmed track.
  void confirm() {
    if (status_ == TrackStatus::Tentative) status_ = TrackStatus::Confirmed;
  }

 private:
  int m_, n_, max_misses_;
  int scans_ = 0, hits_ = 0, misses_in_row_ = 0;
  unsigned history_ = 0;
  TrackStatus status_ = TrackStatus::Tentative;
};

/// P2 §3.5's classifier-score hysteresis: a new track needs a detection with Q ≥ q_person; an
/// established one also accepts Q > q_min.
struct ScoreHysteresis {
  double q_person = 0.5;
  double q_min = 0;
  bool accepts(double q, bool established) const {
    return q >= q_person || (established && q > q_min);
  }
};

/// Confirmation by person evidence accumulated over scans (ours, #45): each scan a tentative track
/// is associated adds its detection's classifier score as log-odds, logit(q) held within ±3 (a
/// score of 0.5 says nothing; 0.95 adds 2.9, 0.3 takes 0.85 off), each scan it is missed adds
/// `miss`. Confirmed once the sum reaches `confirm`; a tentative track whose sum falls to
/// −confirm / 2 is deleted. One frame's high score on furniture is not enough, a person's steady
/// scores are, and however a classifier is calibrated its 0.5 stays the neutral point.
class ScoreEvidence {
 public:
  ScoreEvidence(double confirm, double miss) : confirm_(confirm), miss_(miss) {}
  /// The scan's outcome: associated with a detection scoring q, or missed.
  void add(bool associated, double q);
  bool confirmed() const { return sum_ >= confirm_; }
  bool refuted() const { return sum_ <= -0.5 * confirm_; }
  double sum() const { return sum_; }
  static double logOdds(double q);  ///< logit(q) within ±3

 private:
  double confirm_, miss_, sum_ = 0;
};

/// Sequential probability ratio test on the existence probability (P4 eq. 3): LLR = ln(P_T /
/// (1 − P_T)); confirm at LLR ≥ ln((1 − β_T)/α_T), delete at LLR ≤ ln(β_T / (1 − α_T)), where
/// α_T is the probability of confirming a false track and β_T of deleting a true one.
class ExistenceLlr {
 public:
  ExistenceLlr(double alpha_t, double beta_t);
  double confirmThreshold() const { return confirm_; }
  double deleteThreshold() const { return delete_; }
  static double llr(double p_exist);
  /// The status after a scan with existence probability `p_exist`; once confirmed a track stays
  /// confirmed until it is deleted.
  TrackStatus step(TrackStatus current, double p_exist) const;

 private:
  double confirm_, delete_;
};

/// Re-identification of a lost confirmed person (ours, #44/#45): how far from where they were
/// last seen a new track may take their id back, and how far a place is from where they may be.
struct Reidentification {
  double speed = 1.0;  ///< m/s: the radius grows by this times the time unseen ...
  double max = 1.0;    ///< m: ... by at most this much
  /// The radius around a person unseen for `unseen` s: `gate` + min(speed · unseen, max).
  double radius(double gate, double unseen) const;
  /// How far p is from where a lost person may be: where they were last seen (seen_at; they
  /// stopped) or where their last velocity seen_v carried them in `walked` s (they walked on
  /// behind whoever hid them), whichever is nearer.
  static double lostDistance(const Eigen::Vector2d& seen_at, const Eigen::Vector2d& seen_v,
                             double walked, const Eigen::Vector2d& p);
};

}  // namespace pedtrack::track
