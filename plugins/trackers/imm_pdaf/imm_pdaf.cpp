// imm_pdaf (P4 §2.2–2.3): an IMM over a constant-velocity and constant-turn models (ω = ±1.4
// rad/s), each mode updated by probabilistic data association, with integrated track existence
// (IPDA, P4 eq. 1–2) whose log-likelihood ratio confirms and deletes tracks (eq. 3). Several
// people at once through JPDA where gates overlap (or independent PDA per track).
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "imm_pdaf/existence_log.h"
#include "imm_pdaf/gate.h"
#include "imm_pdaf/jpda.h"
#include "imm_pdaf/occlusion.h"
#include "imm_pdaf/pda.h"
#include "pedtrack/errors.h"
#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"
#include "pedtrack/track/box_filter.h"
#include "pedtrack/track/imm.h"
#include "pedtrack/track/kalman.h"
#include "pedtrack/track/management.h"
#include "pedtrack/track/tracker_base.h"

namespace pedtrack::immpdaf {
namespace {

using namespace pedtrack::track;

struct Settings {
  double sigma = 0.1;                         // m, a detection's x and y
  double q = 1;                               // m²/s³, every motion model's acceleration noise
  std::vector<double> turn_rates{1.4, -1.4};  // rad/s, one constant-turn model each (P4 3.1)
  std::vector<double> transition{0.95,  0.025, 0.025, 0.025, 0.95,
                                 0.025, 0.025, 0.025, 0.95};  // P4 3.1, row by row
  double p_detect = 0.9, p_detect_occluded = 0.1, p_gate = 0.99;
  double clutter_density = 0;  // 1/m², 0: estimated from each gate (P4 2.3)
  double p_survive = 0.98, p_birth = 0, p_init = 0.2;
  double alpha_t = 0.01, beta_t = 0.01;  // P4 eq. 3
  double init_speed_sigma = 1, min_score = 0, surface_offset = 0, merge_distance = 0.35;
  double score_prior = 0;  // 0: scores only threshold; else the share of detections that are people
  bool jpda = true, report_tentative = false;
};

const ParamTable<Settings>& table() {
  using P = Settings;
  static const auto t =
      ParamTable<P>()
          .real(&P::sigma, "sigma", "m", 1e-4, 10,
                "measurement noise: standard deviation of a detection's x and y")
          .real(&P::q, "q", "m^2/s^3", 0, 1e4,
                "acceleration noise power spectral density of every motion model")
          .vector(&P::turn_rates, "turn_rates", "rad/s", 0, -20, 20,
                  "one constant-turn model per rate, after the CV model (P4 3.1)")
          .vector(&P::transition, "transition", "", 0, 0, 1,
                  "model transition matrix, row by row, n x n for n models (P4 3.1)")
          .real(&P::p_detect, "p_detect", "", 0.01, 1,
                "P_D: probability a visible person is detected")
          .real(&P::p_detect_occluded, "p_detect_occluded", "", 0, 1,
                "P_D where a nearer object hides the track's predicted position")
          .real(&P::p_gate, "p_gate", "", 0.5, 0.999999,
                "P_G: gate probability (chi-square, 2 dof)")
          .real(&P::clutter_density, "clutter_density", "1/m^2", 0, 1e6,
                "false detections per m^2; 0: estimated from each gate (P4 2.3)")
          .real(&P::p_survive, "p_survive", "", 0, 1,
                "probability a person still exists after 1 s (P4 eq. 1's P22 per second)")
          .real(&P::p_birth, "p_birth", "1/s", 0, 1,
                "rate at which a non-existing track becomes a person (P4 eq. 1's P12)")
          .real(&P::p_init, "p_init", "", 0, 1, "existence probability of a new track")
          .real(&P::alpha_t, "alpha_t", "", 1e-9, 0.5,
                "alpha_T: probability of confirming a false track (P4 eq. 3)")
          .real(&P::beta_t, "beta_t", "", 1e-9, 0.5,
                "beta_T: probability of deleting a true track (P4 eq. 3)")
          .real(&P::init_speed_sigma, "init_speed_sigma", "m/s", 0.01, 10,
                "standard deviation of a new track's velocity (it starts at rest)")
          .real(&P::min_score, "min_score", "", 0, 1, "detections scoring below are ignored")
          .real(&P::score_prior, "score_prior", "", 0, 0.99,
                "the share of all detections that are people, with scores read as the "
                "probability P that a detection is a person: each detection's evidence is "
                "weighted by its likelihood ratio odds(P) / odds(score_prior) (amplitude-aided "
                "PDA) and a new track starts at existence P; 0: scores only pass min_score")
          .real(&P::surface_offset, "surface_offset", "m", -1, 1,
                "each detection is moved this far away from the sensor (a scan sees the near "
                "surface of a body; 0: as detected)")
          .real(&P::merge_distance, "merge_distance", "m", 0, 5,
                "two tracks closer than this are one person: the less certain is deleted")
          .choice(&P::jpda, "association", {{"jpda", true}, {"pda", false}},
                  "jpda: a detection is at most one track's; pda: each track on its own")
          .boolean(&P::report_tentative, "report_tentative",
                   "also write tentative tracks to tracks.csv (existence.csv has them all)");
  return t;
}

struct ImmTrack {
  long id = 0;
  ImmState imm;
  double existence = 0;
  TrackStatus status = TrackStatus::Tentative;
  BoxFilter box;  // a 3D detector's box and scores, smoothed over the detections weighted by β
};

ExistenceLlr makeLlr(const ParamSet& p, const Settings& s) {
  try {
    return ExistenceLlr(s.alpha_t, s.beta_t);
  } catch (const std::invalid_argument& e) {
    throw ConfigError(table().where(p, &Settings::alpha_t) + ": " + e.what());
  }
}

class ImmPdaf : public Tracker {
 public:
  explicit ImmPdaf(const PluginContext& ctx)
      : s_(table().read(ctx.params)), llr_(makeLlr(ctx.params, s_)) {
    const ParamSet& p = ctx.params;
    if (s_.p_init >= 1 || s_.p_init <= 0)
      throw ConfigError(table().where(p, &Settings::p_init) +
                        ": must lie strictly between 0 and 1");
    if (ExistenceLlr::llr(s_.p_init) >= llr_.confirmThreshold() ||
        ExistenceLlr::llr(s_.p_init) <= llr_.deleteThreshold())
      throw ConfigError(table().where(p, &Settings::p_init) + ": a new track's LLR ln(p/(1-p)) = " +
                        std::to_string(ExistenceLlr::llr(s_.p_init)) +
                        " must lie between the deletion and confirmation thresholds " +
                        std::to_string(llr_.deleteThreshold()) + " and " +
                        std::to_string(llr_.confirmThreshold()));

    std::vector<std::shared_ptr<const MotionModel>> models{
        std::make_shared<ConstantVelocity>(s_.q)};
    for (double w : s_.turn_rates) models.push_back(std::make_shared<CoordinatedTurn>(w, s_.q));
    const std::vector<double>& pi = s_.transition;
    const std::size_t n = models.size();
    if (pi.size() != n * n)
      throw ConfigError(table().where(p, &Settings::transition) + ": " + std::to_string(n) +
                        " models (CV and one per turn rate) need " + std::to_string(n * n) +
                        " numbers (row by row), got " + std::to_string(pi.size()));
    Eigen::MatrixXd T(n, n);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) T(i, j) = pi[i * n + j];
    try {
      imm_ = std::make_unique<Imm>(models, T);
    } catch (const std::invalid_argument& e) {
      throw ConfigError(table().where(p, &Settings::transition) + ": " + e.what());
    }
    meas_ = positionMeasurement(4, s_.sigma);
    gamma_ = gateThreshold(s_.p_gate, 2);
  }

