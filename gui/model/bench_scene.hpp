#pragma once
// The synthetic scene `fieldlines-studio --bench-frames N` renders when no project is given:
// a field-like image with many labelled segments in every colour and stroke style.
#include <filesystem>

#include "fieldlines/data/project.hpp"

namespace fieldlines::studio {

struct BenchSceneParams {
  int width = 640, height = 480;
  int segments = 300;
  unsigned seed = 7;
};

// Writes the image into `folder` (created if needed) and returns an unsaved project over it
// (image path relative to `folder`, i.e. for a project file inside `folder`).
Project write_bench_scene(const std::filesystem::path& folder, const BenchSceneParams& params = {});

}  // namespace fieldlines::studio
