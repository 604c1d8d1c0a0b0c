// Live retraining, part of StudioController: the loop "label a little, see the classifier
// improve, label what it still gets wrong". Its state is LiveRetraining (auto_train.hpp); this
// is what the controller gives it (labels) and takes from it (thresholds, proposals).
#include <algorithm>
#include <tuple>

#include "gui/model/studio_controller.hpp"

namespace fieldlines::studio {

void StudioController::start_auto_train() {
  AutoTrainInput in;
  std::tie(in.train, in.test) = labelled_by_split();
  if (in.train.empty()) {
    live_.skip();  // nothing to learn from yet: proposals (P) stay label-free
    return;
  }
  in.all = all_segments();
  in.gates = all_gates();
  in.train_gates = labelled_gates(false);
  in.start = proposal_start();
  in.params = proposal_params();
  if (test_images_ < kMinTestImages) in.leave_one_out = project_.labelled();
  live_.start(std::move(in));
}

void StudioController::adopt_auto_train(const AutoTrainResult& r) {
  follow_proposals(r.made);
  leave_one_out_ = r.leave_one_out;
  set_thresholds(r.made.thresholds);
  const bool has_proposals = std::any_of(project_.images.begin(), project_.images.end(),
                                         [](const ImageEntry& e) { return !e.proposals.empty(); });
  if (has_proposals) refresh_proposals(r.made.thresholds);
}

void StudioController::wait_for_auto_train(double now_s) {
  poll(now_s);
  while (auto_train_busy() && live_.on()) {
    live_.wait();
    poll(now_s);
  }
}

}  // namespace fieldlines::studio
