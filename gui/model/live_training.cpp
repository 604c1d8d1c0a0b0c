// Live retraining, part of StudioController: the loop "label a little, see the classifier
// improve, label what it still gets wrong". In its own file because it is one concept.
#include <algorithm>
#include <cstdio>
#include <tuple>

#include "gui/model/studio_controller.hpp"

namespace fieldlines::studio {

void StudioController::set_auto_train(bool on) {
  if (on == options_.auto_train) return;
  options_.auto_train = on;
  auto_train_pending_ = on;  // catch up with the labels made while it was off
}

void StudioController::start_auto_train() {
  auto_train_pending_ = false;
  AutoTrainInput in;
  std::tie(in.train, in.test) = labelled_by_split();
  if (in.train.empty()) return;  // nothing to learn from yet: proposals (P) stay label-free
  in.all = all_segments();
  in.start = project_.thresholds;
  in.params = proposal_params();
  auto_train_.start(std::move(in));
}

void StudioController::adopt_auto_train(const AutoTrainResult& r) {
  if (!options_.auto_train) return;  // turned off while it ran: the user's thresholds stay
  set_thresholds(r.made.thresholds);
  const bool has_proposals = std::any_of(project_.images.begin(), project_.images.end(),
                                         [](const ImageEntry& e) { return !e.proposals.empty(); });
  if (has_proposals) refresh_proposals(r.made.thresholds);
  curve_.push_back({r.train_segments + r.test_segments, r.test_segments, r.test_counts});
  char line[160];
  std::snprintf(line, sizeof line, "retrained on %zu train-split labels in %.0f ms (marking %s, boundary %s)", r.train_segments,
                r.elapsed_ms, std::string(to_string(r.made.marking)).c_str(),
                std::string(to_string(r.made.boundary)).c_str());
  auto_train_summary_ = line;
  if (!r.made.note.empty()) auto_train_summary_ += "; " + r.made.note;
}

void StudioController::wait_for_auto_train(double now_s) {
  poll(now_s);
  while (auto_train_busy() && options_.auto_train) {
    auto_train_.wait();
    poll(now_s);
  }
}

}  // namespace fieldlines::studio
