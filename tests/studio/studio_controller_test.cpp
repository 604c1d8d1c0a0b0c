// The studio's controller without a window: labelling, undo/redo, autosave, thresholds, metrics.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <vector>

#include <nlohmann/json.hpp>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/data/reference_csv.hpp"
#include "fixtures.hpp"
#include "fieldlines/train/metrics.hpp"
#include "fieldlines/train/splits.hpp"
#include "gui/model/figures.hpp"
#include "gui/model/studio_controller.hpp"
#include "gui/model/studio_files.hpp"

namespace fs = fieldlines::studio;
using fieldlines::Label;
using fieldlines::Project;

namespace {

struct Session {
  explicit Session(int images = 5, int segments = 6, fs::ControllerOptions options = {})
      : dir("controller"), file(studio_test::write_project(dir.path(), images, segments)),
        controller(Project::load(file), file, options) {}
  Project on_disk() const { return Project::load(file); }
  studio_test::TempDir dir;
  std::filesystem::path file;
  fs::StudioController controller;
};

std::vector<Label> labels_of(const Project& p, std::size_t image) {
  std::vector<Label> out;
  for (const auto& s : p.images.at(image).segments) out.push_back(s.label);
  return out;
}

}  // namespace

TEST(StudioController, LoadsTheCurrentImagePixels) {
  Session s;
  EXPECT_EQ(s.controller.image().cols, 320);
  EXPECT_EQ(s.controller.image().rows, 240);
  EXPECT_TRUE(s.controller.image_error().empty());
  EXPECT_EQ(s.controller.segments().size(), 6u);
}

TEST(StudioController, LabelIsAutosavedAtOnce) {
  Session s;
  const std::size_t one[] = {2};
  ASSERT_TRUE(s.controller.label(one, Label::Marking));
  EXPECT_EQ(s.on_disk().images[0].segments[2].label, Label::Marking);
  EXPECT_EQ(s.controller.save_count(), 1u);
  // The same label again changes nothing and writes nothing.
  EXPECT_FALSE(s.controller.label(one, Label::Marking));
  EXPECT_EQ(s.controller.save_count(), 1u);
}

TEST(StudioController, HoveredLabelling) {
  Session s;
  EXPECT_FALSE(s.controller.label_hovered(Label::Boundary));  // nothing hovered
  s.controller.set_hovered(3);
  EXPECT_TRUE(s.controller.label_hovered(Label::Boundary));
  EXPECT_EQ(s.on_disk().images[0].segments[3].label, Label::Boundary);
  s.controller.set_hovered(99);  // out of range: nothing hovered
  EXPECT_FALSE(s.controller.hovered().has_value());
}

TEST(StudioController, UndoRedoRestoreLabelsOnDisk) {
  Session s;
  const std::size_t first[] = {0, 1, 2};
  const std::size_t second[] = {2, 3};
  ASSERT_TRUE(s.controller.label(first, Label::Marking));
  ASSERT_TRUE(s.controller.label(second, Label::None));
  const auto after_both = labels_of(s.on_disk(), 0);
  EXPECT_EQ(after_both, (std::vector<Label>{Label::Marking, Label::Marking, Label::None, Label::None,
                                            Label::Unlabelled, Label::Unlabelled}));
  ASSERT_TRUE(s.controller.undo());  // the second action, as one step
  EXPECT_EQ(labels_of(s.on_disk(), 0), (std::vector<Label>{Label::Marking, Label::Marking, Label::Marking,
                                                           Label::Unlabelled, Label::Unlabelled, Label::Unlabelled}));
  ASSERT_TRUE(s.controller.undo());
  EXPECT_EQ(labels_of(s.on_disk(), 0), std::vector<Label>(6, Label::Unlabelled));
  EXPECT_FALSE(s.controller.undo());
  ASSERT_TRUE(s.controller.redo());
  ASSERT_TRUE(s.controller.redo());
  EXPECT_EQ(labels_of(s.on_disk(), 0), after_both);
  EXPECT_FALSE(s.controller.redo());
}

