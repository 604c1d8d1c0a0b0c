// Autosave off the UI thread (gui/model/project_saver.hpp): saves land in order, a burst costs
// two writes, failures are reported, and nothing queued is lost when the studio closes.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "fixtures.hpp"
#include "gui/model/project_saver.hpp"
#include "gui/model/studio_controller.hpp"

namespace fs = fieldlines::studio;
using fieldlines::Label;
using fieldlines::Project;

namespace {

fs::ControllerOptions background() {
  fs::ControllerOptions o;
  o.background_save = true;
  o.load_pixels = false;
  return o;
}

TEST(ProjectSaver, ABurstOfSavesWritesTheFirstAndTheNewestOnly) {
  studio_test::TempDir dir("saver");
  const auto file = studio_test::write_project(dir.path(), 2, 40);
  Project p = Project::load(file);
  fs::ProjectSaver saver;
  for (std::size_t i = 0; i < 40; ++i) {
    p.images[0].segments[i].label = Label::Marking;
    saver.save(p, file);  // no poll in between: the first runs, the rest replace each other
  }
  EXPECT_TRUE(saver.busy());
  const fs::ProjectSaver::Done done = saver.finish();
  EXPECT_EQ(done.saved, 2u);
  EXPECT_TRUE(done.error.empty()) << done.error;
  EXPECT_FALSE(saver.busy());
  EXPECT_EQ(Project::load(file).labelled_count(), 40u);
}

TEST(ProjectSaver, AFailedWriteIsReportedWithItsReason) {
  studio_test::TempDir dir("saver");
  const auto file = studio_test::write_project(dir.path(), 1, 5);
  fs::ProjectSaver saver;
  saver.save(Project::load(file), dir.path() / "no-such-folder" / "project.json");
  const fs::ProjectSaver::Done done = saver.finish();
  EXPECT_EQ(done.saved, 0u);
  EXPECT_NE(done.error.find("no-such-folder"), std::string::npos) << done.error;
}

TEST(BackgroundSave, EditsReachTheDiskWithoutTheUiThreadWriting) {
  studio_test::TempDir dir("bgsave");
  const auto file = studio_test::write_project(dir.path(), 3, 8);
  fs::StudioController c(Project::load(file), file, background());
  const std::size_t one[] = {2};
  ASSERT_TRUE(c.label(one, Label::Boundary));
  for (int i = 0; i < 5000 && c.save_count() == 0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    c.poll();
  }
  EXPECT_EQ(c.save_count(), 1u);
  EXPECT_EQ(Project::load(file).images[0].segments[2].label, Label::Boundary);
}

TEST(BackgroundSave, ClosingTheStudioWritesWhatIsStillQueued) {
  studio_test::TempDir dir("bgsave");
  const auto file = studio_test::write_project(dir.path(), 3, 8);
  {
    fs::StudioController c(Project::load(file), file, background());
    for (std::size_t i = 0; i < 8; ++i) {
      const std::size_t one[] = {i};
      ASSERT_TRUE(c.label(one, Label::Marking));  // never polled: the saves stay queued
    }
  }
  EXPECT_EQ(Project::load(file).labelled_count(), 8u);
}

TEST(BackgroundSave, AFailedSaveKeepsTheEditsAndSaysWhy) {
  studio_test::TempDir dir("bgsave");
  const auto file = studio_test::write_project(dir.path(), 2, 4);
  fs::StudioController c(Project::load(file), dir.path() / "gone" / "project.json", background());
  const std::size_t one[] = {1};
  ASSERT_TRUE(c.label(one, Label::None));
  EXPECT_NE(c.finish_saves().find("gone"), std::string::npos);
  EXPECT_FALSE(c.save_error().empty());
  EXPECT_EQ(c.segments()[1].label, Label::None);
  EXPECT_TRUE(c.has_unsaved_settings());  // retried after the settings delay
}

}  // namespace
