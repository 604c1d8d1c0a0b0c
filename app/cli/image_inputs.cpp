#include "app/cli/image_inputs.hpp"

#include <system_error>

#include "fieldlines/detect/error.hpp"
#include "fieldlines/data/image_io.hpp"

namespace fieldlines::cli {

ImageInputs expand_image_inputs(const std::vector<std::string>& paths) {
  ImageInputs out;
  for (const std::string& p : paths) {
    const std::filesystem::path path(p);
    std::error_code ec;
    if (!std::filesystem::is_directory(path, ec)) {
      out.images.push_back(path);
      continue;
    }
    try {
      auto images = list_images(path);
      if (images.empty())
        out.failed.push_back({path, path.string() + ": folder holds no image (png, jpg, jpeg, bmp, tif, tiff, webp, ppm, pgm, pnm)"});
      out.images.insert(out.images.end(), images.begin(), images.end());
    } catch (const Error& e) {
      out.failed.push_back({path, e.what()});
    }
  }
  return out;
}

}  // namespace fieldlines::cli
