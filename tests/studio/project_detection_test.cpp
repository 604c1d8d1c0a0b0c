// Background detection of a project without the controller: which images a start covers, the
// finished ones taken into the project with labels re-attached, failures kept per image, and
// the status bar's summary.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/atomic_file.hpp"
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
