#pragma once
// The project `fieldlines-studio` opens when started with nothing (and nothing opened before):
// synthetic field pictures in the user's data folder, generated once, detected in the background.
#include <filesystem>

namespace fieldlines::studio {

// $XDG_DATA_HOME/fieldlines/demo, else ~/.local/share/fieldlines/demo; throws fieldlines::Error
// when neither variable is set.
std::filesystem::path default_demo_folder();

// Writes `images` synthetic pictures into `folder` unless it already holds images; returns the
// folder (open it with open_project). Throws fieldlines::Error when it cannot write.
std::filesystem::path ensure_demo_images(const std::filesystem::path& folder, int images = 8);

}  // namespace fieldlines::studio
