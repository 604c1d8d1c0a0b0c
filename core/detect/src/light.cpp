#include "fieldlines/detect/light.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace fieldlines {
namespace {

using Histogram = std::array<std::uint32_t, 256>;

float median_of(const Histogram& h, std::uint32_t count) {
  const std::uint32_t half = (count + 1) / 2;
  std::uint32_t seen = 0;
  for (int v = 0; v < 256; ++v) {
    seen += h[v];
    if (seen >= half) return float(v);
  }
  return 255.f;
}

}  // namespace

std::optional<Rgb> estimate_field_colour(const cv::Mat& bgr8, const FieldColourParams& params) {
  if (bgr8.empty() || bgr8.type() != CV_8UC3) return std::nullopt;
  // FieldGreen's test per sample without its float products: the least green that passes
  // against each red or blue value, found once with the test's own arithmetic.
  std::array<int, 256> least_green{};
  for (int v = 0; v < 256; ++v) {
    // From just below the product, a step or two up to the first green that the test passes.
    const float product = std::clamp(params.green.dominance * float(v), 0.f, 256.f);
    int g = std::max(params.green.min_green, product >= 1 ? static_cast<int>(product) - 1 : 0);
    while (g < 256 && !params.green(0, static_cast<std::uint8_t>(g), static_cast<std::uint8_t>(v))) ++g;
    least_green[static_cast<std::size_t>(v)] = g;
  }
  // Two sets of histograms, one for even and one for odd samples: neighbouring samples of turf
  // share their values, and one set would make each increment wait for the one before.
  std::array<std::array<Histogram, 3>, 2> h{};  // R, G, B
  std::uint32_t green = 0, samples = 0;
  const int row_step = std::max(params.row_step, 1), col_step = std::max(params.col_step, 1);
  for (int y = row_step / 2; y < bgr8.rows; y += row_step) {
    const std::uint8_t* row = bgr8.ptr<std::uint8_t>(y);
    for (int x = col_step / 2; x < bgr8.cols; x += col_step) {
      const std::uint8_t b = row[3 * x], g = row[3 * x + 1], r = row[3 * x + 2];
      std::array<Histogram, 3>& set = h[samples & 1];
      ++samples;
      if (g < least_green[r] || g < least_green[b]) continue;
      ++set[0][r];
      ++set[1][g];
      ++set[2][b];
      ++green;
    }
  }
  for (std::size_t c = 0; c < 3; ++c)
    for (std::size_t v = 0; v < 256; ++v) h[0][c][v] += h[1][c][v];
  if (samples == 0 || green < params.min_share * samples || green == 0) return std::nullopt;
  return Rgb{median_of(h[0][0], green), median_of(h[0][1], green), median_of(h[0][2], green)};
}

float light_gain(const Rgb& reference, const Rgb& frame) {
  const float r = reference[0] + reference[1] + reference[2], f = frame[0] + frame[1] + frame[2];
  return std::clamp(std::max(r, 1.f) / std::max(f, 1.f), 0.25f, 4.f);
}

int adapted_gradient_threshold(int threshold, double dark_field, const std::optional<Rgb>& field) {
  if (!(dark_field > 0) || !field) return threshold;
  const double brightness = static_cast<double>((*field)[0]) + (*field)[1] + (*field)[2];
  if (brightness >= dark_field) return threshold;
  const auto scaled = static_cast<int>(std::lround(threshold * brightness / dark_field));
  return std::clamp(scaled, std::min(threshold, kMinAdaptedGradient), threshold);
}

void apply_light_gain(std::span<Segment> segments, float gain) {
  for (Segment& s : segments)
    for (int c = 0; c < 3; ++c) {
      s.grad_x[c] *= gain;
      s.grad_y[c] *= gain;
    }
}

}  // namespace fieldlines
