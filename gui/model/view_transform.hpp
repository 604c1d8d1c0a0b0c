#pragma once
// Maps image coordinates to screen pixels and back: screen = offset + image * scale.
// Image coordinates are continuous: pixel (i, j) covers [i, i+1) x [j, j+1).
#include "gui/model/geometry.hpp"

namespace fieldlines::studio {

struct ViewLimits {
  float min_scale = 1.0f / 64;  // zoomed far out: a 4k image still covers a few pixels
  float max_scale = 64;         // zoomed far in: one image pixel is 64 screen pixels
};

class ViewTransform {
 public:
  explicit ViewTransform(ViewLimits limits = {}) : limits_(limits) {}

  float scale() const { return scale_; }
  Vec2 offset() const { return offset_; }
  Vec2 image_to_screen(Vec2 p) const { return offset_ + p * scale_; }
  Vec2 screen_to_image(Vec2 s) const { return {(s.x - offset_.x) / scale_, (s.y - offset_.y) / scale_}; }

  // Multiplies the scale by `factor` (clamped to the limits) keeping the image point under
  // `screen_point` where it is, so the wheel zooms at the cursor.
  void zoom_at(Vec2 screen_point, float factor);
  // Moves the image by a screen-pixel delta (a mouse drag).
  void pan(Vec2 screen_delta) { offset_ = offset_ + screen_delta; }
  // Largest scale showing the whole image inside `viewport`, centred. Ignores a degenerate
  // image or viewport (keeps the current view).
  void fit(Vec2 image_size, const Rect& viewport);
  void set(float scale, Vec2 offset);

 private:
  ViewLimits limits_;
  float scale_ = 1;
  Vec2 offset_{};
};

}  // namespace fieldlines::studio
