#pragma once
// Where the CLI's `--draw` overlays go (detect, eval): a folder of PNGs, one per input image.
#include <filesystem>
#include <set>
#include <vector>

#include <opencv2/core/mat.hpp>

namespace fieldlines::cli {

// Creates the folder; throws fieldlines::Error naming `--draw` and the folder when it cannot.
void make_overlay_folder(const std::filesystem::path& dir);

// The overlay of `image` in `dir`: <stem>.png, or <stem>-2.png... when that one is in `used`
// already or would overwrite one of `inputs` (as canonical_path gives them); joins `used`.
std::filesystem::path next_overlay_path(const std::filesystem::path& dir, const std::filesystem::path& image,
                                        std::set<std::filesystem::path>& used,
                                        const std::set<std::filesystem::path>& inputs);

// Overlay file names, fixed before a batch so they do not depend on thread timing: each image's
// next_overlay_path, every input guarded.
std::vector<std::filesystem::path> overlay_paths(const std::vector<std::filesystem::path>& images,
                                                 const std::filesystem::path& dir);

// The path as the overlays compare it with the inputs: canonical where it can be, else absolute.
std::filesystem::path canonical_path(const std::filesystem::path& path);

// `overlay` as a PNG at `path`, atomically; throws fieldlines::Error when it cannot.
void write_overlay(const std::filesystem::path& path, const cv::Mat& overlay);

}  // namespace fieldlines::cli
