#pragma once
// The built-in demo: a labelling project of synthetic SSL frames over every lighting condition,
// generated on first use into the user's data folder (never into the repository).
//
//   const std::filesystem::path project = fieldlines::ensure_demo();  // generates once
//   auto p = fieldlines::Project::load(project);
//
// Layout: <folder>/project.json, <folder>/images/*.png with images/truth/*.json and
// images/masks/*.png (ground truth, as `fieldlines synth` writes). The project's first
// `labelled_images` images carry labels from the exact ground truth; the others are unlabelled
// so there is something to label. The folder appears atomically: it is built under a temporary
// name and renamed, so an interrupted or concurrent first run never leaves a half demo behind.
#include <cstdint>
#include <filesystem>

namespace fieldlines {

struct DemoParams {
  std::filesystem::path folder;     // empty: default_demo_folder()
  int images_per_condition = 6;     // x 5 conditions = 30 images
  int labelled_images = 10;         // pre-labelled (spread over the conditions)
  std::uint64_t seed = 2024;
};

// $XDG_DATA_HOME/fieldlines/demo, else $HOME/.local/share/fieldlines/demo.
// Throws fieldlines::Error when neither variable is set.
std::filesystem::path default_demo_folder();

// The demo project file, generated first when <folder>/project.json does not exist.
// Throws fieldlines::Error naming the folder when it cannot be created or written.
std::filesystem::path ensure_demo(const DemoParams& params = {});

}  // namespace fieldlines
