#pragma once
// Frames drawn for the field-feature tests (stripes, intersections, centre circle): paint on
// turf with camera-like noise, since on a noiseless step edge ELSED's drawing finds no anchor.
#include <cstdint>

#include <opencv2/core.hpp>

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

}  // namespace fieldlines::test
