#include "pedtrack/eval/clear_mot.h"

#include <cmath>
#include <map>
#include <unordered_map>

#include "pedtrack/assignment.h"

namespace pedtrack::eval {

double ClearMotCounts::mota() const {
  if (truths == 0) return std::nan("");
  return 1.0 - double(misses + false_positives + id_switches) / double(truths);
}

double ClearMotCounts::motp() const {
  return matches ? distance_sum / double(matches) : std::nan("");
}

ClearMotCounts& ClearMotCounts::operator+=(const ClearMotCounts& o) {
  frames += o.frames;
  truths += o.truths;
  matches += o.matches;
  correct += o.correct;
  misses += o.misses;
  false_positives += o.false_positives;
  id_switches += o.id_switches;
  fragmentations += o.fragmentations;
  unscored_matches += o.unscored_matches;
  distance_sum += o.distance_sum;
  return *this;
}

namespace {

// The remembered correspondences, a partial one-to-one map track id ↔ truth id (the script's
// prev_matched_ids): a pair stays until either id is matched to someone else.
class Memory {
 public:
  const long* truthOf(long track) const {
    auto it = by_track_.find(track);
    return it == by_track_.end() ? nullptr : &it->second;
  }
  bool hasTruth(long truth) const { return by_truth_.count(truth) > 0; }
  const std::map<long, long>& pairs() const { return by_track_; }
  void set(long track, long truth) {
    if (auto it = by_track_.find(track); it != by_track_.end()) {
      by_truth_.erase(it->second);
      by_track_.erase(it);
    }
    if (auto it = by_truth_.find(truth); it != by_truth_.end()) {
      by_track_.erase(it->second);
      by_truth_.erase(it);
    }
    by_track_[track] = truth;
    by_truth_[truth] = track;
  }

 private:
  std::map<long, long> by_track_, by_truth_;
};

// Per truth id, for fragmentations: matched before, and currently in a gap after a match; for
// ID switches: when last matched, and the frames since in which it was present (unscored).
struct FragState {
  bool matched_before = false;
  bool in_gap = false;
  double last_match = std::nan("");
  std::size_t gap_frames = 0, gap_unscored = 0;
};

}  // namespace

ClearMotResult clearMot(const std::vector<EvalFrame>& frames, const ClearMotOptions& opt) {
  ClearMotResult res;
  ClearMotCounts& c = res.counts;
  Memory memory;
  std::unordered_map<long, FragState> frag;
  res.absorbed.resize(frames.size());
  res.scored.resize(frames.size());
  res.missed.resize(frames.size());
  res.unmatched.resize(frames.size());
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const EvalFrame& f = frames[k];
    const auto& tr = f.truths;
    const auto& es = f.estimates;
    ++c.frames;
    auto scored = [&](const Object& o) {
      return o.scored && (!opt.following || *opt.following == 0 || o.id == *opt.following);
    };
    std::vector<int> t2e(tr.size(), -1), e2t(es.size(), -1);
    // 1. Remembered correspondences that still hold.
    std::unordered_map<long, std::size_t> truth_at, est_at;
    for (std::size_t i = tr.size(); i-- > 0;) truth_at[tr[i].id] = i;  // first occurrence wins
    for (std::size_t j = es.size(); j-- > 0;) est_at[es[j].id] = j;
    for (const auto& [track_id, truth_id] : memory.pairs()) {
      auto ei = est_at.find(track_id);
      auto ti = truth_at.find(truth_id);
      if (ei == est_at.end() || ti == truth_at.end()) continue;
      if (distance(tr[ti->second], es[ei->second]) > opt.threshold) continue;
      t2e[ti->second] = int(ei->second);
      e2t[ei->second] = int(ti->second);
    }
    // 2. Minimum-distance assignment of the rest.
    std::vector<std::size_t> free_t, free_e;
    for (std::size_t i = 0; i < tr.size(); ++i)
      if (t2e[i] < 0) free_t.push_back(i);
    for (std::size_t j = 0; j < es.size(); ++j)
      if (e2t[j] < 0) free_e.push_back(j);
    if (!free_t.empty() && !free_e.empty()) {
      std::vector<double> cost(free_t.size() * free_e.size());
      for (std::size_t a = 0; a < free_t.size(); ++a)
        for (std::size_t b = 0; b < free_e.size(); ++b)
          cost[a * free_e.size() + b] = distance(tr[free_t[a]], es[free_e[b]]);
      const Assignment as =
          solveAssignment(cost, int(free_t.size()), int(free_e.size()), opt.threshold);
      for (const auto& [a, b] : as.pairs()) {
        t2e[free_t[a]] = int(free_e[b]);
        e2t[free_e[b]] = int(free_t[a]);
      }
    }
    // 3. Count. Identity is judged against the memory as it was before this frame.
    std::vector<std::pair<long, long>> new_pairs;
    for (std::size_t i = 0; i < tr.size(); ++i) {
      const Object& t = tr[i];
      const bool sc = scored(t);
      if (sc) res.scored[k].push_back(i);
      FragState& fs = frag[t.id];
      if (t2e[i] < 0 || !sc) {
        ++fs.gap_frames;
        if (!sc) ++fs.gap_unscored;
      }
      if (t2e[i] < 0) {
        if (!sc) continue;
        ++c.truths;
        ++c.misses;
        res.missed[k].push_back(i);
        if (fs.matched_before) fs.in_gap = true;
        continue;
      }
      const Object& e = es[t2e[i]];
      if (!sc) {
        ++c.unscored_matches;
        res.absorbed[k].push_back(std::size_t(t2e[i]));
        continue;
      }
      ++c.truths;
      ++c.matches;
      const double d = distance(t, e);
      c.distance_sum += d;
      const long* prev_truth = memory.truthOf(e.id);
      const bool switched = prev_truth ? *prev_truth != t.id : memory.hasTruth(t.id);
      if (switched) {
        ++c.id_switches;
        res.switches.push_back({k, t.id, e.id, prev_truth != nullptr, f.t - fs.last_match,
                                fs.gap_frames, fs.gap_unscored});
      } else {
        ++c.correct;
      }
      fs.last_match = f.t;
      fs.gap_frames = fs.gap_unscored = 0;
      if (fs.in_gap) ++c.fragmentations;
      fs.in_gap = false;
      fs.matched_before = true;
      new_pairs.emplace_back(e.id, t.id);
      res.pairs.push_back({k, t, e, d});
    }
    if (!opt.following)
      for (std::size_t j = 0; j < es.size(); ++j)
        if (e2t[j] < 0) {
          ++c.false_positives;
          res.unmatched[k].push_back(j);
        }
    for (const auto& [track_id, truth_id] : new_pairs) memory.set(track_id, truth_id);
  }
  return res;
}

std::vector<EvalFrame> withoutUnscored(const std::vector<EvalFrame>& frames,
                                       const ClearMotResult& clear) {
  std::vector<EvalFrame> out(frames.size());
  for (std::size_t k = 0; k < frames.size(); ++k) {
    out[k].t = frames[k].t;
    for (const Object& t : frames[k].truths)
      if (t.scored) out[k].truths.push_back(t);
    std::vector<char> drop(frames[k].estimates.size(), 0);
    if (k < clear.absorbed.size())
      for (std::size_t j : clear.absorbed[k]) drop[j] = 1;
    for (std::size_t j = 0; j < frames[k].estimates.size(); ++j)
      if (!drop[j]) out[k].estimates.push_back(frames[k].estimates[j]);
  }
  return out;
}

}  // namespace pedtrack::eval
