#include "gui/model/train_form.hpp"

#include "gui/model/figures.hpp"
#include "gui/model/studio_controller.hpp"

namespace fieldlines::studio {

void TrainForm::toggle(StudioController& controller) const {
  if (controller.training().running()) {
    controller.cancel_training();
  } else {
    controller.start_training(params);
  }
}

bool TrainForm::apply(StudioController& controller) {
  if (!controller.apply_training_result()) return false;
  const bool tested = controller.test_segment_count() > 0;
  applied_thresholds_ = controller.thresholds();
  applied_message_ = applied_summary(tested ? controller.test_counts() : controller.train_counts(), tested ? "test" : "train");
  return true;
}

const std::string& TrainForm::applied_message(const StudioController& controller) const {
  static const std::string none;
  return applied_thresholds_ && *applied_thresholds_ == controller.thresholds() ? applied_message_ : none;
}

}  // namespace fieldlines::studio
