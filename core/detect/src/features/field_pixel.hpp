#pragma once
// Whether a pixel shows the field or paint, against the frame's own field colour (light.hpp).
// One rule for the field boundary and the stripes: a loose "green dominates" test also passes
// grey walls under a greenish camera, so a field pixel must match the field's chromaticity and
// lie within a brightness range of it; paint is brighter than the field and nearly grey. With the
// frame's turf colours (turf_colours.hpp), a pixel in any of them is field too: the turf in sun
// and in shade, not only in the median's light.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "fieldlines/detect/field_boundary.hpp"
#include "fieldlines/detect/segment.hpp"
#include "fieldlines/detect/turf_colours.hpp"
#include "features/paint_profile.hpp"

namespace fieldlines {

// A stripe's paint peaks at least this many times the field colour's R + G + B (stripes.cpp); the
// second drawing's anchors need a pixel that bright beside them (detector.cpp).
constexpr float kPaintContrast = 1.1f;

// Whether the 8-bit B, G, R pixel `bgr`, whose B + G + R is `sum`, is nearly grey: its
// chromaticities r = R / sum and g = G / sum satisfy |r - 1/3| + |g - 1/3| <= max_chroma. Tested
// times 3 sum (|3 R - sum| + |3 G - sum| <= 3 max_chroma sum): exact, and no division. Paint's
// colour test, for the field boundary and the second drawing's anchors alike.
inline bool near_grey(const std::uint8_t* bgr, int sum, float max_chroma) {
  return std::abs(3 * bgr[2] - sum) + std::abs(3 * bgr[1] - sum) <= 3.0 * max_chroma * sum;
}

class FieldPixel {
 public:
  // `turf`, when given and measured, widens the field's colour to the frame's turf colours; it
  // must outlive this.
  FieldPixel(const Rgb& field, const FieldBoundaryParams& params, const TurfColours* turf = nullptr)
      : p_(params), sum_(std::max(field[0] + field[1] + field[2], 1.f)), r_(field[0] / sum_), g_(field[1] / sum_),
        turf_(turf && !turf->empty() ? turf : nullptr),
        tolerance_(turf_ ? params.turf_chroma_tolerance : params.chroma_tolerance) {}

  float field_sum() const { return sum_; }  // R + G + B of the field colour (at least 1)

  // `bgr` points at one 8-bit B, G, R pixel.
  bool field(const std::uint8_t* bgr) const {
    // The same value as the float sum of the three (exact either way): one conversion, not three.
    const float sum = float(bgr[0] + bgr[1] + bgr[2]);
    return bright_as_turf(sum) && field_chroma(bgr[2] / sum, bgr[1] / sum);
  }
  // field()'s two tests: a pixel's R + G + B, then its chromaticities r = R / sum, g = G / sum.
  bool bright_as_turf(float sum) const { return p_.brightness.contains(sum, sum_); }
  bool field_chroma(float r, float g) const {
    return std::abs(r - r_) + std::abs(g - g_) <= tolerance_ || (turf_ && turf_->contains(r, g));
  }
  float field_greyness_distance() const { return paint::greyness_distance(r_, g_); }  // the median's
  bool dark(const std::uint8_t* bgr) const {
    return float(bgr[0] + bgr[1] + bgr[2]) < p_.dark_brightness * sum_;
  }
  bool paint(const std::uint8_t* bgr) const {
    const int sum = bgr[0] + bgr[1] + bgr[2];
    return float(sum) >= p_.paint_brightness * sum_ && near_grey(bgr, sum, p_.paint_chroma);
  }

 private:
  FieldBoundaryParams p_;
  float sum_, r_, g_;
  const TurfColours* turf_;
  float tolerance_;  // of the chromaticity from the median's
};

// Turf followed along a column, sample by sample: field(), or a sample as bright as turf, at least
// `min_saturation` of the field colour's distance from grey, whose chromaticity lies within `step`
// of the last such sample's. Turf in a light the frame's colours miss (seen through a goal's
// net, a lit patch) changes colour gradually; a wall, a floor or paint jumps from it, and only a
// green one is as far from grey as turf.
class ChainedTurf {
 public:
  ChainedTurf(const FieldPixel& pixel, float step, float min_saturation)
      : pixel_(pixel), step_(step), floor_(min_saturation * pixel.field_greyness_distance()) {}
  bool field(const std::uint8_t* bgr) {
    const float sum = float(bgr[0] + bgr[1] + bgr[2]);
    if (!pixel_.bright_as_turf(sum)) return false;  // neither field nor turf in another light
    const float r = bgr[2] / sum, g = bgr[1] / sum;
    const bool turf = pixel_.field_chroma(r, g) || (chained_ && paint::greyness_distance(r, g) >= floor_ &&
                                                     std::abs(r - r_) + std::abs(g - g_) <= step_);
    if (turf) chained_ = true, r_ = r, g_ = g;
    return turf;
  }

 private:
  const FieldPixel& pixel_;
  float step_, floor_;
  bool chained_ = false;  // a field sample was met: r_, g_ are the last turf sample's
  float r_ = 0, g_ = 0;
};

}  // namespace fieldlines
