// The built-in demo: generated once into the data folder, loadable, partly labelled.
#include <cstdlib>
#include <filesystem>
#include <set>

#include <unistd.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/data/project.hpp"
#include "fieldlines/synth/demo.hpp"
#include "fieldlines/synth/synth.hpp"

namespace fieldlines {
namespace {

namespace fs = std::filesystem;

TEST(Demo, DefaultFolderFollowsXdgDataHome) {
  const char* old = std::getenv("XDG_DATA_HOME");
  const std::string saved = old ? old : "";
  setenv("XDG_DATA_HOME", "/tmp/xdg-test", 1);
  EXPECT_EQ(default_demo_folder(), fs::path("/tmp/xdg-test/fieldlines/demo"));
  unsetenv("XDG_DATA_HOME");
  const char* home = std::getenv("HOME");
  if (home != nullptr && *home != '\0') {
    EXPECT_EQ(default_demo_folder(), fs::path(home) / ".local/share/fieldlines/demo");
  }
  if (old) setenv("XDG_DATA_HOME", saved.c_str(), 1);
}

TEST(Demo, GeneratesOnceIntoAProjectFile) {
  const fs::path dir = fs::temp_directory_path() / ("fieldlines_demo_test_" + std::to_string(::getpid())) / "demo";
  fs::remove_all(dir.parent_path());
  DemoParams p;
  p.folder = dir;
  p.images_per_condition = 2;
  p.labelled_images = 4;
  const fs::path project_file = ensure_demo(p);
  ASSERT_TRUE(fs::exists(project_file));
  // Read as plain JSON (the project schema in dataset.hpp): image paths and per-segment labels.
  const nlohmann::json project = nlohmann::json::parse(read_file(project_file));
  ASSERT_EQ(project.at("format"), "fieldlines-project");
  const auto& images = project.at("images");
  ASSERT_EQ(images.size(), 10u);  // 2 x 5 conditions
  std::size_t labelled_images = 0, labelled_segments = 0;
  std::set<synth::Condition> conditions;
  for (const auto& e : images) {
    const fs::path image = Project::resolve(project_file, e.at("path").get<std::string>());
    EXPECT_TRUE(fs::exists(image)) << image;
    ASSERT_TRUE(fs::exists(synth::truth_path(image)));
    conditions.insert(synth::load_truth(synth::truth_path(image)).condition);
    std::size_t labelled = 0;
    for (const auto& seg : e.at("segments")) labelled += seg.at(11).get<std::string>() != "unlabelled";
    labelled_images += labelled > 0;
    labelled_segments += labelled;
  }
  EXPECT_GE(labelled_images, 3u);  // an image may have no segment at all
  EXPECT_LE(labelled_images, 4u);
  EXPECT_GT(labelled_segments, 10u);
  EXPECT_EQ(conditions.size(), 5u);  // every lighting condition is in the demo

  // A second call reuses the demo instead of regenerating it.
  const auto stamp = fs::last_write_time(project_file);
  EXPECT_EQ(ensure_demo(p), project_file);
  EXPECT_EQ(fs::last_write_time(project_file), stamp);
  // No temporary folder is left behind.
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.parent_path())) ++entries;
  EXPECT_EQ(entries, 1);
  fs::remove_all(dir.parent_path());
}

}  // namespace
}  // namespace fieldlines
