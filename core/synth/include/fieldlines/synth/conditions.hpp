#pragma once
// Lighting conditions and camera effects of a synthetic image.
//
// Artificial: bright, even, neutral ceiling light. Natural: daylight through windows, a strong
// gradient across the field and a cool or warm cast. Mixed: both, with soft window patches.
// Dim: low light, so more sensor noise. Shadows: hard shadows of robots and sharp sun patches.
#include <span>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>

#include "fieldlines/train/random.hpp"
#include "fieldlines/synth/world.hpp"

namespace fieldlines::synth {

enum class Condition { Artificial, Natural, Mixed, Dim, Shadows };
std::string_view to_string(Condition c);
// Throws fieldlines::Error listing the known names.
Condition parse_condition(std::string_view text);
std::span<const Condition> all_conditions();

// A lit or shadowed convex quadrilateral on the ground (world xy, counter-clockwise).
struct LightPatch {
  Eigen::Vector2d corners[4];
  float gain = 1;  // multiplies the light inside (> 1 sun patch, < 1 shadow)
  Eigen::Vector2d lo{0, 0}, hi{0, 0};  // bounding box, for a quick reject
  bool contains(const Eigen::Vector2d& p) const;
};

struct Lighting {
  Condition condition = Condition::Artificial;
  float level = 1;                 // overall exposure
  Colour colour{1, 1, 1};          // light colour times the camera's tint, per channel
  Eigen::Vector2d gradient{0, 0};  // relative change per metre across the field (windows)
  float ambient = 0.75f;           // vertical surfaces: ambient share of the light
  Eigen::Vector3d sun{0.3, 0.2, 0.93};  // direction towards the main light (unit)
  std::vector<LightPatch> patches;
  float vignetting = 0.2f;    // relative darkening in the image corners
  float blur_sigma = 0.6f;    // optics, pixels
  float noise_sigma = 2.0f;   // sensor, grey levels
  int jpeg_quality = 90;      // 0: no compression
  // Light multiplier at a ground point (patches included).
  float ground_gain(const Eigen::Vector2d& p) const;
};

Lighting sample_lighting(Condition condition, const World& world, Rand& rand);

// Vignetting, blur, sensor noise and JPEG round trip, in that order, on an 8-bit BGR image.
// Deterministic for `seed`.
void apply_camera_effects(cv::Mat& bgr, const Lighting& lighting, std::uint64_t seed);

}  // namespace fieldlines::synth
