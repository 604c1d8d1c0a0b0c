#pragma once
// Threshold training (PSO + polish) as a background Job (gui/model/job.hpp): one snapshot per
// PSO iteration and one for the polish, then the trained thresholds with their counts on both
// splits, or the error.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fieldlines/train/training.hpp"
#include "gui/model/job.hpp"
#include "gui/model/proposal_gate.hpp"

namespace fieldlines::studio {

struct TrainingSnapshot {
  TrainingPhase phase = TrainingPhase::Pso;
  int iteration = 0, iterations = 0;
  double best_score = 0;              // Polish: the result's score (run.score)
  double pso_best_score = 0;          // Polish: the last PSO iteration's best, for comparison
  Thresholds best;
  std::vector<Thresholds> particles;  // this iteration's swarm (Polish: the polished starts)
  double elapsed_s = 0;
  double eta_s = 0;                   // from the mean time per iteration so far (0 once polished)
};

// The Train tab's progress line: "PSO 7/15: best 82.000" while the swarm runs, then
// "polish: best 84.000 (PSO 82.000)", the score the result reports.
std::string progress_line(const TrainingSnapshot& snap);

// Apply's confirmation, from the live counts once applied: "applied: marking P 0.912 R 0.880 |
// boundary P n/a R n/a on the test split" (n/a where a class has no data there).
std::string applied_summary(const Counts& counts, std::string_view split);

struct TrainingResult {
  TrainResult run;                   // run.cancelled when stopped early (the best so far)
  Counts train_counts, test_counts;  // of run.thresholds on each split
};

class TrainingJob {
 public:
  // Starts training on copies of the data; a running job is cancelled and joined first.
  // `train_gates` / `test_gates`, parallel to each split (or empty): what the robot's detector
  // lets each segment be (proposal_gate.hpp); training and both splits' counts then see it.
  void start(std::vector<Segment> train, std::vector<Segment> test, const Thresholds& start,
             const TrainParams& params, ProposalGate train_gates = {}, ProposalGate test_gates = {});
  // Asks the worker to stop after the current iteration; the outcome is then the best so far.
  void cancel() { job_.cancel(); }
  bool running() const { return job_.running(); }
  // Takes the queued snapshots and the outcome (UI thread, once per frame). Returns how many
  // snapshots were taken.
  std::size_t poll();
  // Blocks until the worker has finished and everything is polled (tests and shutdown).
  void wait() {
    job_.wait();
    poll();
  }

  const std::vector<double>& best_scores() const { return best_scores_; }  // one per PSO iteration
  const std::optional<TrainingSnapshot>& latest() const { return latest_; }
  // Failed when training threw (e.g. nothing labelled).
  const std::optional<Outcome<TrainingResult>>& outcome() const { return job_.outcome(); }

 private:
  std::vector<double> best_scores_;
  std::optional<TrainingSnapshot> latest_;
  Job<TrainingSnapshot, TrainingResult> job_;
};

}  // namespace fieldlines::studio
