#pragma once
// Frames drawn for the field-feature tests (stripes, intersections, centre circle): paint on
// turf with camera-like noise, since on a noiseless step edge ELSED's drawing finds no anchor.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "fieldlines/detect/ground_camera.hpp"

namespace fieldlines::test {

inline const cv::Scalar kTurf(50, 140, 40), kPaint(255, 255, 255), kDark(25, 25, 25);

// `clean` plus Gaussian noise of sd 4 per channel, the same for the same seed.
inline cv::Mat noisy(const cv::Mat& clean, std::uint64_t seed = 7) {
  cv::Mat noise(clean.size(), CV_16SC3), wide, out;
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::NORMAL, 0, 4);
  clean.convertTo(wide, CV_16SC3);
  wide += noise;
  wide.convertTo(out, CV_8UC3);
  return out;
}

// A camera for the 640x480 frames below (focal length 640 px, centred), pitch and roll in degrees.
inline GroundCamera ground_camera(double pitch_deg = 35, double roll_deg = 0, double height = 0.6) {
  constexpr double kDeg = std::numbers::pi / 180;
  return {.fx = 640, .fy = 640, .cx = 319.5, .cy = 239.5, .pitch_rad = pitch_deg * kDeg, .roll_rad = roll_deg * kDeg,
          .height_m = height};
}

// Turf with a circle of `radius` m centred at `centre` on it, painted `width` px wide as camera
// `c` sees it (its points behind the camera or far off the frame left out); no noise.
inline cv::Mat painted_ground_circle(const GroundCamera& c, cv::Point2d centre, double radius, int width) {
  cv::Mat clean(480, 640, CV_8UC3, kTurf);
  const GroundProjection projection(c);
  std::vector<cv::Point> outline;
  for (int k = 0; k < 720; ++k) {
    const double a = 2 * std::numbers::pi * k / 720;
    if (const auto p = projection.to_image({centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)}))
      if (std::abs(p->x) < 5000 && std::abs(p->y) < 5000) outline.emplace_back(cvRound(p->x * 16), cvRound(p->y * 16));
  }
  cv::polylines(clean, outline, true, kPaint, width, cv::LINE_AA, 4);
  return clean;
}

}  // namespace fieldlines::test
