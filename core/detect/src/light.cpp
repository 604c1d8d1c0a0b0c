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
  std::array<Histogram, 3> h{};  // R, G, B
  std::uint32_t green = 0, samples = 0;
  const int row_step = std::max(params.row_step, 1), col_step = std::max(params.col_step, 1);
  for (int y = row_step / 2; y < bgr8.rows; y += row_step) {
    const std::uint8_t* row = bgr8.ptr<std::uint8_t>(y);
    for (int x = col_step / 2; x < bgr8.cols; x += col_step) {
      const std::uint8_t b = row[3 * x], g = row[3 * x + 1], r = row[3 * x + 2];
      ++samples;
      if (!params.green(b, g, r)) continue;
      ++h[0][r];
      ++h[1][g];
      ++h[2][b];
      ++green;
    }
  }
  if (samples == 0 || green < params.min_share * samples || green == 0) return std::nullopt;
  return Rgb{median_of(h[0], green), median_of(h[1], green), median_of(h[2], green)};
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
