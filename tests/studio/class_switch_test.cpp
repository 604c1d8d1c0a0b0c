// Per-class on/off in the studio (gui/model/class_switch.hpp): the user's switch, calibration's
// verdict on a class the field lacks, what the exported file says, proposals never of a class
// that is off, and the guidance when calibration refuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <vector>

#include "fieldlines/detect/thresholds_file.hpp"
#include "fieldlines/train/calibrate.hpp"
#include "fixtures.hpp"
#include "gui/model/studio_controller.hpp"
#include "gui/model/status_line.hpp"
#include "gui/model/studio_files.hpp"
#include "tests/known_features.hpp"

namespace fs = fieldlines::studio;
using fieldlines::Label;

namespace {

// `segments` unlabelled, dealt over three images, as a saved project.
struct Field {
  Field(const std::vector<fieldlines::Segment>& segments, const char* tag) : dir(tag) {
    fieldlines::Project p;
    for (int img = 0; img < 3; ++img) p.images.push_back({"img" + std::to_string(img) + ".png", {}, 1.0, {}});
    for (std::size_t i = 0; i < segments.size(); ++i) {
      truth.push_back(segments[i].label);
      p.images[i % 3].segments.push_back(segments[i]);
      p.images[i % 3].segments.back().label = Label::Unlabelled;
    }
    file = dir.path() / "project.json";
    p.save(file);
    fs::ControllerOptions options;
    options.load_pixels = false;
    controller.emplace(fieldlines::Project::load(file), file, options);
  }
  // Image 0's first `n` segments whose true label is `l`.
  std::vector<std::size_t> first_of(Label l, std::size_t n) const {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; 3 * i < truth.size() && out.size() < n; ++i)
      if (truth[3 * i] == l) out.push_back(i);
    return out;
  }
  std::size_t proposed(Label l) const {
    std::size_t n = 0;
    for (const fieldlines::ImageEntry& e : controller->project().images)
      n += static_cast<std::size_t>(std::count(e.proposals.begin(), e.proposals.end(), l));
    return n;
  }
  studio_test::TempDir dir;
  std::filesystem::path file;
  std::vector<Label> truth;
  std::optional<fs::StudioController> controller;
};

std::vector<fieldlines::Segment> without(const fieldlines::test::KnownField& k, Label gone) {
  std::vector<fieldlines::Segment> out;
  std::copy_if(k.segments.begin(), k.segments.end(), std::back_inserter(out),
               [&](const fieldlines::Segment& s) { return s.label != gone; });
  return out;
}

TEST(StudioClassSwitch, OffNeverPredictsProposesOrExportsTheClassAndOnGivesItsThresholdsBack) {
  const fieldlines::test::KnownField k = fieldlines::test::known_field(9);
  Field f(k.segments, "switch-user");
  fs::StudioController& c = *f.controller;
  ASSERT_TRUE(c.class_on(Label::Boundary));
  const fieldlines::ClassThresholds before = c.thresholds().boundary.thresholds;
  c.propose();
  ASSERT_GT(f.proposed(Label::Boundary), 0u);

  c.set_class_on(Label::Boundary, false);
  EXPECT_FALSE(c.class_on(Label::Boundary));
  EXPECT_TRUE(c.class_on(Label::Marking));
  EXPECT_TRUE(c.class_off_reason(Label::Boundary).empty());  // the user's, not calibration's
  EXPECT_EQ(c.thresholds().boundary.thresholds, fieldlines::disabled_class());
  EXPECT_EQ(f.proposed(Label::Boundary), 0u);  // existing proposals follow at once
  for (std::size_t img = 0; img < c.image_count(); ++img) {
    c.select_image(img);
    for (const Label p : c.predictions()) EXPECT_NE(p, Label::Boundary);
  }
  // P again, even with boundary labels enough to train it: still none proposed.
  const std::vector<std::size_t> walls = f.first_of(Label::Boundary, 12), others = f.first_of(Label::None, 12);
  c.select_image(0);
  ASSERT_TRUE(c.label(walls, Label::Boundary));
  ASSERT_TRUE(c.label(others, Label::None));
  const std::string summary = c.propose();
  EXPECT_NE(summary.find("boundary disabled"), std::string::npos) << summary;
  EXPECT_EQ(f.proposed(Label::Boundary), 0u);
  EXPECT_FALSE(c.class_on(Label::Boundary));

  // The exported file has it off, in the file's own terms: thresholds no segment passes.
  const std::filesystem::path exported = f.dir.path() / "robot.json";
  fs::export_thresholds(c, exported);
  const fieldlines::ThresholdsFile written = fieldlines::load_thresholds_file(exported);
  EXPECT_EQ(written.thresholds.boundary.thresholds, fieldlines::disabled_class());
  EXPECT_EQ(written.provenance["classes_off"]["boundary"], "switched off in the studio");
  EXPECT_FALSE(written.provenance["classes_off"].contains("marking"));
  // And it is kept in the project file.
  c.flush();
  EXPECT_EQ(fieldlines::Project::load(f.file).thresholds.boundary.thresholds, fieldlines::disabled_class());

  c.set_class_on(Label::Boundary, true);
  EXPECT_EQ(c.thresholds().boundary.thresholds, before);
  EXPECT_GT(f.proposed(Label::Boundary), 0u);
}

