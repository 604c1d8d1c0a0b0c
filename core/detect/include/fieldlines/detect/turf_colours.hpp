#pragma once
// The colours of a frame's own turf, in as many modes as the frame shows. One median colour
// (light.hpp) describes a field under even light; a sunlit field with the shade of a window or a
// stand on it shows its turf in two or more chromaticities (sun is warmer, shade bluer), and
// real turf is patchy besides. A field boundary or a stripe check that knows only the median
// throws away the field in the other light, or the turf beside a line.
//
// The model is a chromaticity histogram (r = R / s, g = G / s, s = R + G + B) of the frame's
// green samples, smoothed over 3 x 3 bins; the turf is the connected set of bins grown from its
// peak while each holds at least `grow_share` of the peak's count and lies at least
// `min_saturation` of the field colour's distance from grey, widened by one bin (pixel noise at
// the set's rim). A camera's green cast puts walls, ceilings and stands among the green samples,
// pale and continuous with the turf's colours: the saturation floor keeps them out (without it
// the field boundary of every MSL frame ran up the walls). A green wall or shirt whose colour is
// no continuation of the turf's stays out; a second light on the same turf, which spreads the
// turf's own mode, is in. Fixed arrays: no allocation.
#include <array>
#include <cstdint>
#include <optional>

#include <opencv2/core/mat.hpp>

#include "fieldlines/detect/light.hpp"
#include "fieldlines/detect/segment.hpp"

namespace fieldlines {

// How much darker or brighter than the field colour turf may be (R + G + B over the field
// colour's): from shade to a sun patch. The field boundary's pixel test and the turf colours'
// samples share it.
struct TurfBrightness {
  float min = 0.25f, max = 2.5f;
  bool contains(float sum, float field_sum) const { return sum >= min * field_sum && sum <= max * field_sum; }
};

struct TurfColourParams {
  FieldColourParams sampling;  // the grid and the green test of the field colour's estimate
  float grow_share = 0.1f;     // a bin joins the turf with at least this share of the peak's count...
  float min_saturation = 0.75f;  // ...and |r - 1/3| + |g - 1/3| at least this share of the field colour's
  TurfBrightness brightness;     // the samples taken
};

class TurfColours {
 public:
  static constexpr int kBins = 64;  // per chromaticity axis over [0, 1): 1/64 per bin

  bool empty() const { return !measured_; }
  void clear() { measured_ = false; }
  // Whether chromaticities (r, g) lie in the turf's colours. False when empty.
  bool contains(float r, float g) const {
    if (!measured_) return false;
    const int i = bin(r), j = bin(g);
    return turf_[static_cast<std::size_t>(i * kBins + j)] != 0;
  }

  // 8-bit BGR `bgr8` whose field colour is `field`: measures the model (empty when the frame
  // shows no green sample in that colour's brightness range).
  void measure(const cv::Mat& bgr8, const Rgb& field, const TurfColourParams& params = {});

 private:
  static int bin(float v) { return v <= 0 ? 0 : v >= 1 ? kBins - 1 : static_cast<int>(v * kBins); }
  bool measured_ = false;
  std::array<std::uint8_t, kBins * kBins> turf_{};
  std::array<std::uint32_t, kBins * kBins> counts_{}, smoothed_{};
  std::array<std::uint16_t, kBins * kBins> queue_{};
};

// A frame's field colour as the stages that test pixels for turf take it (the stripes, the field
// boundary): its median and, when measured, its turf colours. Built from the median alone, it is
// the one-colour rule.
struct FieldColours {
  FieldColours(const std::optional<Rgb>& median_colour = std::nullopt, const TurfColours* turf_colours = nullptr)  // NOLINT: implicit
      : median(median_colour), turf(turf_colours) {}
  FieldColours(const Rgb& median_colour, const TurfColours* turf_colours = nullptr)  // NOLINT: implicit
      : median(median_colour), turf(turf_colours) {}
  std::optional<Rgb> median;
  const TurfColours* turf = nullptr;  // not owned; nullptr: the median's colour alone
  explicit operator bool() const { return median.has_value(); }
};

}  // namespace fieldlines
