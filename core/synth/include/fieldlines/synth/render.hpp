#pragma once
// Ray-cast rendering of a synthetic world through a camera, with an exact label mask.
//
// One ray per pixel; pixels on a geometric edge (a change of surface or object) are re-rendered
// with supersample x supersample rays, and painted lines get their analytic coverage of the
// pixel footprint on the ground, so both kinds of edge are anti-aliased like a real lens would.
#include <cstdint>

#include <opencv2/core/mat.hpp>

#include "fieldlines/synth/camera.hpp"
#include "fieldlines/synth/conditions.hpp"
#include "fieldlines/synth/world.hpp"

namespace fieldlines::synth {

// Label mask values (one byte per pixel).
enum MaskClass : std::uint8_t {
  kMaskOther = 0,      // room, floor, ceiling, furniture, people behind the field
  kMaskCarpet = 1,     // field carpet without paint
  kMaskPaint = 2,      // painted line (coverage >= 0.5)
  kMaskFieldWall = 3,  // SSL boundary wall
  kMaskObject = 4,     // robots, ball, goals, doors and windows
};

struct RenderParams {
  int supersample = 3;  // rays per side on geometric edges (1 = off); 1..8
};

struct Rendered {
  cv::Mat bgr;   // CV_8UC3, before camera effects
  cv::Mat mask;  // CV_8UC1, MaskClass values
};

// Throws fieldlines::Error when supersample is out of range.
Rendered render(const World& world, const Camera& camera, const Lighting& lighting,
                const RenderParams& params = {});

}  // namespace fieldlines::synth