  void start(const std::string& out_dir) override {
    if (!out_dir.empty()) log_ = std::make_unique<ExistenceLog>(out_dir + "/existence.csv");
  }
  void finish() override {
    if (log_) log_->close();
  }

  void process(Frame& f) override {
    const double dt = clock_.step(f.t);
    const double survive = std::pow(s_.p_survive, dt);
    for (ImmTrack& t : tracks_) {
      t.existence = existencePredict(t.existence, survive, s_.p_birth * dt);
      imm_->predict(t.imm, dt);
    }
    std::vector<Eigen::VectorXd> z;
    std::vector<const Detection*> zdet;  // the detection of each measurement
    const Eigen::Vector2d sensor(f.sensor_pose.x(), f.sensor_pose.y());
    for (const Detection& d : f.detections) {
      if (!(d.score >= s_.min_score)) continue;
      zdet.push_back(&d);
      // A 2D scan sees the near side of a body: move the detection back along the line of sight.
      const Eigen::Vector2d p(d.x, d.y), ray = p - sensor;
      const double range = ray.norm();
      z.push_back(range > 1e-6 ? Eigen::Vector2d(p + ray / range * s_.surface_offset) : p);
    }
    const OcclusionMap occlusion(f);
    // The score's likelihood ratio, person against clutter (1: the score is not used as evidence).
    std::vector<double> ratio(z.size(), 1.0);
    if (s_.score_prior > 0)
      for (std::size_t i = 0; i < z.size(); ++i) ratio[i] = scoreRatio(zdet[i]->score);

    // Gating on the combined prediction; per-mode likelihoods of the validated measurements.
    const Eigen::Index T = Eigen::Index(tracks_.size()), M = Eigen::Index(z.size());
    const std::size_t K = imm_->size();
    Eigen::MatrixXd evidence = Eigen::MatrixXd::Zero(T, M);
    Eigen::VectorXd miss(T);
    std::vector<Eigen::MatrixXd> mode_lik(tracks_.size());  // M × K likelihoods p_ij
    std::vector<double> best_nis(tracks_.size(), std::nan(""));
    std::vector<char> in_a_gate(z.size(), 0);
    for (Eigen::Index t = 0; t < T; ++t) {
      ImmTrack& tr = tracks_[t];
      const Gaussian pred = Imm::combine(tr.imm);
      const Eigen::MatrixXd S = innovationCovariance(pred, meas_);
      const double pd = occlusion.hidden(pred.x(0), pred.x(1)) ? s_.p_detect_occluded : s_.p_detect;
      miss(t) = 1 - pd * s_.p_gate;
      mode_lik[t] = Eigen::MatrixXd::Zero(M, Eigen::Index(K));
      std::vector<Eigen::Index> gated;
      double best = -1;
      for (Eigen::Index i = 0; i < M; ++i) {
        const Innovation in = innovation(pred, meas_, z[i]);
        if (!(in.nis <= gamma_)) continue;
        gated.push_back(i);
        in_a_gate[i] = 1;
        for (std::size_t j = 0; j < K; ++j)
          mode_lik[t](i, Eigen::Index(j)) =
              std::exp(innovation(tr.imm.modes[j], meas_, z[i]).log_likelihood);
        const double p = tr.imm.mu.dot(mode_lik[t].row(i));
        if (p > best) best = p, best_nis[t] = in.nis;
        evidence(t, i) = p;
      }
      PdaParams pp{pd, s_.p_gate, s_.clutter_density};
      const double lambda = clutterDensity(pp, gated.size(), gateVolume(gamma_, S), tr.existence);
      evidence.row(t) *= pd / lambda;
      mode_lik[t] *= pd / lambda;     // now e_ij: per-mode evidence
      for (Eigen::Index i : gated) {  // a surer detection is likelier the person's
        evidence(t, i) *= ratio[std::size_t(i)];
        mode_lik[t].row(i) *= ratio[std::size_t(i)];
      }
    }
    const AssociationProbabilities a =
        s_.jpda ? jpda(evidence, miss) : independentPda(evidence, miss);

    for (Eigen::Index t = 0; t < T; ++t) {
      update(tracks_[t], a, t, miss(t), mode_lik[t], z);
      updateBox(tracks_[t], a, t, zdet);
    }
    for (Eigen::Index t = 0; t < T; ++t)
      tracks_[t].status = llr_.step(tracks_[t].status, tracks_[t].existence);
    mergeDuplicates();

    // Every measurement no gate validated starts a tentative track.
    for (Eigen::Index i = 0; i < M; ++i) {
      if (in_a_gate[i]) continue;
      Gaussian g;
      g.x = Eigen::Vector4d(z[i](0), z[i](1), 0, 0);
      g.P = Eigen::Vector4d(s_.sigma * s_.sigma, s_.sigma * s_.sigma,
                            s_.init_speed_sigma * s_.init_speed_sigma,
                            s_.init_speed_sigma * s_.init_speed_sigma)
                .asDiagonal();
      tracks_.push_back({ids_.next(),
                         imm_->init(g),
                         initialExistence(zdet[std::size_t(i)]->score),
                         TrackStatus::Tentative,
                         {}});
      tracks_.back().box.update(zdet[std::size_t(i)]->box, zdet[std::size_t(i)]->yaw,
                                zdet[std::size_t(i)]->score, 1);
      best_nis.push_back(std::nan(""));
    }
    report(f, best_nis);
  }

