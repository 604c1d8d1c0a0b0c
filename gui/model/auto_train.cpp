#include "gui/model/auto_train.hpp"

#include <chrono>

namespace fieldlines::studio {

void AutoTrainJob::start(AutoTrainInput input) {
  job_.start([input = std::move(input)](std::stop_token stop, const auto&) {
    const auto t0 = std::chrono::steady_clock::now();
    AutoTrainResult r;
    r.made = proposal_thresholds(input.all, input.train, input.start, input.params, stop);
    r.train_counts = count_labelled(input.train, r.made.thresholds);
    r.test_counts = count_labelled(input.test, r.made.thresholds);
    r.train_segments = input.train.size();
    r.test_segments = input.test.size();
    r.elapsed_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return r;
  });
}

std::optional<AutoTrainResult> AutoTrainJob::poll() {
  const bool was_running = job_.running();
  job_.poll();
  if (!was_running || job_.running() || !job_.outcome()) return std::nullopt;
  if (!job_.outcome()->ok()) {
    error_ = job_.outcome()->error();
    return std::nullopt;
  }
  error_.clear();
  return job_.outcome()->value();
}

}  // namespace fieldlines::studio
