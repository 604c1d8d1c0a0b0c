// The true field boundary of a synthetic frame (feature_truth.hpp's carpet_top).
#include <algorithm>
#include <cstdint>

#include <Eigen/Core>

#include "fieldlines/synth/camera.hpp"
#include "fieldlines/synth/feature_truth.hpp"
#include "fieldlines/synth/field.hpp"
#include "fieldlines/synth/render.hpp"

namespace fieldlines::synth {

std::vector<float> carpet_top_rows(const GroundTruth& truth, const cv::Mat& mask) {
  const FieldModel field = make_field({.scene = truth.scene, .line_width = truth.line_width});
  const Camera camera(truth.intrinsics, truth.pose);
  const Eigen::Vector3d& c = camera.centre();
  const int width = truth.intrinsics.width, height = truth.intrinsics.height;
  const bool masked = mask.type() == CV_8UC1 && mask.cols == width && mask.rows == height;
  const auto hidden = [&](int u, int v) { return masked && mask.at<std::uint8_t>(v, u) == kMaskObject; };
  std::vector<float> out(static_cast<std::size_t>(std::max(width, 0)), -1.f);
  for (int u = 0; u < width; ++u)
    // The carpet is convex and flat, so its image is too: each column shows one run of it.
    for (int v = 0; v < height; ++v) {
      const Eigen::Vector3d dir = camera.ray(u, v);
      if (dir.z() >= 0) continue;  // at or above the horizon
      const double t = -c.z() / dir.z();
      if (field.on_carpet(c.x() + t * dir.x(), c.y() + t * dir.y())) {
        if (!hidden(u, v)) out[static_cast<std::size_t>(u)] = static_cast<float>(v);
        break;
      }
    }
  return out;
}

}  // namespace fieldlines::synth
