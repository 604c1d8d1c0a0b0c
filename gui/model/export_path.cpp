#include "gui/model/export_path.hpp"

#include <algorithm>
#include <cstdlib>
#include <system_error>

#include "fieldlines/detect/error.hpp"

namespace fieldlines::studio {

namespace fs = std::filesystem;

ExportTarget resolve_export_path(std::string_view typed, const fs::path& base, std::string_view home) {
  ExportTarget target;
  // Pasted paths often carry a trailing newline or spaces; a file name never should.
  const auto first = typed.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) {
    target.error = "type a file name (e.g. robot-thresholds.json)";
    return target;
  }
  typed = typed.substr(first, typed.find_last_not_of(" \t\r\n") - first + 1);

  fs::path path;
  if (typed.front() == '~') {
    if (typed.size() > 1 && typed[1] != '/') {
      target.error = "only ~ and ~/ are expanded: write " + std::string(typed) + " as a full path";
      return target;
    }
    if (home.empty()) {
      target.error = "cannot expand ~: $HOME is not set";
      return target;
    }
    path = fs::path(home) / std::string(typed.substr(std::min<std::size_t>(2, typed.size())));
  } else {
    path = fs::path(std::string(typed));
  }
  target.from_base = path.is_relative();
  if (target.from_base) path = base / path;
  path = fs::absolute(path).lexically_normal();

  std::error_code ec;
  if (!path.has_filename() || fs::is_directory(path, ec)) {
    target.error = path.string() + " is a folder: add a file name (e.g. robot-thresholds.json)";
    return target;
  }
  const fs::path folder = path.parent_path();
  if (fs::exists(folder, ec) && !fs::is_directory(folder, ec)) {
    target.error = folder.string() + " is a file, not a folder";
    return target;
  }
  target.folder_exists = fs::is_directory(folder, ec);
  target.path = path;
  return target;
}

std::string home_folder() {
  const char* home = std::getenv("HOME");
  return home ? home : "";
}

fs::path default_export_path(const fs::path& project_file, std::span<const ImageEntry> images) {
  const fs::path folder = fs::absolute(project_file).lexically_normal().parent_path();
  // Image paths are relative to the project folder; one without a folder part lies in it.
  const bool among_images = std::any_of(images.begin(), images.end(), [](const ImageEntry& image) {
    return !fs::path(image.path).has_parent_path();
  });
  if (among_images && folder.has_filename()) {
    return folder.parent_path() / (folder.filename().string() + "-thresholds.json");
  }
  return folder / "robot-thresholds.json";
}

void create_parent_folders(const fs::path& file) {
  const fs::path folder = file.parent_path();
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw Error("cannot create folder " + folder.string() + ": " + ec.message());
}

}  // namespace fieldlines::studio
