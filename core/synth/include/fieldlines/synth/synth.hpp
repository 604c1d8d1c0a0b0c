#pragma once
// Synthetic field images with exact ground truth: the one-call API over the synth_* parts.
//
//   fieldlines::synth::SynthParams p;  p.field.scene = Scene::Kid;
//   auto sample = fieldlines::synth::generate(p, /*seed*/ 7, /*index*/ 0);  // image, mask, truth
//   fieldlines::synth::write_sample(sample, "out");
//
// A set on disk: DIR/<stem>.png (the image), DIR/masks/<stem>.png (label mask),
// DIR/truth/<stem>.json (ground truth, schema in synth_truth.hpp); stem = "<scene>_<seed>_<index>".
// Images and masks sit apart so any tool reading "the images in DIR" sees only the images.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "fieldlines/synth/camera.hpp"
#include "fieldlines/synth/conditions.hpp"
#include "fieldlines/synth/field.hpp"
#include "fieldlines/synth/render.hpp"
#include "fieldlines/synth/truth.hpp"
#include "fieldlines/synth/world.hpp"

namespace fieldlines::synth {

struct SynthParams {
  FieldParams field;
  // Image i is rendered under conditions[i % size()]; must not be empty.
  std::vector<Condition> conditions{Condition::Artificial};
  std::optional<CameraRanges> camera;  // default: default_camera_ranges(field.scene)
  Intrinsics intrinsics;               // image size and principal point (fx is drawn per image)
  ClutterParams clutter;
  RenderParams render;
  TruthParams truth;
  bool camera_effects = true;  // vignetting, blur, noise, JPEG
};

struct SynthSample {
  cv::Mat bgr;   // CV_8UC3
  cv::Mat mask;  // CV_8UC1, MaskClass values
  GroundTruth truth;
};

// Image `index` of the set `seed`: the same (params, seed, index) always gives the same bytes.
// Throws fieldlines::Error on invalid parameters.
SynthSample generate(const SynthParams& params, std::uint64_t seed, int index);

std::string sample_stem(Scene scene, std::uint64_t seed, int index);

struct SampleFiles {
  std::filesystem::path image, mask, truth;
};
SampleFiles sample_files(const std::filesystem::path& dir, const std::string& stem);
// The ground truth file of an image of a set (DIR/truth/<stem>.json).
std::filesystem::path truth_path(const std::filesystem::path& image);

// Writes the three files atomically (creating DIR/masks and DIR/truth). Throws
// fieldlines::Error naming the path when a file cannot be written.
SampleFiles write_sample(const SynthSample& sample, const std::filesystem::path& dir);

}  // namespace fieldlines::synth
