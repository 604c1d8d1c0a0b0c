#include "gui/model/canvas_state.hpp"

#include "gui/model/studio_controller.hpp"

namespace fieldlines::studio {

const cv::Mat* CanvasState::picture_to_upload(const StudioController& controller) {
  const cv::Mat& image = controller.image();
  const bool tint_changed = show_missed && missed.update(image, controller.segments(), controller.image_generation());
  const bool tinted = show_missed && !missed.tinted().empty();
  if (uploaded_generation_ == controller.image_generation() && !tint_changed && tinted == uploaded_tinted_) return nullptr;
  uploaded_generation_ = controller.image_generation();
  uploaded_tinted_ = tinted;
  return tinted ? &missed.tinted() : &image;
}

}  // namespace fieldlines::studio
