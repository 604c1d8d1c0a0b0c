// The Export tab's path rules without a window: ~ expansion, the relative base, what exists,
// the default location and creating a missing folder.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "fieldlines/detect/error.hpp"
#include "fixtures.hpp"
#include "gui/model/export_path.hpp"
#include "gui/model/folder_listing.hpp"
#include "gui/model/studio_controller.hpp"
#include "gui/model/studio_files.hpp"

namespace fs = std::filesystem;
using fieldlines::studio::default_export_path;
using fieldlines::studio::resolve_export_path;

TEST(ExportPath, TildeExpandsFromHome) {
  studio_test::TempDir home("home");
  const fs::path base = "/srv/project";
  const auto t = resolve_export_path("~/x/robot.json", base, home.path().string());
  ASSERT_TRUE(t.ok()) << t.error;
  EXPECT_EQ(t.path, home.path() / "x" / "robot.json");
  EXPECT_FALSE(t.folder_exists);  // ~/x does not exist yet: the panel offers to create it

  fs::create_directories(home.path() / "x");
  EXPECT_TRUE(resolve_export_path("~/x/robot.json", base, home.path().string()).folder_exists);
  // A file straight in $HOME, and the folder itself is no file name.
  EXPECT_EQ(resolve_export_path("~/robot.json", base, home.path().string()).path, home.path() / "robot.json");
  EXPECT_FALSE(resolve_export_path("~", base, home.path().string()).ok());
  EXPECT_FALSE(resolve_export_path("~/", base, home.path().string()).ok());
}

TEST(ExportPath, TildeWithoutHomeOrWithAUserIsAnErrorNotAFolderCalledTilde) {
  const auto no_home = resolve_export_path("~/robot.json", "/srv/project", "");
  EXPECT_FALSE(no_home.ok());
  EXPECT_TRUE(no_home.path.empty());
  EXPECT_NE(no_home.error.find("HOME"), std::string::npos) << no_home.error;
  const auto user = resolve_export_path("~bob/robot.json", "/srv/project", "/home/me");
  EXPECT_FALSE(user.ok());
  EXPECT_TRUE(user.path.empty());
  // A tilde inside a name is an ordinary character.
  EXPECT_EQ(resolve_export_path("a~b.json", "/srv/project", "/home/me").path, fs::path("/srv/project/a~b.json"));
}

TEST(ExportPath, RelativePathsStartAtTheBaseAndAreNormalised) {
  studio_test::TempDir dir("base");
  const auto here = resolve_export_path("robot.json", dir.path(), "/home/me");
  ASSERT_TRUE(here.ok()) << here.error;
  EXPECT_EQ(here.path, dir.path() / "robot.json");
  EXPECT_TRUE(here.folder_exists);
  EXPECT_TRUE(here.from_base);  // the panel says where a relative path starts
  EXPECT_FALSE(resolve_export_path("/tmp/r.json", dir.path(), "").from_base);
  EXPECT_FALSE(resolve_export_path("~/r.json", dir.path(), "/home/me").from_base);
  EXPECT_EQ(resolve_export_path("sub/../up/./r.json", dir.path(), "").path, dir.path() / "up" / "r.json");
  EXPECT_EQ(resolve_export_path("../r.json", dir.path(), "").path, dir.path().parent_path() / "r.json");
  // Absolute paths ignore the base; surrounding blanks (a pasted line) are dropped.
  EXPECT_EQ(resolve_export_path("  /tmp/r.json\n", dir.path(), "").path, fs::path("/tmp/r.json"));
}

TEST(ExportPath, FoldersFilesInTheWayAndEmptyTextAreErrors) {
  studio_test::TempDir dir("errors");
  EXPECT_FALSE(resolve_export_path("", dir.path(), "").ok());
  EXPECT_FALSE(resolve_export_path("   ", dir.path(), "").ok());
  fs::create_directories(dir.path() / "existing");
  const auto folder = resolve_export_path("existing", dir.path(), "");
  EXPECT_FALSE(folder.ok());
  EXPECT_NE(folder.error.find("folder"), std::string::npos) << folder.error;
  EXPECT_FALSE(resolve_export_path("new/", dir.path(), "").ok());
  std::ofstream(dir.path() / "plain.txt") << "x";
  const auto under_file = resolve_export_path("plain.txt/robot.json", dir.path(), "");
  EXPECT_FALSE(under_file.ok());
  EXPECT_NE(under_file.error.find("not a folder"), std::string::npos) << under_file.error;
}

