#pragma once
// The synthetic scene `fieldlines-studio --bench-frames N` renders when no project is given:
// a field-like image with many labelled segments in every colour and stroke style, and field
// features of every kind drawn over them.
#include <filesystem>

#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/field_features.hpp"

namespace fieldlines::studio {

struct BenchSceneParams {
  int width = 640, height = 480;
  int segments = 300;
  unsigned seed = 7;
  int stripes = 60, intersections = 30;  // and one centre circle and a field boundary
};

// Writes the image into `folder` (created if needed) and returns an unsaved project over it
// (image path relative to `folder`, i.e. for a project file inside `folder`).
Project write_bench_scene(const std::filesystem::path& folder, const BenchSceneParams& params = {});

// The scene's field features (the studio shows them with every layer on): `stripes` centre
// lines with widths, `intersections` junctions of every type, a centre circle in perspective and
// a field boundary across the top with a point every 8 px (the detector's column step).
FieldFeatures bench_scene_features(const BenchSceneParams& params = {});

}  // namespace fieldlines::studio
