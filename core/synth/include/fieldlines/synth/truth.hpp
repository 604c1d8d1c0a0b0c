#pragma once
// Exact ground truth of a synthetic image: where every painted line (and, for SSL, the foot of
// the boundary wall) is visible, as image-space polylines, plus how the image was made.
//
// JSON schema "fieldlines-synth-truth" version 1 (one file per image):
//   { "schema": "fieldlines-synth-truth", "version": 1,
//     "image": "<file name of the PNG>", "mask": "<mask PNG, relative to the JSON's folder>",
//     "scene": "ssl"|"kid", "condition": "artificial"|..., "seed": S, "index": I,
//     "line_width_m": W,
//     "camera": { "width", "height", "fx", "fy", "cx", "cy",
//                 "position": [x, y, z] (m), "yaw_deg", "pitch_deg", "roll_deg" },
//     "mask_classes": { "0": "other", "1": "carpet", "2": "paint", "3": "field wall", "4": "object" },
//     "features": [ { "label": "marking"|"boundary", "name": "touch line +y",
//                     "points": [[x, y, width_px], ...] }, ... ] }
// Points are centreline pixels (integer = pixel centre) in drawing order; width_px is the line's
// width across the image-space line (0 for the boundary, which is an edge, not a strip).
// A line hidden in the middle (a robot in front) gives two features with the same name.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "fieldlines/detect/segment.hpp"
#include "fieldlines/synth/camera.hpp"
#include "fieldlines/synth/conditions.hpp"
#include "fieldlines/synth/world.hpp"

namespace fieldlines::synth {

struct TruthPoint {
  float x = 0, y = 0, width = 0;
};

struct TruthFeature {
  Label label = Label::Marking;  // Marking or Boundary
  std::string name;
  std::vector<TruthPoint> points;  // at least 2
  double length_px() const;
};

struct GroundTruth {
  static constexpr int kVersion = 1;
  std::string image, mask;
  Scene scene = Scene::Ssl;
  Condition condition = Condition::Artificial;
  std::uint64_t seed = 0;
  int index = 0;
  double line_width = 0;
  Intrinsics intrinsics;
  Pose pose;
  std::vector<TruthFeature> features;
};

struct TruthParams {
  double step = 0.005;       // sampling step along a line, metres
  double tolerance = 0.25;   // polyline simplification, pixels (position and width)
};

// The visible features of `world` seen by `camera` (same ray casts as the renderer).
std::vector<TruthFeature> extract_features(const World& world, const Camera& camera,
                                           const TruthParams& params = {});

nlohmann::json to_json(const GroundTruth& truth);
// The "points" of one feature object, [[x, y, width_px], ...], at least 2, all finite; throws
// fieldlines::Error naming `context`. Shared with the hand-made truth (hand_truth.hpp).
std::vector<TruthPoint> truth_points_from_json(const nlohmann::json& feature, const std::string& context);
// Throws fieldlines::Error naming `context` (e.g. the file) and the bad field.
GroundTruth truth_from_json(const nlohmann::json& json, const std::string& context);
// Files: load throws fieldlines::Error on unreadable or malformed files; save is atomic.
GroundTruth load_truth(const std::filesystem::path& path);
void save_truth(const std::filesystem::path& path, const GroundTruth& truth);

}  // namespace fieldlines::synth
