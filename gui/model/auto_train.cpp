#include "gui/model/auto_train.hpp"

#include <chrono>
#include <cstdio>

namespace fieldlines::studio {

void AutoTrainJob::start(AutoTrainInput input) {
  job_.start([input = std::move(input)](std::stop_token stop, const auto&) {
    const auto t0 = std::chrono::steady_clock::now();
    AutoTrainResult r;
    // Label-free: one fit shared with leave-one-out.
    const Calibration fit = calibrate_gated(input.all, input.start, input.gates);
    r.made = proposal_thresholds(fit, input.train, input.start, input.params, stop,
                                 {input.train_gates.may_mark, input.train_gates.may_bound});
    r.train_counts = count_labelled(input.train, r.made.thresholds);
    r.test_counts = count_labelled(input.test, r.made.thresholds);
    r.train_segments = input.train.size();
    r.test_segments = input.test.size();
    r.few_test_images = input.leave_one_out.has_value();
    if (input.leave_one_out)
      r.leave_one_out = leave_one_image_out(fit, *input.leave_one_out, input.start, input.params, stop);
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

void LiveRetraining::set_on(bool on) {
  if (on == on_) return;
  on_ = on;
  pending_ = on;
}

void LiveRetraining::start(AutoTrainInput input) {
  pending_ = false;
  job_.start(std::move(input));
}

std::optional<AutoTrainResult> LiveRetraining::poll() {
  std::optional<AutoTrainResult> r = job_.poll();
  if (!job_.error().empty()) summary_ = "retraining failed: " + job_.error();
  if (!r || !on_) return std::nullopt;  // turned off while it ran: the user's thresholds stay
  CurvePoint point{r->train_segments + r->test_segments, r->test_segments, r->test_counts};
  if (r->leave_one_out.images > 0) {
    point.test = r->leave_one_out.pooled;
    point.leave_one_out = true;
  } else if (r->few_test_images) {
    point.judged = false;
  }
  curve_.push_back(point);
  char line[160];
  std::snprintf(line, sizeof line, "retrained on %zu train-split labels in %.0f ms (marking %s, boundary %s)",
                r->train_segments, r->elapsed_ms, std::string(to_string(r->made.marking)).c_str(),
                std::string(to_string(r->made.boundary)).c_str());
  summary_ = line;
  if (!r->made.note.empty()) summary_ += "; " + r->made.note;
  return r;
}

}  // namespace fieldlines::studio
