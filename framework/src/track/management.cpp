#include "pedtrack/track/management.h"

#include <algorithm>
#include <bitset>
#include <cmath>
#include <stdexcept>

namespace pedtrack::track {

const char* toString(TrackStatus s) {
  switch (s) {
    case TrackStatus::Tentative:
      return "tentative";
    case TrackStatus::Confirmed:
      return "confirmed";
    case TrackStatus::Deleted:
      return "deleted";
  }
  return "?";
}

TrackStatus MOfN::step(bool associated) {
  if (status_ == TrackStatus::Deleted) return status_;
  ++scans_;
  history_ = (history_ << 1) | (associated ? 1u : 0u);
  misses_in_row_ = associated ? 0 : misses_in_row_ + 1;
  if (status_ == TrackStatus::Tentative) {
    const unsigned window = n_ >= 32 ? ~0u : ((1u << n_) - 1);
    hits_ = int(std::bitset<32>(history_ & window).count());
    if (hits_ >= m_) {
      status_ = TrackStatus::Confirmed;
    } else if (scans_ >= n_ || hits_ + (n_ - scans_) < m_) {
      status_ = TrackStatus::Deleted;  // M hits can no longer come within the first N scans
    }
  } else if (misses_in_row_ >= max_misses_) {
    status_ = TrackStatus::Deleted;
  }
  return status_;
}

ExistenceLlr::ExistenceLlr(double alpha_t, double beta_t) {
  if (!(alpha_t > 0 && alpha_t < 1 && beta_t > 0 && beta_t < 1))
    throw std::invalid_argument("alpha_T and beta_T must lie in (0, 1)");
  confirm_ = std::log((1 - beta_t) / alpha_t);
  delete_ = std::log(beta_t / (1 - alpha_t));
}

double ExistenceLlr::llr(double p) {
  const double e = 1e-300;
  return std::log(std::max(p, e)) - std::log(std::max(1 - p, e));
}

TrackStatus ExistenceLlr::step(TrackStatus current, double p_exist) const {
  if (current == TrackStatus::Deleted) return current;
  const double l = llr(p_exist);
  if (l <= delete_) return TrackStatus::Deleted;
  if (l >= confirm_) return TrackStatus::Confirmed;
  return current;  // continue the test; a confirmed track stays confirmed
}

double ScoreEvidence::logOdds(double q) {
  const double p = std::clamp(q, 1e-6, 1 - 1e-6);
  return std::clamp(std::log(p / (1 - p)), -3.0, 3.0);
}

void ScoreEvidence::add(bool associated, double q) {
  sum_ += associated ? logOdds(q) : miss_;
}

double Reidentification::radius(double gate, double unseen) const {
  return gate + std::min(speed * unseen, max);
}

double Reidentification::lostDistance(const Eigen::Vector2d& seen_at, const Eigen::Vector2d& seen_v,
                                      double walked, const Eigen::Vector2d& p) {
  return std::min((seen_at - p).norm(), (seen_at + walked * seen_v - p).norm());
}

}  // namespace pedtrack::track
