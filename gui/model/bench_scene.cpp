#include "gui/model/bench_scene.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "fieldlines/detect/error.hpp"
#include "fieldlines/train/random.hpp"

namespace fieldlines::studio {

Project write_bench_scene(const std::filesystem::path& folder, const BenchSceneParams& params) {
  std::filesystem::create_directories(folder);
  // The one seeded generator (fieldlines/train/random.hpp): the same scene with every library.
  SplitMix64 rng(params.seed);
  const auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * static_cast<float>(rng.uniform()); };
  const float w = static_cast<float>(params.width - 1), h = static_cast<float>(params.height - 1);
  const auto grad = [&] { return uniform(-255, 255); };
  cv::Mat image(params.height, params.width, CV_8UC3, cv::Scalar(40, 140, 40));
  ImageEntry entry;
  entry.path = "bench.png";
  entry.detect_ms = 1;  // marks it as detected
  for (int i = 0; i < params.segments; ++i) {
    Segment s;
    s.x0 = uniform(0, w), s.y0 = uniform(0, h);
    const float l = uniform(15, 120), a = uniform(0, 6.2831853f);
    s.x1 = std::clamp(s.x0 + l * std::cos(a), 0.0f, w);
    s.y1 = std::clamp(s.y0 + l * std::sin(a), 0.0f, h);
    s.saliency = l;
    s.grad_x = {grad(), grad(), grad()};
    s.grad_y = {grad(), grad(), grad()};
    s.label = static_cast<Label>(static_cast<int>(rng.next() % 4) - 1);
    // Unlabelled segments carry a proposal, so the frame draws the review loop's dashed strokes.
    entry.proposals.push_back(s.label == Label::Unlabelled ? static_cast<Label>(rng.next() % 3) : Label::Unlabelled);
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

FieldFeatures bench_scene_features(const BenchSceneParams& params) {
  SplitMix64 rng(params.seed + 1);
  const auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * static_cast<float>(rng.uniform()); };
  const float w = static_cast<float>(params.width - 1), h = static_cast<float>(params.height - 1);
  FieldFeatures f;
  for (int i = 0; i < params.stripes; ++i) {
    Marking m;
    m.x0 = uniform(0, w), m.y0 = uniform(0.2f * h, h);
    const float l = uniform(30, 200), a = uniform(0, 6.2831853f);
    m.x1 = std::clamp(m.x0 + l * std::cos(a), 0.0f, w);
    m.y1 = std::clamp(m.y0 + l * std::sin(a), 0.0f, h);
    m.width = uniform(3, 12);
    f.markings.push_back(m);
  }
  constexpr JunctionType kTypes[] = {JunctionType::L, JunctionType::T, JunctionType::X};
  for (int i = 0; i < params.intersections; ++i) {
    Intersection j;
    j.x = uniform(0, w), j.y = uniform(0.2f * h, h);
    j.type = kTypes[static_cast<std::size_t>(i) % 3];
    j.num_rays = static_cast<int>(j.type) + 2;  // L 2, T 3, X 4
    const float start = uniform(0, 1.5f);
    for (int k = 0; k < j.num_rays; ++k)
      j.heading_rays[static_cast<std::size_t>(k)] = start + 6.2831853f * static_cast<float>(k) / static_cast<float>(j.num_rays);
    j.confidence = uniform(0.5f, 1);
    f.intersections.push_back(j);
  }
  f.ellipses.push_back({0.5f * w, 0.6f * h, 0.6f * w, 0.25f * h, 3, 0.9f});
  f.field_boundary.image_height = params.height;
  for (int x = 0; x < params.width; x += 8) {
    const float t = static_cast<float>(x) / w - 0.5f;
    f.field_boundary.points.push_back({static_cast<float>(x), 0.15f * h + 0.1f * h * t * t});
  }
  return f;
}

}  // namespace fieldlines::studio
