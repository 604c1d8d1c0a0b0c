#pragma once
// The studio's files for others, written from a controller's public state: the robot's
// thresholds file (fieldlines/detect/thresholds_file.hpp) with the studio's provenance (the
// split and its figures, under the keys `fieldlines train` writes), the labelled segments as the
// reference CSV, and a thresholds file read back in. All throw fieldlines::Error. The Export
// tab's form (export_form.hpp) calls these.
#include <cstddef>
#include <filesystem>

#include "gui/model/studio_controller.hpp"

namespace fieldlines::studio {

void export_thresholds(const StudioController& controller, const std::filesystem::path& path);
// Unlabelled segments are not in that format; returns how many rows were written.
std::size_t export_labels_csv(const StudioController& controller, const std::filesystem::path& path);
// The file's detector parameters and thresholds become the project's, saved at once.
void import_thresholds(StudioController& controller, const std::filesystem::path& path);

}  // namespace fieldlines::studio
