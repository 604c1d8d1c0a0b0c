// The Export tab's form without a window: the default path per project, the typed path
// resolved, export refused into a missing folder until asked to create it, import, the labels
// CSV beside the thresholds file, failures as messages, and the folder browser.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include "fixtures.hpp"
#include "gui/model/export_form.hpp"
#include "gui/model/studio_controller.hpp"

namespace fs = std::filesystem;
using fieldlines::Project;
using fieldlines::studio::ExportForm;
using fieldlines::studio::StudioController;

namespace {
// A project in its own subfolder, so exports can go beside it.
fs::path project_in(const fs::path& folder, int images, int segments) {
  fs::create_directories(folder);
  return studio_test::write_project(folder, images, segments);
}
struct Session {
  Session() : dir("export-form"), file(project_in(dir.path() / "p", 2, 6)), controller(Project::load(file), file) {}
  studio_test::TempDir dir;
  fs::path file;
  StudioController controller;
};
bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }
}  // namespace

TEST(ExportForm, StartsFromTheProjectsDefaultAndResolvesWhatIsTyped) {
  Session s;
  ExportForm form;
  form.update(s.controller);
  EXPECT_EQ(form.path(), fieldlines::studio::default_export_path(s.file, s.controller.project().images).string());
  EXPECT_EQ(form.base(), fs::absolute(s.file).parent_path());
  form.path() = "out/robot.json";
  form.resolve();
  ASSERT_TRUE(form.target().ok()) << form.target().error;
  EXPECT_EQ(form.target().path, form.base() / "out" / "robot.json");
  EXPECT_TRUE(form.target().from_base);
  EXPECT_FALSE(form.target().folder_exists);
  // A typed path survives the next frames; only another project brings its own default back.
  form.update(s.controller);
  EXPECT_EQ(form.path(), "out/robot.json");
  form.path() = "";
  form.resolve();
  EXPECT_FALSE(form.target().ok());
}

TEST(ExportForm, ExportIntoAMissingFolderWaitsForCreateFolderAndExport) {
  Session s;
  ExportForm form;
  form.update(s.controller);
  form.path() = (s.dir.path() / "robot" / "x.json").string();
  form.resolve();
  form.export_thresholds(s.controller);
  EXPECT_TRUE(form.failed());
  EXPECT_TRUE(contains(form.message(), "Create folder and export")) << form.message();
  EXPECT_FALSE(fs::exists(s.dir.path() / "robot"));
  form.create_folder_and_export(s.controller);
  ASSERT_FALSE(form.failed()) << form.message();
  const fs::path written = s.dir.path() / "robot" / "x.json";
  EXPECT_EQ(fieldlines::load_thresholds_file(written).thresholds, s.controller.thresholds());
  EXPECT_EQ(form.preview(), fieldlines::read_file(written));
  EXPECT_TRUE(contains(form.message(), "wrote ")) << form.message();
  EXPECT_TRUE(contains(form.message(), "x.json")) << form.message();
  // The folder exists now: a plain export writes again.
  form.resolve();
  form.export_thresholds(s.controller);
  EXPECT_FALSE(form.failed()) << form.message();
}

TEST(ExportForm, ImportAndTheLabelsCsvAndFailuresAsMessages) {
  Session s;
  ExportForm form;
  form.update(s.controller);
  const fs::path file = s.dir.path() / "robot.json";
  fieldlines::ThresholdsFile tf;
  tf.thresholds.marking.thresholds.min_projection = 42;
  fieldlines::save_thresholds_file(file, tf);
  form.path() = file.string();
  form.resolve();
  form.import_thresholds(s.controller);
  ASSERT_FALSE(form.failed()) << form.message();
  EXPECT_FLOAT_EQ(s.controller.thresholds().marking.thresholds.min_projection, 42);
  EXPECT_TRUE(contains(form.message(), "imported ")) << form.message();

  const std::size_t one[] = {1};
  ASSERT_TRUE(s.controller.label(one, fieldlines::Label::Marking));
  form.export_labels_csv(s.controller);
  ASSERT_FALSE(form.failed()) << form.message();
  EXPECT_TRUE(fs::exists(s.dir.path() / (s.file.stem().string() + "-labels.csv")));
  EXPECT_TRUE(contains(form.message(), "wrote 1 labelled segments")) << form.message();

  std::ofstream(s.dir.path() / "bad.json") << "{ not json";
  form.path() = (s.dir.path() / "bad.json").string();
  form.resolve();
  form.import_thresholds(s.controller);
  EXPECT_TRUE(form.failed());
  EXPECT_FALSE(form.message().empty());
  EXPECT_FLOAT_EQ(s.controller.thresholds().marking.thresholds.min_projection, 42);  // unchanged
}

TEST(ExportForm, TheFolderBrowserShowsTheNearestFolderAndChoosingOneKeepsTheFileName) {
  Session s;
  ExportForm form;
  form.update(s.controller);
  fs::create_directories(s.dir.path() / "a" / "b");
  form.path() = (s.dir.path() / "a" / "missing" / "deeper" / "t.json").string();
  form.resolve();
  EXPECT_EQ(form.browsed_folder(), s.dir.path() / "a");
  EXPECT_EQ(form.subfolders(0), std::vector<fs::path>{s.dir.path() / "a" / "b"});
  form.choose_folder(s.dir.path() / "a" / "b");
  EXPECT_EQ(form.path(), (s.dir.path() / "a" / "b" / "t.json").string());
  form.resolve();
  EXPECT_EQ(form.browsed_folder(), s.dir.path() / "a" / "b");
}

TEST(ExportForm, AnotherProjectBringsItsOwnDefaultAndClearsTheMessage) {
  Session s;
  ExportForm form;
  form.update(s.controller);
  form.path() = "";
  form.resolve();
  form.export_thresholds(s.controller);
  EXPECT_TRUE(form.failed());
  const fs::path other = project_in(s.dir.path() / "q", 1, 4);
  const StudioController next(Project::load(other), other);
  form.update(next);
  EXPECT_FALSE(form.failed());
  EXPECT_TRUE(form.message().empty());
  EXPECT_EQ(form.path(), fieldlines::studio::default_export_path(other, next.project().images).string());
}
