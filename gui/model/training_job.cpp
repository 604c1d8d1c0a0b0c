#include "gui/model/training_job.hpp"

#include <chrono>
#include <cstdio>

#include "fieldlines/train/feature_table.hpp"
#include "fieldlines/train/metrics.hpp"
#include "gui/model/figures.hpp"

namespace fieldlines::studio {

std::string progress_line(const TrainingSnapshot& snap) {
  char line[128];
  if (snap.phase == TrainingPhase::Polish) {
    std::snprintf(line, sizeof line, "polish: best %.3f (PSO %.3f)", snap.best_score, snap.pso_best_score);
  } else {
    std::snprintf(line, sizeof line, "PSO %d/%d: best %.3f", snap.iteration, snap.iterations, snap.best_score);
  }
  return line;
}

std::string applied_summary(const Counts& counts, std::string_view split) {
  const auto pr = [](const ClassCounts& c) {
    return "P " + format_figure(c, c.precision()) + " R " + format_figure(c, c.recall());
  };
  return "applied: marking " + pr(counts.marking) + " | boundary " + pr(counts.boundary) + " on the " +
         std::string(split) + " split";
}

namespace {

// The gate's spans where they cover `n` segments; none otherwise (nothing gated).
LabelledCandidates candidates(const ProposalGate& gate, std::size_t n) {
  if (!gate.covers(n)) return {};
  return {gate.may_mark, gate.may_bound};
}

}  // namespace

void TrainingJob::start(std::vector<Segment> train_set, std::vector<Segment> test_set, const Thresholds& initial,
                        const TrainParams& params, ProposalGate train_gates, ProposalGate test_gates) {
  best_scores_.clear();
  latest_.reset();
  job_.start([train_set = std::move(train_set), test_set = std::move(test_set), initial, params,
              train_gates = std::move(train_gates), test_gates = std::move(test_gates)](std::stop_token stop,
                                                                                          const auto& report) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    const auto on_progress = [&](const TrainingProgress& p) {
      TrainingSnapshot snap;
      snap.phase = p.phase;
      snap.iteration = p.iteration;
      snap.iterations = p.iterations;
      snap.best_score = p.best_score;
      snap.best = p.best;
      snap.particles.assign(p.particles.begin(), p.particles.end());
      snap.elapsed_s = std::chrono::duration<double>(Clock::now() - t0).count();
      const bool swarming = p.phase == TrainingPhase::Pso && p.iteration > 0;
      snap.eta_s = swarming ? snap.elapsed_s / p.iteration * (p.iterations - p.iteration) : 0;
      report(std::move(snap));
    };
    TrainingResult r;
    r.run = train(train_set, initial, params, on_progress, stop, candidates(train_gates, train_set.size()));
    const auto counts = [&](const std::vector<Segment>& set, const ProposalGate& gate) {
      const ClassThresholds &b = r.run.thresholds.boundary.thresholds, &m = r.run.thresholds.marking.thresholds;
      return FeatureTable(set, r.run.thresholds, candidates(gate, set.size())).count(b, m);
    };
    r.train_counts = counts(train_set, train_gates);
    r.test_counts = counts(test_set, test_gates);
    return r;
  });
}

std::size_t TrainingJob::poll() {
  std::vector<TrainingSnapshot> snapshots = job_.poll();
  for (TrainingSnapshot& s : snapshots) {
    if (s.phase == TrainingPhase::Pso) {
      best_scores_.push_back(s.best_score);
    } else if (!best_scores_.empty()) {
      s.pso_best_score = best_scores_.back();
    }
    latest_ = std::move(s);
  }
  return snapshots.size();
}

}  // namespace fieldlines::studio
