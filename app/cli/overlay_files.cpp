#include "app/cli/overlay_files.hpp"

#include <set>
#include <string>
#include <string_view>
#include <system_error>

#include <opencv2/imgcodecs.hpp>

#include "app/cli/output_file.hpp"
#include "fieldlines/detect/error.hpp"

namespace fieldlines::cli {

namespace fs = std::filesystem;

void make_overlay_folder(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (!fs::is_directory(dir))
    throw Error("--draw " + dir.string() + ": cannot create the folder" + (ec ? " (" + ec.message() + ")" : ""));
}

fs::path canonical_path(const fs::path& path) {
  std::error_code ec;
  const fs::path c = fs::weakly_canonical(path, ec);
  return ec ? fs::absolute(path, ec).lexically_normal() : c;
}

fs::path next_overlay_path(const fs::path& dir, const fs::path& image, std::set<fs::path>& used,
                           const std::set<fs::path>& inputs) {
  const std::string stem = image.stem().string().empty() ? "image" : image.stem().string();
  fs::path out = dir / (stem + ".png");
  for (int k = 2; used.count(out) || inputs.count(canonical_path(out)); ++k)
    out = dir / (stem + "-" + std::to_string(k) + ".png");
  used.insert(out);
  return out;
}

std::vector<fs::path> overlay_paths(const std::vector<fs::path>& images, const fs::path& dir) {
  std::set<fs::path> inputs, used;
  for (const auto& p : images) inputs.insert(canonical_path(p));
  std::vector<fs::path> out;
  for (const auto& p : images) out.push_back(next_overlay_path(dir, p, used, inputs));
  return out;
}

void write_overlay(const fs::path& path, const cv::Mat& overlay) {
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", overlay, png)) throw Error("could not encode the overlay as PNG");
  write_output_file(path, std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

}  // namespace fieldlines::cli
