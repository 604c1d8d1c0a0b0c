#pragma once
// Turning command-line PATHs (images or folders) into the list of images a batch works on.
#include <filesystem>
#include <string>
#include <vector>

namespace fieldlines::cli {

struct FailedImage {
  std::filesystem::path path;
  std::string error;  // a user-facing message that names the path
};

struct ImageInputs {
  std::vector<std::filesystem::path> images;  // in command-line order; a folder's images sorted
  std::vector<FailedImage> failed;            // folders that could not be listed or hold no image
};

// A folder contributes its images (fieldlines::list_images); anything else is taken as an image
// as it is, so a missing or bad file is reported by the loader with its own message.
ImageInputs expand_image_inputs(const std::vector<std::string>& paths);

}  // namespace fieldlines::cli
