#include "gui/model/bench_scene.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "fieldlines/detect/error.hpp"

namespace fieldlines::studio {

Project write_bench_scene(const std::filesystem::path& folder, const BenchSceneParams& params) {
  std::filesystem::create_directories(folder);
  std::mt19937 rng(params.seed);
  std::uniform_real_distribution<float> ux(0, static_cast<float>(params.width - 1)),
      uy(0, static_cast<float>(params.height - 1)), len(15, 120), angle(0, 6.2831853f), grad(-255, 255);
  cv::Mat image(params.height, params.width, CV_8UC3, cv::Scalar(40, 140, 40));
  ImageEntry entry;
  entry.path = "bench.png";
  entry.detect_ms = 1;  // marks it as detected
  for (int i = 0; i < params.segments; ++i) {
    Segment s;
    s.x0 = ux(rng), s.y0 = uy(rng);
    const float l = len(rng), a = angle(rng);
    s.x1 = std::clamp(s.x0 + l * std::cos(a), 0.0f, static_cast<float>(params.width - 1));
    s.y1 = std::clamp(s.y0 + l * std::sin(a), 0.0f, static_cast<float>(params.height - 1));
    s.saliency = l;
    s.grad_x = {grad(rng), grad(rng), grad(rng)};
    s.grad_y = {grad(rng), grad(rng), grad(rng)};
    s.label = static_cast<Label>(static_cast<int>(rng() % 4) - 1);
    // Unlabelled segments carry a proposal, so the frame draws the review loop's dashed strokes.
    entry.proposals.push_back(s.label == Label::Unlabelled ? static_cast<Label>(rng() % 3) : Label::Unlabelled);
    cv::line(image, {static_cast<int>(s.x0), static_cast<int>(s.y0)}, {static_cast<int>(s.x1), static_cast<int>(s.y1)},
             cv::Scalar(235, 235, 235), 3);
    entry.segments.push_back(s);
  }
  const std::filesystem::path image_path = folder / entry.path;
  if (!cv::imwrite(image_path.string(), image)) throw Error(image_path.string() + ": cannot write the bench image");
  Project project;
  project.images.push_back(std::move(entry));
  return project;
}

}  // namespace fieldlines::studio