 private:
  // IMM-PDAF: each mode's PDA weights are the track's association probabilities re-weighted by
  // how well that mode explains each measurement (exactly per-mode PDA when tracks are
  // independent); the mode likelihoods follow from the same terms.
  void update(ImmTrack& tr, const AssociationProbabilities& a, Eigen::Index t, double miss,
              const Eigen::MatrixXd& e_mode, const std::vector<Eigen::VectorXd>& z) {
    const Eigen::Index M = Eigen::Index(z.size()), K = Eigen::Index(imm_->size());
    const double delta = (1 - miss) - a.effective_evidence.row(t).sum();
    tr.existence = existenceUpdate(tr.existence, delta);
    std::vector<Eigen::VectorXd> zs;
    std::vector<Eigen::Index> idx;
    for (Eigen::Index i = 0; i < M; ++i)
      if (a.beta(t, i) > 0) zs.push_back(z[i]), idx.push_back(i);
    Eigen::VectorXd log_lik(K);
    for (Eigen::Index j = 0; j < K; ++j) {
      // Mode j's share: β_0 ∝ b, β_i ∝ e*_ti · e_ij / e_ti.
      PdaWeights w;
      double total = miss;
      for (Eigen::Index i : idx) {
        const double e_track = a.effective_evidence(t, i);
        const double e_raw = tr.imm.mu.dot(e_mode.row(i));
        const double share = e_raw > 0 ? e_track * e_mode(i, j) / e_raw : 0;
        w.beta.push_back(share);
        total += share;
      }
      w.beta0 = miss / total;
      for (double& b : w.beta) b /= total;
      log_lik(j) = std::log(total);
      pdaUpdate(tr.imm.modes[j], meas_, zs, w);
    }
    Imm::updateProbabilities(tr.imm, log_lik);
  }

