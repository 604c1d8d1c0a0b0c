#pragma once
// Threshold training (PSO + polish) as a background Job (gui/model/job.hpp): one snapshot per
// iteration, then the trained thresholds with their counts on both splits, or the error.
#include <cstddef>
#include <optional>
#include <vector>

#include "fieldlines/train/training.hpp"
#include "gui/model/job.hpp"

namespace fieldlines::studio {

struct TrainingSnapshot {
  int iteration = 0, iterations = 0;
  double best_score = 0;
  Thresholds best;
  std::vector<Thresholds> particles;  // this iteration's swarm, for the scatter plot
  double elapsed_s = 0;
  double eta_s = 0;                   // from the mean time per iteration so far
};

struct TrainingResult {
  TrainResult run;                   // run.cancelled when stopped early (the best so far)
  Counts train_counts, test_counts;  // of run.thresholds on each split
};

class TrainingJob {
 public:
  // Starts training on copies of the data; a running job is cancelled and joined first.
  void start(std::vector<Segment> train, std::vector<Segment> test, const Thresholds& start,
             const TrainParams& params);
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

  const std::vector<double>& best_scores() const { return best_scores_; }  // one per iteration
  const std::optional<TrainingSnapshot>& latest() const { return latest_; }
  // Failed when training threw (e.g. nothing labelled).
  const std::optional<Outcome<TrainingResult>>& outcome() const { return job_.outcome(); }

 private:
  std::vector<double> best_scores_;
  std::optional<TrainingSnapshot> latest_;
  Job<TrainingSnapshot, TrainingResult> job_;
};

}  // namespace fieldlines::studio
