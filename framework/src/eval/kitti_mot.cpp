#include "pedtrack/eval/kitti_mot.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "pedtrack/assignment.h"
#include "pedtrack/errors.h"

namespace pedtrack::eval {
namespace {

// KITTI counts the class and its neighbour (ignored where found, never a false positive).
std::string neighbourOf(const std::string& cls) {
  return cls == "pedestrian" ? "person_sitting" : cls == "car" ? "van" : "";
}

// One sequence, read once: labels and tracker boxes by frame, and each track's mean score.
struct Prepared {
  long frames = 0;
  std::vector<std::vector<const KittiTrackRow*>> truth, dontcare, tracks;
  std::vector<std::vector<std::size_t>> track_index;  // into `ever_matched`
  std::map<long, double> mean_score;                  // by track id
  std::map<long, long> lines;                         // by track id: its lines in the file
  std::set<long> truth_ids;
};

Prepared prepare(const KittiSequence& s, const KittiMotOptions& o) {
  const std::string cls = o.object_class, near = neighbourOf(cls);
  const auto kept = [&](const std::string& t) {
    return t.find(cls) != std::string::npos ||
           (!near.empty() && t.find(near) != std::string::npos) ||
           t.find("dontcare") != std::string::npos;
  };
  Prepared p;
  long last = -1;
  for (const auto& r : s.truth) last = std::max(last, r.frame);
  p.frames = s.frames > 0 ? s.frames : last + 1;
  const std::size_t n = std::size_t(std::max(0L, p.frames));
  p.truth.resize(n), p.dontcare.resize(n), p.tracks.resize(n), p.track_index.resize(n);
  for (const auto& r : s.truth) {
    if (!kept(r.type) || r.frame < 0 || r.frame >= p.frames) continue;
    if (r.type == "dontcare") {
      p.dontcare[std::size_t(r.frame)].push_back(&r);
    } else if (r.id != -1) {
      p.truth[std::size_t(r.frame)].push_back(&r);
      p.truth_ids.insert(r.id);
    }
  }
  std::map<long, std::pair<double, long>> sums;
  std::set<std::pair<long, long>> seen;
  for (std::size_t k = 0; k < s.tracks.size(); ++k) {
    const auto& r = s.tracks[k];
    if (!kept(r.type) || r.type == "dontcare" || r.id == -1) continue;
    if (!seen.insert({r.frame, r.id}).second)
      throw DataError(s.name + ": frame " + std::to_string(r.frame) + " has track " +
                      std::to_string(r.id) + " twice (a results file has one line per track)");
    auto& [sum, count] = sums[r.id];
    sum += r.score, ++count;  // frames past the labels count too (as KITTI's tool does)
    if (r.frame < 0 || r.frame >= p.frames) continue;
    p.tracks[std::size_t(r.frame)].push_back(&r);
    p.track_index[std::size_t(r.frame)].push_back(k);
  }
  for (const auto& [id, sc] : sums) {
    p.mean_score[id] = sc.first / double(sc.second);
    p.lines[id] = sc.second;
  }
  return p;
}

double overlapShare(const KittiTrackRow& t, const KittiTrackRow& d) {
  const double w = std::min(t.x2, d.x2) - std::max(t.x1, d.x1);
  const double h = std::min(t.y2, d.y2) - std::max(t.y1, d.y1);
  const double area = (t.x2 - t.x1) * (t.y2 - t.y1);
  return w <= 0 || h <= 0 || area <= 0 ? 0 : w * h / area;
}

// A frame's labels and tracker boxes matched as the evaluation matches them: per pair the 3D IoU
// (or, with max_distance, the bottom centres' bird's-eye distance, m), truth-major, and the
// assignment of the pairs within the gate.
struct FrameMatch {
  std::vector<double> value;
  Assignment as;
};

FrameMatch matchFrame(const std::vector<const KittiTrackRow*>& G,
                      const std::vector<const KittiTrackRow*>& T, const KittiMotOptions& o) {
  const bool by_distance = o.max_distance > 0;
  const int n = int(G.size()), m = int(T.size());
  FrameMatch fm;
  fm.value.resize(std::size_t(n) * std::size_t(m));
  std::vector<double> cost(fm.value.size());
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const auto &a = G[std::size_t(i)]->box, &b = T[std::size_t(j)]->box;
      const std::size_t k = std::size_t(i * m + j);
      fm.value[k] = by_distance ? std::hypot(a.x - b.x, a.z - b.z) : kittiIou3d(a, b);
      cost[k] = by_distance ? fm.value[k] : 1 - fm.value[k];
    }
  fm.as = solveAssignment(cost, n, m, by_distance ? o.max_distance : 1 - o.min_iou);
  return fm;
}

// A label that is neither required nor a false positive's excuse to miss: too truncated, too
// occluded, or of the neighbouring class.
bool ignoredTruth(const KittiTrackRow& g, const KittiMotOptions& o) {
  const std::string near = neighbourOf(o.object_class);
  return g.occluded > o.max_occlusion || g.truncated > o.max_truncation ||
         (!near.empty() && g.type == near);
}

// An unmatched tracker box that is no false positive: of the neighbouring class, too low in the
// image, or mostly inside a DontCare area.
bool ignoredBox(const KittiTrackRow& t, const std::vector<const KittiTrackRow*>& dontcare,
                const KittiMotOptions& o) {
  const std::string near = neighbourOf(o.object_class);
  if ((!near.empty() && t.type == near) || std::abs(t.y2 - t.y1) <= o.min_height) return true;
  for (const KittiTrackRow* d : dontcare)
    if (overlapShare(t, *d) > 0.5) return true;
  return false;
}

// One pass at a track-score threshold: the counts, and the matched tracks' scores. `ever` is
// KITTI's `valid` flag per tracker box, which its tool never resets between passes: a box matched
// once is never ignored again (kept so the figures equal the tool's).
KittiMotCounts pass(const std::vector<Prepared>& seqs, std::vector<std::vector<char>>& ever,
                    const std::vector<std::map<long, double>>& means, double threshold,
                    const KittiMotOptions& o, std::vector<double>* scores) {
  KittiMotCounts c;
  for (std::size_t si = 0; si < seqs.size(); ++si) {
    const Prepared& p = seqs[si];
    // truth id -> per appearance (track id | -1, ignored)
    std::map<long, std::vector<std::pair<long, bool>>> traj;
    for (std::size_t f = 0; f < std::size_t(p.frames); ++f) {
      const auto& G = p.truth[f];
      std::vector<const KittiTrackRow*> T;
      std::vector<std::size_t> Ti;
      for (std::size_t k = 0; k < p.tracks[f].size(); ++k)
        if (means[si].at(p.tracks[f][k]->id) >= threshold)
          T.push_back(p.tracks[f][k]), Ti.push_back(p.track_index[f][k]);
      const FrameMatch fm = matchFrame(G, T, o);
      const int n = int(G.size()), m = int(T.size());
      long ignored_fn = 0, ignored_tp = 0, ignored_trk = 0, matched = 0;
      for (int i = 0; i < n; ++i) {
        const KittiTrackRow& g = *G[std::size_t(i)];
        const bool ignored = ignoredTruth(g, o);
        const int j = fm.as.row_to_col[std::size_t(i)];
        if (j >= 0) {
          ++matched;
          ignored_tp += ignored;
          c.sum_similarity += fm.value[std::size_t(i * m + j)];
          ever[si][Ti[std::size_t(j)]] = 1;
          if (scores) scores->push_back(means[si].at(T[std::size_t(j)]->id));
        } else {
          ignored_fn += ignored;
        }
        traj[g.id].push_back({j >= 0 ? T[std::size_t(j)]->id : -1, ignored});
      }
      for (int j = 0; j < m; ++j)
        if (fm.as.col_to_row[std::size_t(j)] < 0 && !ever[si][Ti[std::size_t(j)]])
          ignored_trk += ignoredBox(*T[std::size_t(j)], p.dontcare[f], o);
      c.tp += matched;
      c.ignored_tp += ignored_tp;
      c.fn += n - matched - ignored_fn;
      c.fp += m - matched - ignored_trk;
      c.n_gt += n - ignored_fn - ignored_tp;
    }
    // Per labelled trajectory, over its appearances (KITTI's rules, docs/pipelines.md).
    for (const long id : p.truth_ids) {
      ++c.trajectories;
      const auto it = traj.find(id);
      if (it == traj.end()) continue;
      const auto& a = it->second;
      const std::size_t K = a.size();
      long n_ign = 0;
      bool any = false;
      for (const auto& [t, ig] : a) n_ign += ig, any = any || t != -1;
      if (n_ign == long(K)) {
        --c.trajectories;  // wholly ignored: not scored
        continue;
      }
      if (!any) {
        ++c.mostly_lost;
        continue;
      }
      long last = a[0].first, tracked = a[0].first != -1;
      for (std::size_t k = 1; k < K; ++k) {
        const long g = a[k].first, prev = a[k - 1].first;
        if (a[k].second) {
          last = -1;
          continue;
        }
        if (last != g && last != -1 && g != -1 && prev != -1) ++c.ids;
        if (k < K - 1 && prev != g && last != -1 && g != -1 && a[k + 1].first != -1) ++c.frag;
        if (g != -1) ++tracked, last = g;
      }
      if (K > 1 && a[K - 2].first != a[K - 1].first && last != -1 && a[K - 1].first != -1 &&
          !a[K - 1].second)
        ++c.frag;
      const double ratio = double(tracked) / double(long(K) - n_ign);
      ratio > 0.8 ? ++c.mostly_tracked : ratio < 0.2 ? ++c.mostly_lost : ++c.partly_tracked;
    }
  }
  return c;
}

// One sequence's frames for HOTA: every track, the ignored labels and what they or the ignore
// rules account for left out (TrackEval's KITTI preprocessing, with this evaluation's rules).
std::vector<HotaFrame> hotaFrames(const Prepared& p, const KittiMotOptions& o) {
  std::vector<HotaFrame> out(std::size_t(std::max(0L, p.frames)));
  for (std::size_t f = 0; f < out.size(); ++f) {
    const auto &G = p.truth[f], &T = p.tracks[f];
    const FrameMatch fm = matchFrame(G, T, o);
    const int n = int(G.size()), m = int(T.size());
    std::vector<int> kept_truth, kept_track;
    for (int i = 0; i < n; ++i)
      if (!ignoredTruth(*G[std::size_t(i)], o)) kept_truth.push_back(i);
    for (int j = 0; j < m; ++j) {
      const int i = fm.as.col_to_row[std::size_t(j)];
      if (i >= 0 ? !ignoredTruth(*G[std::size_t(i)], o)
                 : !ignoredBox(*T[std::size_t(j)], p.dontcare[f], o))
        kept_track.push_back(j);
    }
    HotaFrame& h = out[f];
    for (int i : kept_truth) h.truths.push_back(G[std::size_t(i)]->id);
    for (int j : kept_track) h.tracks.push_back(T[std::size_t(j)]->id);
    for (int i : kept_truth)
      for (int j : kept_track) {
        const double v = fm.value[std::size_t(i * m + j)];
        h.similarity.push_back(o.max_distance > 0 ? std::max(0.0, 1 - v / o.max_distance) : v);
      }
  }
  return out;
}

}  // namespace