TEST(StudioClassSwitch, CalibrationTurnsOffABoundaryTheFieldLacksUntilLabelsShowOne) {
  // A field with markings and grey edges but no dark wall (a Nao field).
  const fieldlines::test::KnownField k = fieldlines::test::known_field(9);
  Field f(without(k, Label::Boundary), "switch-verdict");
  fs::StudioController& c = *f.controller;
  const std::string summary = c.propose();
  EXPECT_FALSE(c.class_on(Label::Boundary)) << summary;
  EXPECT_EQ(f.proposed(Label::Boundary), 0u);
  // The real cause, in calibration's words: no dark edge, not a missing green field.
  const std::string& why = c.class_off_reason(Label::Boundary);
  EXPECT_NE(why.find("no dark field edge"), std::string::npos) << why;
  EXPECT_EQ(why.find("green field"), std::string::npos) << why;
  EXPECT_NE(c.guidance().find("Boundary off"), std::string::npos) << c.guidance();
  EXPECT_EQ(c.guidance().find("markings"), std::string::npos) << c.guidance();  // the markings were fitted
  // Off in the exported file too.
  const std::filesystem::path exported = f.dir.path() / "robot.json";
  fs::export_thresholds(c, exported);
  const fieldlines::ThresholdsFile written = fieldlines::load_thresholds_file(exported);
  EXPECT_EQ(written.thresholds.boundary.thresholds, fieldlines::disabled_class());
  EXPECT_EQ(written.provenance["classes_off"]["boundary"], "calibration: " + why);
  // Imported back, the file's choice is the user's: no longer calibration's verdict.
  fs::import_thresholds(c, exported);
  EXPECT_FALSE(c.class_on(Label::Boundary));
  EXPECT_TRUE(c.class_off_reason(Label::Boundary).empty());
  c.propose();
  EXPECT_TRUE(c.class_off_reason(Label::Boundary).empty());  // a person's off is never re-asked
  // On again by hand: the next proposals ask calibration, whose verdict stands.
  c.set_class_on(Label::Boundary, true);
  c.propose();
  EXPECT_FALSE(c.class_on(Label::Boundary));
  ASSERT_FALSE(c.class_off_reason(Label::Boundary).empty());

  // Three segments labelled boundary (and three others): trained from them, on again.
  c.select_image(0);
  const std::vector<std::size_t> marks = f.first_of(Label::Marking, 3), others = f.first_of(Label::None, 3);
  ASSERT_TRUE(c.label(marks, Label::Boundary));
  ASSERT_TRUE(c.label(others, Label::None));
  c.propose();
  EXPECT_TRUE(c.class_on(Label::Boundary));
  EXPECT_TRUE(c.class_off_reason(Label::Boundary).empty());
  EXPECT_TRUE(c.guidance().empty()) << c.guidance();
}

