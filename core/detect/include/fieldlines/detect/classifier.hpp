#pragma once
// Classification of a segment by its colour transition (the method's step 3).
//
// A class is a colour transition: the gradient of a "from" colour turning into a "to" colour
// (top/left to bottom/right), e.g. field boundary = black wall above, green carpet below.
// A segment is a member when, for its gradient g projected on v = to - from:
//   projection  = g.v/|v|          >= min_projection   (|projection| if two-sided)
//   angle(g, v) in degrees         <= max_angle_deg    (folded into [0, 90] if two-sided)
//   saliency                       >= min_length
// The boundary class is tested first, on grad_y; the marking class on grad_y, then on grad_x.

#include <span>
#include <vector>

#include "fieldlines/detect/light.hpp"
#include "fieldlines/detect/segment.hpp"

namespace fieldlines {

struct ClassThresholds {
  float min_projection = 0;
  float max_angle_deg = 90;
  float min_length = 0;
  bool operator==(const ClassThresholds&) const = default;
};

struct ColourClass {
  Rgb from{};              // colour before the edge (above / left)
  Rgb to{};                // colour after the edge (below / right)
  bool two_sided = false;  // a painted line has both edges: ignore the sign
  ClassThresholds thresholds;
  bool operator==(const ColourClass&) const = default;
};

// Which gradient is compared with the transition.
enum class GradientMode {
  Axes,    // the reference: boundary on grad_y; marking on grad_y then grad_x
  Normal,  // orientation-invariant: the gradient along the segment's normal (from its endpoints)
};

struct Thresholds {
  // Defaults are the reference implementation's defaults (reference/README.md).
  ColourClass boundary{{0, 0, 0}, {0, 1, 0}, false, {27.78332309f, 51.21788891f, 95.33978007f}};
  ColourClass marking{{1, 1, 1}, {0, 1, 0}, true, {32.17114637f, 29.69457975f, 104.8096455f}};
  GradientMode mode = GradientMode::Axes;
  // The reference converts degrees with pi = 3.1415; set to reproduce it bit for bit.
  bool reference_pi = false;
  // Off by default; calibration from images turns it on (light.hpp). The detector then scales
  // each frame's segment gradients onto the calibration's light before classifying.
  LightAdaptation light;
  // Off by default: the frame's field boundary (field_boundary.hpp) gates both classes: a
  // marking above it is none (paint is on the field; white walls and boards beside it are not),
  // and so is a boundary edge away from it (a black robot standing on the field).
  bool field_boundary_gate = false;
  bool operator==(const Thresholds&) const = default;
};

// The per-class measurements a threshold set is compared with; cached by the trainer and the
// studio so that moving a threshold never needs re-detection.
struct ClassFeatures {
  float projection = 0;  // signed (one-sided) or absolute (two-sided) projection on v/|v|
  float angle_deg = 180; // angle between g and v, folded for two-sided; 180 when g is zero
};

// Features for one class: one entry per gradient tested (1 for boundary/Normal, 2 for marking/Axes).
struct SegmentFeatures {
  ClassFeatures boundary;
  ClassFeatures marking[2];
  int marking_count = 1;
  float length = 0;
};

SegmentFeatures compute_features(const Segment& segment, const Thresholds& thresholds);
bool passes(const ClassFeatures& f, float length, const ClassThresholds& t);
// The angle an achromatic (1,1,1) gradient makes with the class's transition, degrees: where
// every grey edge (wall, robot, shadow) lies, 35.26 for green-to-white.
double achromatic_angle_deg(const ColourClass& c);
Label classify(const SegmentFeatures& features, const Thresholds& thresholds);
Label classify(const Segment& segment, const Thresholds& thresholds);
// Relabels every segment in place.
void classify_all(std::span<Segment> segments, const Thresholds& thresholds);

}  // namespace fieldlines