TEST(ExportPath, DefaultIsNeverInsideTheImageFolder) {
  // A folder opened as a project: the project file lies among the images.
  std::vector<fieldlines::ImageEntry> images(2);
  images[0].path = "0001.png";
  images[1].path = "0002.png";
  EXPECT_EQ(default_export_path("/data/nao-field/fieldlines-project.json", images),
            fs::path("/data/nao-field-thresholds.json"));
  // A project file beside its image folder: the file goes beside the project file.
  images[0].path = "frames/0001.png";
  images[1].path = "frames/0002.png";
  EXPECT_EQ(default_export_path("/data/match/project.json", images), fs::path("/data/match/robot-thresholds.json"));
  EXPECT_EQ(default_export_path("/data/match/project.json", {}), fs::path("/data/match/robot-thresholds.json"));
  // Relative project files are made absolute.
  EXPECT_TRUE(default_export_path("project.json", {}).is_absolute());
}

TEST(ExportPath, CreatesMissingFoldersOrSaysWhichOneFailed) {
  studio_test::TempDir dir("create");
  const fs::path file = dir.path() / "a" / "b" / "robot.json";
  fieldlines::studio::create_parent_folders(file);
  EXPECT_TRUE(fs::is_directory(dir.path() / "a" / "b"));
  EXPECT_FALSE(fs::exists(file));  // only the folders
  std::ofstream(dir.path() / "plain.txt") << "x";
  try {
    fieldlines::studio::create_parent_folders(dir.path() / "plain.txt" / "sub" / "robot.json");
    FAIL() << "a folder under a file was created";
  } catch (const fieldlines::Error& e) {
    EXPECT_NE(std::string(e.what()).find("plain.txt"), std::string::npos) << e.what();
  }
}

// A folder nobody can write to (not even root: /proc takes no new files) gives an error that
// names the path, and nothing is written: what the panel shows instead of "wrote".
TEST(ExportPath, UnwritablePlacesAreClearErrorsAndWriteNothing) {
  studio_test::TempDir dir("unwritable");
  const fs::path file = studio_test::write_project(dir.path(), 1, 4);
  const fieldlines::studio::StudioController c(fieldlines::Project::load(file), file);
  const auto target = resolve_export_path("/proc/robot-thresholds.json", dir.path(), "");
  ASSERT_TRUE(target.ok()) << target.error;
  EXPECT_TRUE(target.folder_exists);
  try {
    fieldlines::studio::export_thresholds(c, target.path);
    FAIL() << "exported into /proc";
  } catch (const fieldlines::Error& e) {
    EXPECT_NE(std::string(e.what()).find("/proc/robot-thresholds.json"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(target.path));
  EXPECT_THROW(fieldlines::studio::create_parent_folders("/proc/fieldlines-new/robot.json"), fieldlines::Error);
  EXPECT_FALSE(fs::exists("/proc/fieldlines-new"));
}

TEST(FolderListing, ListsSubfoldersOnceUntilTheFolderChangesOrTheListingAges) {
  studio_test::TempDir root("listing");
  fs::create_directories(root.path() / "b");
  fs::create_directories(root.path() / "a" / "inner");
  fs::create_directories(root.path() / ".hidden");
  std::ofstream(root.path() / "file.json") << "{}";
  fieldlines::studio::FolderListing listing(1.0);
  const std::vector<fs::path> expected{root.path() / "a", root.path() / "b"};  // sorted, no files or dot folders
  EXPECT_EQ(listing.subfolders(root.path(), 10.0), expected);
  // Every frame of the next second reuses that listing, even if the disk changed meanwhile.
  fs::create_directories(root.path() / "c");
  for (double t = 10.0; t < 10.99; t += 1.0 / 60) EXPECT_EQ(listing.subfolders(root.path(), t), expected);
  EXPECT_EQ(listing.listings(), 1u);
  // Another folder is read at once; back to the first after a second shows the new folder.
  EXPECT_EQ(listing.subfolders(root.path() / "a", 11.0), std::vector<fs::path>{root.path() / "a" / "inner"});
  EXPECT_EQ(listing.subfolders(root.path(), 11.01).size(), 3u);
  EXPECT_EQ(listing.listings(), 3u);
  // A missing folder lists as empty, not as an error.
  EXPECT_TRUE(listing.subfolders(root.path() / "missing", 12.0).empty());
}
