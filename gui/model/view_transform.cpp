#include "gui/model/view_transform.hpp"

#include <algorithm>
#include <cmath>

namespace fieldlines::studio {

void ViewTransform::zoom_at(Vec2 screen_point, float factor) {
  if (!(factor > 0) || !std::isfinite(factor)) return;
  const Vec2 anchor = screen_to_image(screen_point);
  scale_ = std::clamp(scale_ * factor, limits_.min_scale, limits_.max_scale);
  // Solve screen_point = offset + anchor * scale for the new offset.
  offset_ = screen_point - anchor * scale_;
}

void ViewTransform::fit(Vec2 image_size, const Rect& viewport) {
  const Rect v = viewport.normalised();
  if (!(image_size.x > 0 && image_size.y > 0 && v.width() > 0 && v.height() > 0)) return;
  scale_ = std::clamp(std::min(v.width() / image_size.x, v.height() / image_size.y), limits_.min_scale,
                      limits_.max_scale);
  offset_ = {v.min.x + (v.width() - image_size.x * scale_) / 2, v.min.y + (v.height() - image_size.y * scale_) / 2};
}

void ViewTransform::set(float scale, Vec2 offset) {
  scale_ = std::clamp(scale, limits_.min_scale, limits_.max_scale);
  offset_ = offset;
}

}  // namespace fieldlines::studio
