#include "gui/model/training_job.hpp"

#include <chrono>
#include <exception>


namespace fieldlines::studio {

namespace {
Counts count_with(std::span<const Segment> segments, const Thresholds& t) {
  Counts counts;
  for (const Segment& s : segments) {
    if (s.label != Label::Unlabelled) tally(counts, s.label, classify(s, t));
  }
  return counts;
}
}  // namespace

TrainingJob::~TrainingJob() {
  if (worker_.joinable()) {
    worker_.request_stop();
    worker_.join();
  }
}

void TrainingJob::start(std::vector<Segment> train_set, std::vector<Segment> test_set, const Thresholds& initial,
                        const TrainParams& params) {
  if (worker_.joinable()) {
    worker_.request_stop();
    worker_.join();
  }
  queue_.drain();
  best_scores_.clear();
  latest_.reset();
  outcome_.reset();
  running_ = true;
  worker_ = std::jthread([this, train_set = std::move(train_set), test_set = std::move(test_set), initial,
                          params](std::stop_token stop) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    TrainingOutcome outcome;
    try {
      const auto on_progress = [&](const TrainingProgress& p) {
        TrainingSnapshot snap;
        snap.iteration = p.iteration;
        snap.iterations = p.iterations;
        snap.best_score = p.best_score;
        snap.best = p.best;
        snap.particles.assign(p.particles.begin(), p.particles.end());
        snap.elapsed_s = std::chrono::duration<double>(Clock::now() - t0).count();
        snap.eta_s = p.iteration > 0 ? snap.elapsed_s / p.iteration * (p.iterations - p.iteration) : 0;
        queue_.push({std::move(snap), std::nullopt});
      };
      outcome.result = train(train_set, initial, params, on_progress, stop);
      outcome.train_counts = count_with(train_set, outcome.result.thresholds);
      outcome.test_counts = count_with(test_set, outcome.result.thresholds);
    } catch (const std::exception& e) {
      outcome.error = e.what();
    }
    queue_.push({std::nullopt, std::move(outcome)});
  });
}

void TrainingJob::cancel() {
  if (worker_.joinable()) worker_.request_stop();
}

std::size_t TrainingJob::poll() {
  std::vector<Message> messages = queue_.drain();
  for (Message& m : messages) {
    if (m.snapshot) {
      best_scores_.push_back(m.snapshot->best_score);
      latest_ = std::move(m.snapshot);
    }
    if (m.outcome) {
      outcome_ = std::move(m.outcome);
      running_ = false;
    }
  }
  if (!running_ && worker_.joinable()) worker_.join();  // already finished: joins at once
  return messages.size();
}

void TrainingJob::wait() {
  if (worker_.joinable()) worker_.join();
  poll();
}

}  // namespace fieldlines::studio