double KittiMotCounts::mota() const {
  return n_gt > 0 ? 1 - double(fn + fp + ids) / double(n_gt)
                  : -std::numeric_limits<double>::infinity();
}
double KittiMotCounts::motp() const {
  return tp > 0 ? sum_similarity / double(tp) : 0;
}
double KittiMotCounts::recall() const {
  return tp + fn > 0 ? double(tp) / double(tp + fn) : 0;
}
double KittiMotCounts::precision() const {
  return tp + fp > 0 ? double(tp) / double(tp + fp) : 0;
}
double KittiMotCounts::smota(double r) const {
  if (n_gt <= 0 || r <= 0) return 0;
  const double v = 1 - (double(fn + fp + ids) - (1 - r) * double(n_gt)) / (r * double(n_gt));
  return std::clamp(v, 0.0, 1.0);
}

KittiMotResult evaluateKittiMot(std::vector<KittiSequence> sequences, const KittiMotOptions& o) {
  std::vector<Prepared> seqs;
  std::vector<std::vector<char>> ever;
  std::vector<std::map<long, double>> means;
  for (const auto& s : sequences) {
    seqs.push_back(prepare(s, o));
    ever.emplace_back(s.tracks.size(), 0);
    means.push_back(seqs.back().mean_score);
  }
  // evaluate.py overwrites every box's score with its track's mean and averages those again in
  // the next pass: Python's sum of n equal floats over n can land one step below the mean, so a
  // track may fail the very threshold it set. Reproduced on request, pass by pass.
  const auto drift = [&] {
    if (!o.score_drift) return;
    for (std::size_t si = 0; si < seqs.size(); ++si)
      for (auto& [id, m] : means[si]) {
        const long n = seqs[si].lines.at(id);
        double sum = 0;
        for (long k = 0; k < n; ++k) sum += m;
        m = sum / double(n);
      }
  };
  KittiMotResult res;
  std::vector<double> scores;
  const KittiMotCounts all = pass(seqs, ever, means, -1e4, o, &scores);
  drift();
  // The recall levels 1/40 ... 40/40: the matched score at which each is (nearest) reached.
  constexpr int kLevels = 40;
  std::sort(scores.begin(), scores.end(), std::greater<>());
  const double num_gt = double(all.tp + all.fn);
  std::vector<std::pair<double, double>> levels;  // (threshold, recall)
  double current = 0;
  for (std::size_t i = 0; i < scores.size() && num_gt > 0; ++i) {
    const double left = double(i + 1) / num_gt;
    const double right = i + 1 < scores.size() ? double(i + 2) / num_gt : left;
    if (i + 1 < scores.size() && right - current < current - left) continue;
    levels.push_back({scores[i], current});
    current += 1.0 / kLevels;
  }
  if (!levels.empty()) levels.erase(levels.begin());  // recall 0 is not a level
  double best_mota = 0;
  for (const auto& [threshold, r] : levels) {
    const KittiMotCounts c = pass(seqs, ever, means, threshold, o, nullptr);
    drift();
    res.samota += c.smota(r);
    res.amota += c.mota();
    res.amotp += c.motp();
    if (c.mota() > best_mota) best_mota = c.mota(), res.threshold = threshold;
  }
  res.samota /= kLevels, res.amota /= kLevels, res.amotp /= kLevels;
  res.levels = int(levels.size());
  res.best = pass(seqs, ever, means, res.threshold, o, nullptr);
  std::vector<HotaResult> per_sequence;
  for (const Prepared& p : seqs) per_sequence.push_back(hota(hotaFrames(p, o)));
  if (!per_sequence.empty()) res.hota = combineHota(per_sequence);
  return res;
}

}  // namespace pedtrack::eval
