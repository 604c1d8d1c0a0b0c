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

std::vector<fs::path> overlay_paths(const std::vector<fs::path>& images, const fs::path& dir) {
  auto canonical = [](const fs::path& p) {
    std::error_code ec;
    const fs::path c = fs::weakly_canonical(p, ec);
    return ec ? fs::absolute(p, ec).lexically_normal() : c;
  };
  std::set<fs::path> inputs;
  for (const auto& p : images) inputs.insert(canonical(p));
  std::set<std::string> used;
  std::vector<fs::path> out;
  for (const auto& p : images) {
    const std::string stem = p.stem().string().empty() ? "image" : p.stem().string();
    std::string name = stem + ".png";
    for (int k = 2; used.count(name) || inputs.count(canonical(dir / name)); ++k)
      name = stem + "-" + std::to_string(k) + ".png";
    used.insert(name);
    out.push_back(dir / name);
  }
  return out;
}

void write_overlay(const fs::path& path, const cv::Mat& overlay) {
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", overlay, png)) throw Error("could not encode the overlay as PNG");
  write_output_file(path, std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

}  // namespace fieldlines::cli
