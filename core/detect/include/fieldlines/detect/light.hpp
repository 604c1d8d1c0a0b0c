#pragma once
// Per-frame light adaptation: the classes' projection thresholds assume the exposure the
// thresholds were calibrated under; a frame in shade, in sun or with the camera's exposure
// changed scales every edge's contrast. The carpet is the one large surface every frame shows,
// so its brightness measures that scale: a frame's gradients are multiplied by
// brightness(reference field) / brightness(frame's field) before classification.
//
// One gain for all three channels, not one per channel (a diagonal light model): measured on
// the hand-drawn truth of real frames (docs/calibration.md), per-channel gains lowered marking
// precision at two of three MSL venues and made Humanoid frames refuse. Cameras' white balance
// already takes out the light's colour; dividing by the carpet's channels then tints the
// grey axis that the classes' angle tests are built on.
//
// The field colour is the per-channel median of a frame's green pixels (field_green.hpp),
// sampled on a grid; fixed-size histograms, so no allocation.
#include <optional>
#include <span>

#include <opencv2/core/mat.hpp>

#include "fieldlines/detect/field_green.hpp"
#include "fieldlines/detect/segment.hpp"

namespace fieldlines {

struct LightAdaptation {
  bool enabled = false;
  Rgb reference_field{};  // the field's colour under the calibration's light (R, G, B)
  bool operator==(const LightAdaptation&) const = default;
};

struct FieldColourParams {
  // Every col_step-th pixel of every row_step-th row (4,800 samples at 640x480): few rows, each
  // read densely, since a row's cache lines cost the time, not the pixels in them.
  int row_step = 16, col_step = 4;
  FieldGreen green;
  double min_share = 0.02;   // fewer green samples than this share: no field seen
};

// Empty when the frame shows too little green (8-bit BGR input).
std::optional<Rgb> estimate_field_colour(const cv::Mat& bgr8, const FieldColourParams& params = {});

// The gain that maps the frame's field brightness (R + G + B) onto the reference's, clamped to
// [1/4, 4] so that one odd frame cannot blow up.
float light_gain(const Rgb& reference, const Rgb& frame);

// Scales every segment's gradients by the gain.
void apply_light_gain(std::span<Segment> segments, float gain);

// The detector's gradient threshold for a frame whose field is `field`: `threshold` times the
// field's brightness (R + G + B) over `dark_field` when it is darker, never below
// kMinAdaptedGradient (sensor noise on any field); `threshold` when dark_field is 0 (off), the
// field is at least that bright, or the frame shows no field. Edge contrast scales with the
// exposure, so a dim frame then keeps the edges the threshold keeps on a bright one; the classes'
// tests see the frame's gradients scaled by light_gain() as before.
inline constexpr int kMinAdaptedGradient = 8;
int adapted_gradient_threshold(int threshold, double dark_field, const std::optional<Rgb>& field);

}  // namespace fieldlines