  static double clampProbability(double p) { return std::clamp(p, 1e-6, 1 - 1e-6); }
  double scoreRatio(double score) const {
    if (!(score >= 0 && score <= 1))
      throw DataError("detection score " + std::to_string(score) +
                      " is no probability: score_prior reads scores as P(person) in [0, 1] "
                      "(calibrate the detector's, e.g. with a score_logistic stage)");
    const double p = clampProbability(score), q = s_.score_prior;
    return (p / (1 - p)) / (q / (1 - q));
  }
  // A new track's existence: p_init, or with scores as evidence the detection's P, kept strictly
  // between the deletion and confirmation thresholds (one more look decides).
  double initialExistence(double score) const {
    if (!(s_.score_prior > 0)) return s_.p_init;
    const auto prob = [](double llr) { return 1 / (1 + std::exp(-llr)); };
    const double lo = prob(llr_.deleteThreshold()), hi = prob(llr_.confirmThreshold());
    const double margin = 1e-3 * (hi - lo);
    return std::clamp(clampProbability(score), lo + margin, hi - margin);
  }

  // The box moves towards the detections' boxes, each as much as it is the track's (β_i).
  // So does the detection score.
  static void updateBox(ImmTrack& tr, const AssociationProbabilities& a, Eigen::Index t,
                        const std::vector<const Detection*>& zdet) {
    double weight = 0, score = 0, box_weight = 0, best = 0, yaw = 0;
    Box3 mean;
    for (std::size_t i = 0; i < zdet.size(); ++i) {
      const double b = a.beta(t, Eigen::Index(i));
      if (!(b > 0)) continue;
      weight += b;
      score += b * zdet[i]->score;
      if (!zdet[i]->box.known()) continue;
      if (b > best) best = b, yaw = zdet[i]->yaw;  // headings do not average: the likeliest's
      const Box3& d = zdet[i]->box;
      box_weight += b;
      mean.z += b * d.z, mean.h += b * d.h, mean.w += b * d.w, mean.l += b * d.l;
    }
    if (!(weight > 0)) return;
    // Detections without a box say nothing of it (mean.h stays 0 when none has one).
    if (box_weight > 0)
      mean.z /= box_weight, mean.h /= box_weight, mean.w /= box_weight, mean.l /= box_weight;
    tr.box.update(mean, yaw, score / weight, weight);
  }

