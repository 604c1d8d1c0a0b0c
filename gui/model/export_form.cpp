#include "gui/model/export_form.hpp"

#include <exception>
#include <system_error>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/error.hpp"
#include "gui/model/studio_controller.hpp"
#include "gui/model/studio_files.hpp"

namespace fieldlines::studio {

namespace {
namespace fs = std::filesystem;

// The path as written, with symbolic links and ".." resolved, for the "wrote ..." line.
std::string written_path(const fs::path& path) {
  std::error_code ec;
  const fs::path real = fs::weakly_canonical(path, ec);
  return (ec ? path : real).string();
}
}  // namespace

void ExportForm::update(const StudioController& controller) {
  const fs::path& project = controller.project_file();
  if (project_ != project) {
    project_ = project;
    path_ = default_export_path(project, controller.project().images).string();
    base_ = fs::absolute(project).lexically_normal().parent_path();
    report_.clear();
    preview_.clear();
  }
  resolve();
}

void ExportForm::resolve() {
  target_ = resolve_export_path(path_, base_, home_folder());
  browsed_ = target_.ok() ? target_.path.parent_path() : base_;
  file_name_ = target_.ok() ? target_.path.filename().string() : "robot-thresholds.json";
  std::error_code ec;
  while (browsed_.has_relative_path() && !fs::is_directory(browsed_, ec)) browsed_ = browsed_.parent_path();
}

std::string ExportForm::write(const StudioController& controller) {
  studio::export_thresholds(controller, target_.path);
  preview_ = read_file(target_.path);
  return "wrote " + written_path(target_.path);
}

void ExportForm::export_thresholds(const StudioController& controller) {
  if (!target_.ok()) return report_.set(target_.error, true);
  if (!target_.folder_exists)
    return report_.set("the folder does not exist: press \"Create folder and export\" to create it", true);
  report_.run([&] { return write(controller); });
}

void ExportForm::create_folder_and_export(const StudioController& controller) {
  report_.run([&] {
    if (!target_.ok()) throw Error(target_.error);
    create_parent_folders(target_.path);
    target_.folder_exists = true;
    return write(controller);
  });
}

void ExportForm::import_thresholds(StudioController& controller) {
  report_.run([&] {
    if (!target_.ok()) throw Error(target_.error);
    studio::import_thresholds(controller, target_.path);
    preview_ = read_file(target_.path);
    return "imported " + written_path(target_.path);
  });
}

void ExportForm::export_labels_csv(const StudioController& controller) {
  report_.run([&] {
    if (!target_.ok()) throw Error(target_.error);
    const fs::path csv = target_.path.parent_path() / (controller.project_file().stem().string() + "-labels.csv");
    const std::size_t rows = studio::export_labels_csv(controller, csv);
    return "wrote " + std::to_string(rows) + " labelled segments to " + written_path(csv) +
           " (the authors' reference CSV; `fieldlines train` reads it)";
  });
}

void ExportForm::choose_folder(const fs::path& folder) { path_ = (folder / file_name_).string(); }

}  // namespace fieldlines::studio
