#pragma once
// Truth drawn by hand on real frames (tests/data/hand_truth/README.md): the painted lines as
// centre polylines with their width, the foot of a boundary wall, and the field boundary (the
// upper envelope of the turf). Scored with the same GtEdges as the synthetic truth.
//
// JSON schema "fieldlines-hand-truth" version 1 (one file per image):
//   { "schema": "fieldlines-hand-truth", "version": 1,
//     "image": "<path relative to the data folder>", "width": W, "height": H,
//     "annotated_by": "<how>",
//     "features": [ { "label": "marking"|"boundary_edge"|"field_boundary", "name": "...",
//                     "points": [[x, y, width_px], ...] }, ... ] }
#include <filesystem>
#include <string>
#include <vector>

#include "fieldlines/synth/truth.hpp"

namespace fieldlines::synth {

struct HandTruth {
  static constexpr int kVersion = 1;
  std::string image;   // relative to the data folder (../shared/data)
  int width = 0, height = 0;
  // Markings (label Marking) and wall feet (label Boundary): what segments are scored against.
  GroundTruth truth;
  // The field boundary polylines, left to right (empty: the field fills the frame).
  std::vector<std::vector<TruthPoint>> field_boundary;
};

// Per image column (`width` entries): the hand-drawn field boundary's row there, linear between
// its points, or -1 where no polyline spans the column (an occluder reaching the frame's edge).
std::vector<float> field_boundary_rows(const HandTruth& hand);

// Throws fieldlines::Error naming `context` and the bad field.
HandTruth hand_truth_from_json(const nlohmann::json& json, const std::string& context);
HandTruth load_hand_truth(const std::filesystem::path& path);
// The hand-truth files directly in `dir`, in file-name order; throws when there are none.
std::vector<std::filesystem::path> list_hand_truth(const std::filesystem::path& dir);

}  // namespace fieldlines::synth
