#pragma once
// Where the CLI's `--draw` overlays go (detect, eval): a folder of PNGs, one per input image.
#include <filesystem>
#include <vector>

#include <opencv2/core/mat.hpp>

namespace fieldlines::cli {

// Creates the folder; throws fieldlines::Error naming `--draw` and the folder when it cannot.
void make_overlay_folder(const std::filesystem::path& dir);

// Overlay file names, fixed before a batch so they do not depend on thread timing: <stem>.png,
// or <stem>-2.png... when two inputs share a stem or the name would overwrite an input.
std::vector<std::filesystem::path> overlay_paths(const std::vector<std::filesystem::path>& images,
                                                 const std::filesystem::path& dir);

// `overlay` as a PNG at `path`, atomically; throws fieldlines::Error when it cannot.
void write_overlay(const std::filesystem::path& path, const cv::Mat& overlay);

}  // namespace fieldlines::cli
