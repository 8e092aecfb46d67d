#include "imm_pdaf/jpda.h"

#include <numeric>
#include <vector>

namespace pedtrack::track {
namespace {

void fillEffective(AssociationProbabilities& a, const Eigen::VectorXd& miss) {
  a.effective_evidence = Eigen::MatrixXd::Zero(a.beta.rows(), a.beta.cols());
  for (Eigen::Index t = 0; t < a.beta.rows(); ++t)
    if (a.beta0(t) > 0) a.effective_evidence.row(t) = a.beta.row(t) / a.beta0(t) * miss(t);
}

void pdaRow(const Eigen::MatrixXd& e, const Eigen::VectorXd& miss, Eigen::Index t,
            AssociationProbabilities& a) {
  const double total = miss(t) + e.row(t).sum();
  a.beta.row(t) = e.row(t) / total;
  a.beta0(t) = miss(t) / total;
}

int find(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Depth-first over the cluster's tracks: each takes no measurement or a free gated one.
struct Enumerator {
  const Eigen::MatrixXd& e;
  const Eigen::VectorXd& miss;
  const std::vector<int>& tracks;
  std::vector<std::vector<int>> gated;  // per cluster track: its gated measurements
  std::vector<char> used;
  std::vector<int> choice;
  Eigen::MatrixXd mass;  // cluster track × (measurements + 1): summed event weights
  double total = 0;

  void run(std::size_t k, double w) {
    if (k == tracks.size()) {
      total += w;
      for (std::size_t j = 0; j < tracks.size(); ++j)
        mass(Eigen::Index(j), choice[j] < 0 ? e.cols() : choice[j]) += w;
      return;
    }
    const int t = tracks[k];
    choice[k] = -1;
    run(k + 1, w * miss(t));
    for (int i : gated[k]) {
      if (used[i]) continue;
      used[i] = 1;
      choice[k] = i;
      run(k + 1, w * e(t, i));
      used[i] = 0;
    }
  }
};

}  // namespace

AssociationProbabilities independentPda(const Eigen::MatrixXd& e, const Eigen::VectorXd& miss) {
  AssociationProbabilities a;
  a.beta = Eigen::MatrixXd::Zero(e.rows(), e.cols());
  a.beta0 = Eigen::VectorXd::Ones(e.rows());
  for (Eigen::Index t = 0; t < e.rows(); ++t) pdaRow(e, miss, t, a);
  fillEffective(a, miss);
  return a;
}

AssociationProbabilities jpda(const Eigen::MatrixXd& e, const Eigen::VectorXd& miss,
                              std::size_t max_events) {
  const int T = int(e.rows()), M = int(e.cols());
  AssociationProbabilities a;
  a.beta = Eigen::MatrixXd::Zero(T, M);
  a.beta0 = Eigen::VectorXd::Ones(T);
  // Clusters: tracks joined through a measurement both gate.
  std::vector<int> parent(T);
  std::iota(parent.begin(), parent.end(), 0);
  for (int i = 0; i < M; ++i) {
    int first = -1;
    for (int t = 0; t < T; ++t) {
      if (!(e(t, i) > 0)) continue;
      if (first < 0)
        first = t;
      else
        parent[find(parent, t)] = find(parent, first);
    }
  }
  std::vector<std::vector<int>> clusters(T);
  for (int t = 0; t < T; ++t) clusters[find(parent, t)].push_back(t);
  for (const auto& cl : clusters) {
    if (cl.empty()) continue;
    Enumerator en{e,
                  miss,
                  cl,
                  {},
                  std::vector<char>(M, 0),
                  std::vector<int>(cl.size(), -1),
                  Eigen::MatrixXd::Zero(Eigen::Index(cl.size()), M + 1)};
    double events = 1;  // an upper bound: Π (1 + gated count)
    for (int t : cl) {
      std::vector<int> g;
      for (int i = 0; i < M; ++i)
        if (e(t, i) > 0) g.push_back(i);
      events *= double(g.size() + 1);
      en.gated.push_back(std::move(g));
    }
    if (cl.size() == 1 || events > double(max_events)) {
      for (int t : cl) pdaRow(e, miss, t, a);
      if (cl.size() > 1) ++a.clusters_approximated;
      continue;
    }
    en.run(0, 1.0);
    ++a.clusters_enumerated;
    for (std::size_t j = 0; j < cl.size(); ++j) {
      const int t = cl[j];
      a.beta.row(t) = en.mass.row(Eigen::Index(j)).head(M) / en.total;
      a.beta0(t) = en.mass(Eigen::Index(j), M) / en.total;
    }
  }
  fillEffective(a, miss);
  return a;
}

}  // namespace pedtrack::track
