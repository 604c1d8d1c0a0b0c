#pragma once
// The Camera tab's form, window-free: whether the ground grid is drawn over the frame, the top
// view's range, the painted line width a fit may take the height from, and the camera file's
// path as typed (resolved as the Export tab's: export_path.hpp) with Save and Load. Each action
// reports in one line; a failure gives its reason and changes nothing (the studio's camera and
// the file on disk stay as they were).
#include <filesystem>
#include <string>

#include "fieldlines/train/camera_fit.hpp"
#include "gui/model/action_report.hpp"
#include "gui/model/camera_tuning.hpp"
#include "gui/model/export_path.hpp"

namespace fieldlines::studio {

class StudioController;

// Beside the thresholds file the Export tab offers (never inside the folder of images):
// `robot-camera.json` or `<folder>-camera.json`.
std::filesystem::path default_camera_path(const std::filesystem::path& project_file, std::span<const ImageEntry> images);

class CameraForm {
 public:
  // Once per frame, before drawing: a newly opened project starts from its default path with no
  // message; then the typed path is resolved from the project file's folder.
  void update(const StudioController& controller);
  void resolve();  // after an edit of path()

  std::string& path() { return path_; }
  const ExportTarget& target() const { return target_; }

  // Writes the studio's camera (camera_file.hpp's JSON) atomically where target() says.
  void save(const StudioController& controller);
  // Reads the camera file at target() and makes it the studio's camera.
  void load(StudioController& controller);
  // The typical camera for the current image (camera_tuning.hpp), to nudge from.
  void start_typical(StudioController& controller);
  // Adopts the finished fit (camera_fit_job.hpp's apply_camera_fit) and says what is next.
  void apply_fit(StudioController& controller);
  const std::string& message() const { return report_.text(); }
  bool failed() const { return report_.failed(); }

  bool show_grid = true;     // the ground grid over the frame while the tab is open
  GridParams grid;
  float top_view_range_m = 4;
  float line_width_cm = 0;   // the painted width for the fit's height; 0: the height is kept
  // The fit's parameters from the form (the line width when one is given).
  CameraFitParams fit_params() const;

 private:

  std::string path_;
  std::filesystem::path project_;  // the project the default path was made for
  std::filesystem::path base_;
  ExportTarget target_;
  ActionReport report_;
};

}  // namespace fieldlines::studio
