#pragma once
// Loading images for the detector with a clear fieldlines::Error for every bad file.
//
// What happens to unusual images (see docs/detect_and_bench.md for the full table):
//  - missing path, a folder, an empty (0-byte) file, a file OpenCV cannot decode (corrupt,
//    truncated, unknown format): Error "<path>: <reason>";
//  - 1-channel (grey) and 4-channel (BGRA) images, 8- and 16-bit: loaded unchanged; the detector
//    accepts them (grey is replicated, alpha dropped, 16-bit scaled by 1/256);
//  - other depths (32-bit float TIFF/EXR, signed) and 2-channel images: Error naming the type;
//  - images larger than ImageLoadParams::max_pixels: Error, checked from the file header before
//    decoding for PNG, JPEG, BMP and PNM, so a huge file never gets allocated;
//  - tiny images (< 3x3) load fine; the detector returns no segments for them.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

namespace fieldlines {

struct ImageLoadParams {
  // Refuse images with more pixels than this (default 100 Mpx, e.g. 12000x8000): a 3-channel
  // image that size already needs 300 MB before the detector's own buffers.
  std::int64_t max_pixels = 100'000'000;
};

// Reads an image keeping its depth and channels (cv::IMREAD_UNCHANGED), so 16-bit and alpha
// images reach the detector as they are. The result is 8U or 16U with 1, 3 or 4 channels.
// Throws fieldlines::Error "<path>: <reason>" on any failure.
cv::Mat load_image(const std::filesystem::path& path, const ImageLoadParams& params = {});

// Width and height from the file header without decoding the pixels (PNG, JPEG, BMP, PNM);
// nullopt for other formats or a header too damaged to read.
std::optional<cv::Size> probe_image_size(const std::filesystem::path& path);

// A file name's extension in lower case (".png" for "A.PNG"), empty when it has none: the one
// rule by which every tool tells file kinds apart.
std::string lower_extension(const std::filesystem::path& path);

// True for the extensions load_image is meant for (png, jpg, jpeg, bmp, tif, tiff, webp, ppm,
// pgm, pnm), case-insensitive.
bool has_image_extension(const std::filesystem::path& path);

// The regular files with an image extension directly inside `folder` (not recursive, hidden
// files skipped), sorted by file name so batches are reproducible.
// Throws fieldlines::Error when `folder` is not a readable folder.
std::vector<std::filesystem::path> list_images(const std::filesystem::path& folder);

// Any image load_image returns, as 8-bit BGR for drawing and saving (16-bit scaled by 1/256,
// grey replicated, alpha dropped). Shares data with `image` when it already is 8-bit BGR.
cv::Mat to_bgr8(const cv::Mat& image);

// Human-readable OpenCV pixel type, e.g. "16-bit 3-channel" (for messages).
std::string describe_type(int cv_type);

}  // namespace fieldlines
