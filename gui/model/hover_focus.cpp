#include "gui/model/hover_focus.hpp"

namespace fieldlines::studio {

void HoverFocus::hold(std::size_t image, std::size_t segment) {
  held_ = segment;
  image_ = image;
}

std::optional<std::size_t> HoverFocus::update(std::size_t image, std::size_t segment_count,
                                              std::optional<std::size_t> pointer, bool pointer_acted) {
  // A re-detection can leave fewer segments than the index held.
  if (held_ && (image != image_ || *held_ >= segment_count)) held_.reset();
  if (held_ && pointer_acted && pointer && *pointer != *held_) held_.reset();
  return held_ ? held_ : pointer;
}

}  // namespace fieldlines::studio
