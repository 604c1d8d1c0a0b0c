#pragma once
// Threshold training (PSO + polish) on a worker thread. The worker only pushes messages; the UI
// thread calls poll() once per frame to take them, so the UI stays at full frame rate.
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "fieldlines/train/training.hpp"
#include "gui/model/message_queue.hpp"

namespace fieldlines::studio {

struct TrainingSnapshot {
  int iteration = 0, iterations = 0;
  double best_score = 0;
  Thresholds best;
  std::vector<Thresholds> particles;  // this iteration's swarm, for the scatter plot
  double elapsed_s = 0;
  double eta_s = 0;                   // from the mean time per iteration so far
};

struct TrainingOutcome {
  TrainResult result;
  Counts train_counts, test_counts;  // of result.thresholds on each split
  std::string error;                 // non-empty when training threw (e.g. nothing labelled)
};

class TrainingJob {
 public:
  TrainingJob() = default;
  ~TrainingJob();  // requests a stop and joins: no worker outlives its job
  TrainingJob(const TrainingJob&) = delete;
  TrainingJob& operator=(const TrainingJob&) = delete;

  // Starts training on copies of the data; a running job is cancelled and joined first.
  void start(std::vector<Segment> train, std::vector<Segment> test, const Thresholds& start,
             const TrainParams& params);
  // Asks the worker to stop after the current iteration; poll() then reports a cancelled outcome.
  void cancel();
  // True from start() until poll() has taken the outcome.
  bool running() const { return running_; }
  // Takes the queued messages (UI thread, once per frame). Returns how many were taken.
  std::size_t poll();
  // Blocks until the worker has finished and everything is polled (tests and shutdown).
  void wait();

  const std::vector<double>& best_scores() const { return best_scores_; }  // one per iteration
  const std::optional<TrainingSnapshot>& latest() const { return latest_; }
  const std::optional<TrainingOutcome>& outcome() const { return outcome_; }

 private:
  struct Message {
    std::optional<TrainingSnapshot> snapshot;
    std::optional<TrainingOutcome> outcome;
  };
  MessageQueue<Message> queue_;
  std::jthread worker_;
  bool running_ = false;
  std::vector<double> best_scores_;
  std::optional<TrainingSnapshot> latest_;
  std::optional<TrainingOutcome> outcome_;
};

}  // namespace fieldlines::studio