TEST(StudioClassSwitch, TheUsersSwitchOverridesCalibrationsVerdictOnlyUntilTheNextProposals) {
  const fieldlines::test::KnownField k = fieldlines::test::known_field(9);
  Field f(without(k, Label::Boundary), "switch-override");
  fs::StudioController& c = *f.controller;
  c.propose();
  ASSERT_FALSE(c.class_on(Label::Boundary));
  c.set_class_on(Label::Boundary, true);
  EXPECT_TRUE(c.class_on(Label::Boundary));
  EXPECT_EQ(c.thresholds().boundary.thresholds, fieldlines::Thresholds{}.boundary.thresholds);
  EXPECT_TRUE(c.class_off_reason(Label::Boundary).empty());
  // Proposals ask calibration again, which still sees no wall: off, saying why.
  c.propose();
  EXPECT_FALSE(c.class_on(Label::Boundary));
  EXPECT_FALSE(c.class_off_reason(Label::Boundary).empty());
}

TEST(StudioClassSwitch, AutoTrainKeepsASwitchedOffClassOff) {
  const fieldlines::test::KnownField k = fieldlines::test::known_field(9);
  Field f(k.segments, "switch-auto");
  fs::StudioController& c = *f.controller;
  c.set_class_on(Label::Boundary, false);
  c.set_auto_train(true);
  c.select_image(0);
  ASSERT_TRUE(c.label(f.first_of(Label::Marking, 12), Label::Marking));
  ASSERT_TRUE(c.label(f.first_of(Label::None, 12), Label::None));
  c.wait_for_auto_train();
  EXPECT_FALSE(c.learning_curve().empty());
  EXPECT_FALSE(c.class_on(Label::Boundary));
  EXPECT_TRUE(c.class_on(Label::Marking));
}

TEST(StudioClassSwitch, WhenCalibrationRefusesTheMarkingsTheGuidanceSaysWhyAndWhatToDoUntilAFewAreLabelled) {
  // Grey edges and three faint markings: no mode of paint colours for calibration to fit.
  const fieldlines::test::KnownField k = fieldlines::test::known_field(9);
  std::vector<fieldlines::Segment> venue(k.segments.end() - k.greys, k.segments.end());
  for (int i = 0; i < 9; ++i) venue.insert(venue.begin() + 3 * i, k.segments[static_cast<std::size_t>(i)]);
  Field f(venue, "switch-refused");
  fs::StudioController& c = *f.controller;
  const std::string summary = c.propose();
  const std::string& g = c.guidance();
  EXPECT_NE(g.find("Calibration cannot fit the markings"), std::string::npos) << g;
  EXPECT_NE(g.find("no field markings seen"), std::string::npos) << g;  // why, in calibration's words
  EXPECT_NE(g.find("Label a few segments of each class"), std::string::npos) << g;  // what to do
  // The status bar shows it (as a warning, ahead of P's own message) until labels answer it.
  const std::vector<fs::StatusNote> notes = fs::status_notes(c, summary);
  ASSERT_FALSE(notes.empty());
  EXPECT_EQ(notes[0].text, g);
  EXPECT_EQ(notes[0].severity, fs::Severity::Warning);
  EXPECT_TRUE(c.class_on(Label::Marking));  // never switched off: the markings are what the robot needs

  c.select_image(0);
  ASSERT_TRUE(c.label(f.first_of(Label::Marking, 3), Label::Marking));
  ASSERT_TRUE(c.label(f.first_of(Label::None, 3), Label::None));
  const std::string after = c.propose();
  EXPECT_NE(after.find("marking trained"), std::string::npos) << after;
  EXPECT_EQ(c.guidance().find("markings"), std::string::npos) << c.guidance();
  EXPECT_GT(f.proposed(Label::Marking), 0u);
  for (const fs::StatusNote& n : fs::status_notes(c, after)) EXPECT_EQ(n.text.find("markings"), std::string::npos) << n.text;
}

}  // namespace
