#pragma once
// A detected line segment and its colour-gradient features.
//
// Conventions used by every fieldlines type (converted only at the reference CSV boundary):
//  - channels are in R, G, B order;
//  - grad_x is the usual left-to-right derivative, grad_y the usual image-DOWN derivative
//    (row below minus row above). The reference CSV stores B, G, R and the opposite y sign.
//  - both are the mean 3x3 RGB window along the segment, Sobel-filtered once and divided by 4,
//    so a full 0->255 step reads as 255.

#include <array>
#include <cstdint>
#include <string_view>

namespace fieldlines {

using Rgb = std::array<float, 3>;

// Numeric values match the reference implementation (0 none, 1 boundary, 2 marking).
enum class Label : std::int8_t { Unlabelled = -1, None = 0, Boundary = 1, Marking = 2 };

struct Segment {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // endpoints, pixels
  float saliency = 0;                    // count of validated (orientation-inlier) pixels
  Rgb grad_x{};                          // mean colour gradient, d/dx, R,G,B
  Rgb grad_y{};                          // mean colour gradient, image-down d/dy, R,G,B
  Label label = Label::None;             // predicted (detector) or annotated (dataset)
};

std::string_view to_string(Label label);
// Accepts "marking", "boundary", "none", "unlabelled"; returns false on anything else.
bool parse_label(std::string_view text, Label& out);

}  // namespace fieldlines