  // Two tracks on one person: the one less sure to exist goes.
  void mergeDuplicates() {
    for (std::size_t a = 0; a < tracks_.size(); ++a)
      for (std::size_t b = a + 1; b < tracks_.size(); ++b) {
        ImmTrack &x = tracks_[a], &y = tracks_[b];
        if (x.status == TrackStatus::Deleted || y.status == TrackStatus::Deleted) continue;
        const Gaussian gx = Imm::combine(x.imm), gy = Imm::combine(y.imm);
        if ((gx.x.head<2>() - gy.x.head<2>()).norm() > s_.merge_distance) continue;
        const bool keep_x =
            (x.status == TrackStatus::Confirmed) != (y.status == TrackStatus::Confirmed)
                ? x.status == TrackStatus::Confirmed
                : x.existence >= y.existence;
        (keep_x ? y : x).status = TrackStatus::Deleted;
      }
  }

  void report(Frame& f, const std::vector<double>& nis) {
    std::vector<ImmTrack> alive;
    for (std::size_t k = 0; k < tracks_.size(); ++k) {
      ImmTrack& tr = tracks_[k];
      if (log_)
        log_->row(f.t, f.index, tr.id, tr.existence, llr_.confirmThreshold(),
                  llr_.deleteThreshold(), toString(tr.status));
      if (tr.status == TrackStatus::Deleted) continue;
      if (tr.status == TrackStatus::Confirmed || s_.report_tentative) {
        Track row = trackRow(tr.id, Imm::combine(tr.imm), imm_->model(0));
        // With scores as evidence, how sure the detector was too: existence saturates near 1.
        row.score = s_.score_prior > 0 ? tr.existence * tr.box.score : tr.existence;
        row.model_probs.assign(tr.imm.mu.data(), tr.imm.mu.data() + tr.imm.mu.size());
        row.status = toString(tr.status);
        row.nis = nis[k];
        row.box = tr.box.box;
        if (row.box.known()) row.yaw = tr.box.yaw;  // a 3D detector's heading, not the velocity's
        f.tracks.push_back(std::move(row));
      }
      alive.push_back(std::move(tr));
    }
    tracks_ = std::move(alive);
    if (log_) log_->endFrame();
  }

  Settings s_;
  ExistenceLlr llr_;
  std::unique_ptr<Imm> imm_;
  LinearMeasurement meas_;
  double gamma_ = 0;
  FrameClock clock_;
  TrackIds ids_;
  std::vector<ImmTrack> tracks_;
  std::unique_ptr<ExistenceLog> log_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Tracker;
  d.doc = "IMM (CV + constant turns) with PDA/JPDA and existence-LLR track management (P4)";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<ImmPdaf>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::immpdaf

PEDTRACK_PLUGIN("imm_pdaf", pedtrack::immpdaf::describe)