TEST(StudioController, UndoShowsTheImageItChanges) {
  Session s;
  s.controller.select_image(3);
  const std::size_t one[] = {1};
  ASSERT_TRUE(s.controller.label(one, Label::Boundary));
  s.controller.select_image(0);
  ASSERT_TRUE(s.controller.undo());
  EXPECT_EQ(s.controller.current(), 3u);
  EXPECT_EQ(s.on_disk().images[3].segments[1].label, Label::Unlabelled);
}

TEST(StudioController, NewEditDropsTheRedoBranch) {
  Session s;
  const std::size_t a[] = {0};
  const std::size_t b[] = {1};
  s.controller.label(a, Label::Marking);
  s.controller.undo();
  EXPECT_TRUE(s.controller.can_redo());
  s.controller.label(b, Label::None);
  EXPECT_FALSE(s.controller.can_redo());
}

TEST(StudioController, LabelTheRestAsNone) {
  Session s;
  const std::size_t one[] = {4};
  s.controller.label(one, Label::Marking);
  ASSERT_TRUE(s.controller.label_rest_as_none());
  const auto labels = labels_of(s.on_disk(), 0);
  EXPECT_EQ(labels[4], Label::Marking);
  EXPECT_EQ(std::count(labels.begin(), labels.end(), Label::None), 5);
  EXPECT_FALSE(s.controller.label_rest_as_none());  // nothing left
  s.controller.undo();
  const auto undone = labels_of(s.on_disk(), 0);
  EXPECT_EQ(std::count(undone.begin(), undone.end(), Label::Unlabelled), 5);
}

TEST(StudioController, NavigationWrapsAround) {
  Session s(3);
  s.controller.previous_image();
  EXPECT_EQ(s.controller.current(), 2u);
  s.controller.next_image();
  EXPECT_EQ(s.controller.current(), 0u);
  s.controller.next_image();
  EXPECT_EQ(s.controller.current(), 1u);
  const auto generation = s.controller.image_generation();
  s.controller.select_image(7);  // out of range: ignored
  EXPECT_EQ(s.controller.current(), 1u);
  EXPECT_EQ(s.controller.image_generation(), generation);
}

TEST(StudioController, ThresholdChangeReclassifiesFromCachedFeatures) {
  Session s;
  // Defaults: even grid segments are markings, odd ones boundaries.
  auto p = s.controller.predictions();
  ASSERT_EQ(p.size(), 6u);
  EXPECT_EQ(p[0], Label::Marking);
  EXPECT_EQ(p[1], Label::Boundary);
  // Label image 0 by the truth of the fixture; all correct: precision and recall 1.
  const std::size_t evens[] = {0, 2, 4};
  const std::size_t odds[] = {1, 3, 5};
  s.controller.label(evens, Label::Marking);
  s.controller.label(odds, Label::Boundary);
  EXPECT_EQ(s.controller.train_counts().marking.tp, 3);
  EXPECT_EQ(s.controller.train_counts().marking.fn, 0);
  EXPECT_EQ(s.controller.progress(0).errors, 0);

  // A marking length threshold above every segment's saliency: markings are missed.
  auto t = s.controller.thresholds();
  t.marking.thresholds.min_length = 250;
  s.controller.set_thresholds(t);
  EXPECT_EQ(s.controller.predictions()[0], Label::None);
  EXPECT_EQ(s.controller.predictions()[1], Label::Boundary);
  EXPECT_EQ(s.controller.train_counts().marking.tp, 0);
  EXPECT_EQ(s.controller.train_counts().marking.fn, 3);
  EXPECT_EQ(s.controller.progress(0).errors, 3);
  EXPECT_EQ(s.controller.train_counts().boundary.tp, 3);
}

TEST(StudioController, ThresholdChangesAreSavedAfterAPause) {
  Session s;
  auto t = s.controller.thresholds();
  t.boundary.thresholds.min_projection = 77;
  s.controller.set_thresholds(t);
  EXPECT_TRUE(s.controller.has_unsaved_settings());
  s.controller.poll(10.0);  // first poll after the change starts the pause
  s.controller.poll(10.0 + fs::StudioController::settings_save_delay_s / 2);
  EXPECT_NE(s.on_disk().thresholds.boundary.thresholds.min_projection, 77);
  s.controller.poll(10.0 + fs::StudioController::settings_save_delay_s);
  EXPECT_FALSE(s.controller.has_unsaved_settings());
  EXPECT_EQ(s.on_disk().thresholds.boundary.thresholds.min_projection, 77);
}

