#pragma once
// What `fieldlines-studio PATH` opens: a project file, or a folder of images (whose project file
// is created inside it as fieldlines-project.json, or reopened when it already exists).
#include <filesystem>

#include "fieldlines/data/project.hpp"

namespace fieldlines::studio {

inline constexpr const char* kFolderProjectName = "fieldlines-project.json";

struct OpenedProject {
  Project project;
  std::filesystem::path file;    // where it is (auto)saved
  bool needs_detection = false;  // some images have no segments yet
};

// The detector a folder's new project starts with: the built-in one with the stripes stage on
// (the review's proposals assume it). Its first detection chooses the venue's from the frames
// (ProjectDetection::start).
DetectorParams folder_detector();

// A new project over the images directly inside `folder` (sorted, paths relative to the
// project file's folder), nothing detected yet, folder_detector(). Throws fieldlines::Error when
// there is no image.
Project project_for_folder(const std::filesystem::path& folder, const std::filesystem::path& project_file);

// Throws fieldlines::Error with a user-facing message for anything it cannot open.
OpenedProject open_project(const std::filesystem::path& path);

}  // namespace fieldlines::studio
