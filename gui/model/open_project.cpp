#include "gui/model/open_project.hpp"

#include <system_error>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/data/image_io.hpp"

namespace fieldlines::studio {

DetectorParams folder_detector() {
  DetectorParams d;
  // The review proposes markings through the stripes check (proposal_gate.hpp), so the labels
  // and the thresholds trained on them are for a detector that runs it: the exported file says so.
  d.stripes = true;
  return d;
}

Project project_for_folder(const std::filesystem::path& folder, const std::filesystem::path& project_file) {
  Project project;
  project.detector = folder_detector();
  for (const auto& file : list_images(folder)) {
    std::error_code ec;
    const auto relative = std::filesystem::relative(file, project_file.parent_path(), ec);
    project.images.push_back({ec || relative.empty() ? file.string() : relative.string(), {}, 0});
  }
  if (project.images.empty()) {
    throw Error(folder.string() + ": no images (png, jpg, bmp, tif, webp, pnm) in this folder");
  }
  return project;
}

OpenedProject open_project(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  OpenedProject out;
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    out.file = path / kFolderProjectName;
    if (fs::exists(out.file, ec)) {
      out.project = Project::load(out.file);
    } else {
      out.project = project_for_folder(path, out.file);
      out.project.save(out.file);  // the folder now has a project to reopen
    }
  } else if (fs::is_regular_file(path, ec)) {
    out.file = path;
    out.project = Project::load(path);
  } else {
    throw Error(path.string() + ": no such project file or image folder");
  }
  // Hidden debris of saves killed mid-write (crash, SIGKILL); the project itself is intact.
  remove_stale_temporaries(out.file);
  for (const ImageEntry& image : out.project.images) out.needs_detection |= image.segments.empty() && image.detect_ms == 0;
  return out;
}

}  // namespace fieldlines::studio