TEST(StudioController, FlushSavesPendingSettings) {
  Session s;
  auto d = s.controller.detector_params();
  d.gradient_threshold = 55;
  s.controller.set_detector_params(d);
  s.controller.flush();
  EXPECT_EQ(s.on_disk().detector.gradient_threshold, 55);
}

namespace {

// Labels image `image` of a Session by the fixture's truth (even segments markings, odd ones
// boundaries), except that `wrong` labels the first marking as a boundary.
void label_truth(fs::StudioController& c, std::size_t image, bool wrong = false) {
  c.select_image(image);
  const std::size_t evens[] = {0, 2, 4}, odds[] = {1, 3, 5}, first[] = {0};
  c.label(evens, Label::Marking);
  c.label(odds, Label::Boundary);
  if (wrong) c.label(first, Label::Boundary);
}

}  // namespace

TEST(StudioController, TestSplitIsTheCliSplitOfTheLabelledSegments) {
  Session s(6);
  for (std::size_t img = 0; img < 6; ++img) label_truth(s.controller, img, img % 2 == 1);
  // What `fieldlines train project.json` splits: the project's labelled set, the same function.
  const Project p = s.on_disk();
  EXPECT_EQ(p.split, fieldlines::SplitSpec{});
  const fieldlines::LabelledSet all = p.labelled();
  const fieldlines::Split split = fieldlines::split_train_test(all, p.split);
  ASSERT_FALSE(split.test.empty());
  EXPECT_EQ(s.controller.test_segment_count(), split.test.size());
  EXPECT_EQ(s.controller.train_segment_count(), split.train.size());
  EXPECT_EQ(s.controller.test_counts(), fieldlines::evaluate(all.subset(split.test), p.thresholds).total);
  EXPECT_EQ(s.controller.train_counts(), fieldlines::evaluate(all.subset(split.train), p.thresholds).total);
  std::size_t test_images = 0;
  for (std::size_t img = 0; img < 6; ++img) test_images += s.controller.is_test_image(img);
  EXPECT_EQ(test_images, 2u);  // by image, 70 % of 6 images in train
  EXPECT_NE(s.controller.split_summary().find("test split: 12 of 36"), std::string::npos) << s.controller.split_summary();
}

TEST(StudioController, OnlyLabelledImagesAreSplit) {
  Session s(5);
  label_truth(s.controller, 3);
  label_truth(s.controller, 4);
  // Two labelled images, 70 % train: one each side; unlabelled images are in neither part.
  EXPECT_NE(s.controller.is_test_image(3), s.controller.is_test_image(4));
  for (std::size_t img = 0; img < 3; ++img) EXPECT_FALSE(s.controller.is_test_image(img)) << img;
  EXPECT_EQ(s.controller.test_segment_count(), 6u);
  EXPECT_EQ(s.controller.test_counts().marking.tp, 3);
  EXPECT_EQ(s.controller.train_counts().marking.tp, 3);
  EXPECT_EQ(s.controller.labelled_total(), 12u);
}

TEST(StudioController, EmptyTestSplitIsSaidAndShowsNoNumber) {
  Session s(5);
  EXPECT_NE(s.controller.split_summary().find("no labelled segments"), std::string::npos);
  label_truth(s.controller, 0);  // one labelled image: it must train, nothing is left to test
  EXPECT_EQ(s.controller.test_segment_count(), 0u);
  EXPECT_NE(s.controller.split_summary().find("test split empty"), std::string::npos) << s.controller.split_summary();
  const auto& test = s.controller.test_counts().marking;
  EXPECT_EQ(fs::format_figure(test, test.precision()), "n/a");
  const auto& train = s.controller.train_counts().marking;
  EXPECT_EQ(fs::format_figure(train, train.precision()), "1.000");
  const auto out = s.dir.path() / "robot.json";
  fs::export_thresholds(s.controller, out);
  const auto provenance = nlohmann::json::parse(fieldlines::read_file(out))["provenance"];
  EXPECT_TRUE(provenance["test"].is_null()) << provenance.dump();
  EXPECT_FALSE(provenance["train"].is_null());
  EXPECT_EQ(provenance["counts"]["test_segments"], 0);
}

