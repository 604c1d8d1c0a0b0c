// Background detection of a project without the controller: which images a start covers, the
// finished ones taken into the project with labels re-attached, failures kept per image, and
// the status bar's summary.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "fieldlines/data/project.hpp"
#include "fieldlines/data/image_io.hpp"
#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fixtures.hpp"
#include "gui/model/project_detection.hpp"

namespace fs = fieldlines::studio;
using fieldlines::Label;

namespace {
// good.png (one tilted line), bad.png (a truncated PNG), good2.png with a segment already.
struct Folder {
  Folder() : dir("project-detection") {
    fieldlines::Segment line;  // tilted: exactly horizontal edges between anchor rows are never drawn
    line.x0 = 20, line.y0 = 100, line.x1 = 300, line.y1 = 130;
    cv::imwrite((dir.path() / "good.png").string(), studio_test::field_image(320, 240, {line}));
    cv::imwrite((dir.path() / "good2.png").string(), studio_test::field_image(320, 240, {line}));
    fieldlines::write_file_atomically(dir.path() / "bad.png", "\x89PNG\r\n\x1a\n truncated");
    project.images.push_back({"good.png", {}, 0});
    project.images.push_back({"bad.png", {}, 0});
    project.images.push_back({"good2.png", {line}, 1.5});
    file = dir.path() / "p.json";
  }
  studio_test::TempDir dir;
  fieldlines::Project project;
  std::filesystem::path file;
};
}  // namespace

TEST(ProjectDetection, NewImagesOnlyThenTheFailureIsKeptPerImage) {
  Folder f;
  EXPECT_TRUE(fs::needs_detection(f.project.images[0]));
  EXPECT_FALSE(fs::needs_detection(f.project.images[2]));
  fs::ProjectDetection detection;
  EXPECT_TRUE(detection.report().summary().empty());
  detection.start(f.project, f.file, true);
  EXPECT_EQ(detection.job().total(), 2u);  // good2.png was detected already
  detection.job().wait();
  const std::vector<std::size_t> changed = detection.poll(f.project);
  EXPECT_EQ(changed, std::vector<std::size_t>{0});
  EXPECT_GT(f.project.images[0].segments.size(), 0u);
  EXPECT_GT(f.project.images[0].detect_ms, 0);
  EXPECT_EQ(detection.report().detected, 1u);
  ASSERT_EQ(detection.report().failed.size(), 1u);
  EXPECT_EQ(detection.report().failed[0].first, 1u);
  EXPECT_NE(detection.error(1).find("bad.png"), std::string::npos) << detection.error(1);
  EXPECT_TRUE(detection.error(0).empty());
  EXPECT_TRUE(detection.error(7).empty());  // past the images: no reason, no crash
  EXPECT_NE(detection.report().summary().find("detected 1 image; 1 failed: "), std::string::npos)
      << detection.report().summary();
  EXPECT_TRUE(detection.poll(f.project).empty());  // nothing new
}

TEST(ProjectDetection, ReDetectingAllKeepsTheLabelsThatStillMatch) {
  Folder f;
  fs::ProjectDetection detection;
  detection.start(f.project, f.file, true);
  detection.job().wait();
  detection.poll(f.project);
  ASSERT_GT(f.project.images[0].segments.size(), 0u);
  f.project.images[0].segments[0].label = Label::Marking;  // a label on a detected segment

  detection.start(f.project, f.file, false);  // a new start begins a new report
  EXPECT_EQ(detection.report().detected, 0u);
  EXPECT_EQ(detection.job().total(), 3u);
  detection.job().wait();
  const std::vector<std::size_t> changed = detection.poll(f.project);
  EXPECT_EQ(changed, (std::vector<std::size_t>{0, 2}));
  // The same picture gives the same segments: the label is re-attached to its segment.
  EXPECT_EQ(f.project.images[0].segments[0].label, Label::Marking);
  EXPECT_GE(detection.report().labels_kept, 1u);
  EXPECT_NE(detection.report().summary().find("labels kept"), std::string::npos) << detection.report().summary();
}

TEST(ProjectDetection, KeepsEachImagesFieldFeaturesAndTheSameSegmentsAsWithoutThem) {
  Folder f;
  // A crossing, so the stripes and their junction have something to find.
  fieldlines::Segment across, down;
  across.x0 = 20, across.y0 = 100, across.x1 = 300, across.y1 = 120;
  down.x0 = 150, down.y0 = 40, down.x1 = 170, down.y1 = 230;
  cv::imwrite((f.dir.path() / "good.png").string(), studio_test::field_image(320, 240, {across, down}));
  EXPECT_EQ(fieldlines::with_every_feature({}).stripes, true);
  EXPECT_EQ(fieldlines::with_every_feature({}).intersections, true);
  EXPECT_EQ(fieldlines::with_every_feature({}).centre_circle, true);
  EXPECT_EQ(fieldlines::with_every_feature({}).gradient_threshold, fieldlines::DetectorParams{}.gradient_threshold);
  ASSERT_FALSE(f.project.detector.stripes);  // the project's own detector leaves the stages off

  fs::ProjectDetection detection;
  EXPECT_TRUE(detection.features(0).markings.empty());  // before any detection: none
  detection.start(f.project, f.file, false);
  detection.job().wait();
  detection.poll(f.project);
  const fieldlines::FieldFeatures& features = detection.features(0);
  EXPECT_FALSE(features.markings.empty());
  EXPECT_FALSE(features.field_boundary.empty());
  EXPECT_TRUE(detection.features(1).markings.empty());  // bad.png failed: nothing
  EXPECT_TRUE(detection.features(9).field_boundary.empty());  // past the images: empty, no crash

  // The segments are those the project's detector finds with the stages off: same geometry,
  // same colour gradients, so the same cached features and predictions; labels all cleared.
  fieldlines::LineDetector plain(f.project.detector, f.project.thresholds);
  const std::vector<fieldlines::Segment> expected =
      plain.detect(fieldlines::load_image(f.dir.path() / "good.png"));
  const std::vector<fieldlines::Segment>& got = f.project.images[0].segments;
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].x0, expected[i].x0);
    EXPECT_EQ(got[i].y0, expected[i].y0);
    EXPECT_EQ(got[i].x1, expected[i].x1);
    EXPECT_EQ(got[i].y1, expected[i].y1);
    EXPECT_EQ(got[i].grad_x, expected[i].grad_x);
    EXPECT_EQ(got[i].grad_y, expected[i].grad_y);
    EXPECT_EQ(got[i].saliency, expected[i].saliency);
    EXPECT_EQ(got[i].label, Label::Unlabelled);
  }

  fieldlines::FieldFeatures synthetic;
  synthetic.markings.push_back({1, 2, 3, 4, 5});
  detection.set_features(5, synthetic);  // an index past the images so far grows the list
  EXPECT_EQ(detection.features(5).markings.size(), 1u);
}
