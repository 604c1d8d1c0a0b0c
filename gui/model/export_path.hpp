#pragma once
// How the Export tab reads the path a user typed: `~` from $HOME, relative paths from one stated
// base (the project file's folder: where the project lives, the same on every launch, whatever
// folder the studio was started from), and what is in the way of writing there.
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "fieldlines/data/project.hpp"

namespace fieldlines::studio {

struct ExportTarget {
  std::filesystem::path path;    // absolute and lexically normal; empty when `error` is set
  std::string error;             // why nothing can be written there (empty text, a folder, ...)
  bool folder_exists = false;    // path's parent folder exists (when false: offer to create it)
  bool from_base = false;        // the typed path was relative: it starts at `base`
  bool ok() const { return error.empty(); }
};

// `~` and `~/rest` expand from `home` (an error when it is empty); `~user` is not expanded
// and is an error rather than a folder literally called "~user". A relative path is taken from
// `base`. Never touches the disk except to look at what exists.
ExportTarget resolve_export_path(std::string_view typed, const std::filesystem::path& base, std::string_view home);

// $HOME, or empty when unset.
std::string home_folder();

// The default thresholds file: beside the image folder when the project file sits among its
// images (a folder opened as a project: `<folder>-thresholds.json` next to it), otherwise
// `robot-thresholds.json` beside the project file. Never inside the folder of images.
std::filesystem::path default_export_path(const std::filesystem::path& project_file,
                                          std::span<const ImageEntry> images);

// Creates `file`'s missing parent folders; throws fieldlines::Error naming the folder on failure.
void create_parent_folders(const std::filesystem::path& file);

}  // namespace fieldlines::studio
