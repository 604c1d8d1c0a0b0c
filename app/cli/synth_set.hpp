#pragma once
// The images of a synthetic set (made by `fieldlines synth`) with their ground-truth files,
// shared by `autolabel` and `eval --gt`.
#include <filesystem>
#include <vector>

namespace fieldlines::cli {

struct SynthSetImage {
  std::filesystem::path image, truth;
};

// The images directly in `dir` (file-name order) that have DIR/truth/<name>.json.
// Throws fieldlines::Error when `dir` is not a folder or holds no image with ground truth.
// Defined in cmd_eval_gt.cpp: using it from autolabel also keeps `eval --gt` linked into the
// CLI.
std::vector<SynthSetImage> list_synth_set(const std::filesystem::path& dir);

}  // namespace fieldlines::cli
