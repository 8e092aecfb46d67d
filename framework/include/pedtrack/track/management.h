#pragma once
// Track-management policies a tracker composes: when a track is confirmed and when it is
// deleted. Each is a small value type the tracker keeps per track.
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

}  // namespace pedtrack::track