TEST(StudioController, SplitSpecIsRecordedInTheProjectAndTheProvenance) {
  Session s(4);
  for (std::size_t img = 0; img < 4; ++img) label_truth(s.controller, img);
  const fieldlines::SplitSpec spec{fieldlines::SplitMode::ByRow, 0.5, 7};
  s.controller.set_split_spec(spec);
  EXPECT_TRUE(s.controller.has_unsaved_settings());
  EXPECT_EQ(s.controller.test_segment_count(), 12u);  // half of 24 rows
  s.controller.flush();
  EXPECT_EQ(s.on_disk().split, spec);
  const auto out = s.dir.path() / "robot.json";
  fs::export_thresholds(s.controller, out);
  const auto provenance = nlohmann::json::parse(fieldlines::read_file(out))["provenance"];
  EXPECT_EQ(provenance["split"], "row");
  EXPECT_EQ(provenance["train_fraction"], 0.5);
  EXPECT_EQ(provenance["seed"], 7);
  EXPECT_EQ(provenance["counts"]["test_segments"], 12);
  EXPECT_FALSE(provenance["test"].is_null());
  // Reopened, the studio splits the same way.
  fs::StudioController again(Project::load(s.file), s.file);
  EXPECT_EQ(again.test_counts(), s.controller.test_counts());
}

TEST(StudioController, ProjectWithoutSplitLoadsWithTheCliDefaults) {
  studio_test::TempDir dir("split-schema");
  const auto file = studio_test::write_project(dir.path(), 1, 2);
  auto j = nlohmann::json::parse(fieldlines::read_file(file));
  ASSERT_TRUE(j.contains("split"));
  j.erase("split");  // a project written before the split was recorded
  fieldlines::write_file_atomically(file, j.dump());
  const fieldlines::SplitSpec defaults = Project::load(file).split;
  EXPECT_EQ(defaults.mode, fieldlines::SplitMode::ByImage);  // `fieldlines train`'s defaults
  EXPECT_EQ(defaults.train_fraction, 0.7);
  EXPECT_EQ(defaults.seed, 1u);
  j["split"] = {{"seed", 3}};
  fieldlines::write_file_atomically(file, j.dump());
  EXPECT_EQ(Project::load(file).split, (fieldlines::SplitSpec{fieldlines::SplitMode::ByImage, 0.7, 3}));
  for (const nlohmann::json& bad : {nlohmann::json{{"mode", "pixel"}}, nlohmann::json{{"train_fraction", 0}},
                                   nlohmann::json{{"seed", -1}}, nlohmann::json(3)}) {
    j["split"] = bad;
    fieldlines::write_file_atomically(file, j.dump());
    EXPECT_THROW(Project::load(file), fieldlines::Error) << bad.dump();
  }
}

TEST(StudioController, NextImageWithErrors) {
  Session s(5);
  const std::size_t wrong[] = {1};  // a boundary labelled as marking: an error
  s.controller.select_image(3);
  s.controller.label(wrong, Label::Marking);
  s.controller.select_image(0);
  ASSERT_TRUE(s.controller.next_image_with_errors());
  EXPECT_EQ(s.controller.current(), 3u);
  s.controller.undo();
  EXPECT_FALSE(s.controller.next_image_with_errors());
}

TEST(StudioController, AutosaveFailureKeepsTheEditAndReportsIt) {
  studio_test::TempDir dir("badsave");
  const auto file = studio_test::write_project(dir.path(), 1, 4);
  fs::StudioController c(Project::load(file), dir.path() / "missing-folder" / "p.json");
  const std::size_t one[] = {0};
  ASSERT_TRUE(c.label(one, Label::Marking));
  EXPECT_FALSE(c.save_error().empty());
  EXPECT_EQ(c.segments()[0].label, Label::Marking);
}

