#include "gui/model/camera_form.hpp"

#include <exception>
#include <string>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/camera_file.hpp"
#include "fieldlines/detect/error.hpp"
#include "gui/model/studio_controller.hpp"

namespace fieldlines::studio {

namespace fs = std::filesystem;

fs::path default_camera_path(const fs::path& project_file, std::span<const ImageEntry> images) {
  fs::path path = default_export_path(project_file, images);
  std::string name = path.filename().string();
  const std::string thresholds = "thresholds";
  if (const auto at = name.rfind(thresholds); at != std::string::npos) name.replace(at, thresholds.size(), "camera");
  return path.replace_filename(name);
}

void CameraForm::update(const StudioController& controller) {
  if (project_ != controller.project_file()) {
    project_ = controller.project_file();
    path_ = default_camera_path(project_, controller.project().images).string();
    base_ = fs::absolute(project_).lexically_normal().parent_path();
    report_.clear();
  }
  resolve();
}

void CameraForm::resolve() { target_ = resolve_export_path(path_, base_, home_folder()); }

void CameraForm::save(const StudioController& controller) {
  report_.run([&] {
    if (!target_.ok()) throw Error(target_.error);
    if (!controller.camera()) throw Error("no camera to save: load one or start from a typical camera");
    write_file_atomically(target_.path, to_json(*controller.camera()).dump(2) + "\n");
    return "saved " + target_.path.string();
  });
}

void CameraForm::load(StudioController& controller) {
  report_.run([&] {
    if (!target_.ok()) throw Error(target_.error);
    controller.set_camera(load_camera_file(target_.path));
    return "loaded " + target_.path.string();
  });
}

void CameraForm::start_typical(StudioController& controller) {
  report_.run([&] {
    controller.set_camera(typical_camera(controller.image().cols, controller.image().rows));
    return std::string("a typical camera for this image size: nudge it, or fit it from the lines");
  });
}

void CameraForm::apply_fit(StudioController& controller) {
  report_.run([&] {
    if (!apply_camera_fit(controller)) throw Error("no fitted camera to apply");
    return std::string("applied the fitted camera: save it to keep it, re-detect to use it");
  });
}

CameraFitParams CameraForm::fit_params() const {
  CameraFitParams params;
  if (line_width_cm > 0) params.line_width_m = line_width_cm / 100.0;
  return params;
}

}  // namespace fieldlines::studio