TEST(StudioController, ExportAndImportRobotThresholds) {
  Session s;
  auto t = s.controller.thresholds();
  t.marking.thresholds.max_angle_deg = 33;
  s.controller.set_thresholds(t);
  const auto out = s.dir.path() / "robot.json";
  fs::export_thresholds(s.controller, out);
  t.marking.thresholds.max_angle_deg = 10;
  s.controller.set_thresholds(t);
  fs::import_thresholds(s.controller, out);
  EXPECT_FLOAT_EQ(s.controller.thresholds().marking.thresholds.max_angle_deg, 33);
  EXPECT_THROW(fs::import_thresholds(s.controller, s.dir.path() / "nope.json"), fieldlines::Error);
}

// A full disk while autosaving (simulated in a child process with RLIMIT_FSIZE, SIGXFSZ
// ignored): the save fails with a message, the file on disk stays the previous complete version,
// the edit stays in memory, and the next save once space is back writes every label.
TEST(StudioController, FullDiskAutosaveKeepsThePreviousFileAndRecovers) {
  Session s(2, 6);
  const std::string before = fieldlines::read_file(s.file);
  const pid_t pid = ::fork();
  if (pid == 0) {
    int failures = 0;
    const auto check = [&](bool ok) { failures += ok ? 0 : 1; };
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit tight{1024, RLIM_INFINITY};  // smaller than the project: every save must fail
    ::setrlimit(RLIMIT_FSIZE, &tight);
    const std::size_t one[] = {1};
    check(s.controller.label(one, Label::Marking));
    check(!s.controller.save_error().empty());
    check(fieldlines::read_file(s.file) == before);
    check(s.controller.segments()[1].label == Label::Marking);
    const rlimit room{RLIM_INFINITY, RLIM_INFINITY};
    ::setrlimit(RLIMIT_FSIZE, &room);
    const std::size_t two[] = {2};
    check(s.controller.label(two, Label::Boundary));
    check(s.controller.save_error().empty());
    const auto disk = Project::load(s.file);
    check(disk.images[0].segments[1].label == Label::Marking);
    check(disk.images[0].segments[2].label == Label::Boundary);
    ::_exit(failures);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "the child died from a signal";
  EXPECT_EQ(WEXITSTATUS(status), 0) << WEXITSTATUS(status) << " checks failed";
  const auto disk = s.on_disk();  // the child's recovered save, seen from here
  EXPECT_EQ(disk.images[0].segments[1].label, Label::Marking);
  EXPECT_EQ(disk.images[0].segments[2].label, Label::Boundary);
}

TEST(StudioController, ExportToAnUnwritablePathIsAnErrorAndImportOfGarbageChangesNothing) {
  Session s;
  fieldlines::write_file_atomically(s.dir.path() / "plain-file", "x");
  EXPECT_THROW(fs::export_thresholds(s.controller, s.dir.path() / "plain-file" / "robot.json"), fieldlines::Error);
  const auto thresholds = s.controller.thresholds();
  for (const std::string text : {"{", "{\"format\": \"fieldlines-thresholds\", \"version\": 99}", "[]",
                                 "{\"format\": \"fieldlines-thresholds\", \"version\": 1, \"marking\": {\"min_projection\": NaN}}"}) {
    fieldlines::write_file_atomically(s.dir.path() / "bad.json", text);
    EXPECT_THROW(fs::import_thresholds(s.controller, s.dir.path() / "bad.json"), fieldlines::Error) << text;
    EXPECT_FLOAT_EQ(s.controller.thresholds().marking.thresholds.max_angle_deg, thresholds.marking.thresholds.max_angle_deg);
  }
}

TEST(StudioController, LabelsExportAsTheReferenceCsv) {
  Session s(2, 6);
  const std::size_t some[] = {0, 3};
  ASSERT_TRUE(s.controller.label(some, Label::Marking));
  const auto csv = s.dir.path() / "labels.csv";
  EXPECT_EQ(fs::export_labels_csv(s.controller, csv), 2u);
  const auto rows = fieldlines::read_reference_csv(csv);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].segment.label, Label::Marking);
  EXPECT_FLOAT_EQ(rows[1].segment.x0, s.controller.segments()[3].x0);
  EXPECT_THROW(fs::export_labels_csv(s.controller, s.dir.path() / "no-such-folder" / "l.csv"), fieldlines::Error);
}
