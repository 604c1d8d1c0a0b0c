// Small studio parts: overlay styles and legend, frame statistics, command line, recent list.
#include <gtest/gtest.h>

#include <chrono>

#include "fieldlines/detect/atomic_file.hpp"

#include "fieldlines/detect/error.hpp"
#include "fixtures.hpp"
#include "gui/model/frame_stats.hpp"
#include "gui/model/open_project.hpp"
#include "gui/model/overlay_style.hpp"
#include "gui/model/recent_projects.hpp"
#include "gui/model/studio_args.hpp"

namespace fs = fieldlines::studio;
using fieldlines::Label;

TEST(OverlayStyle, LabelsHaveDistinctColours) {
  const Label all[] = {Label::Marking, Label::Boundary, Label::None, Label::Unlabelled};
  for (auto a : all) {
    for (auto b : all) {
      if (a != b) {
        EXPECT_NE(fs::label_colour(a), fs::label_colour(b));
      }
    }
  }
}

TEST(OverlayStyle, AgreementIsSolidDashedDotted) {
  using fs::OverlayMode;
  using fs::Stroke;
  const auto tp = fs::style_for(OverlayMode::Agreement, Label::Marking, Label::Marking);
  EXPECT_EQ(tp.stroke, Stroke::Solid);
  EXPECT_EQ(tp.colour, fs::label_colour(Label::Marking));
  const auto fp = fs::style_for(OverlayMode::Agreement, Label::None, Label::Boundary);
  EXPECT_EQ(fp.stroke, Stroke::Dashed);
  EXPECT_EQ(fp.colour, fs::label_colour(Label::Boundary));
  const auto fn = fs::style_for(OverlayMode::Agreement, Label::Marking, Label::None);
  EXPECT_EQ(fn.stroke, Stroke::Dotted);
  EXPECT_EQ(fn.colour, fs::label_colour(Label::Marking));
  // Wrong class: a false positive of the predicted class.
  EXPECT_EQ(fs::style_for(OverlayMode::Agreement, Label::Marking, Label::Boundary).stroke, Stroke::Dashed);
  // Labels and prediction modes colour by their own source.
  EXPECT_EQ(fs::style_for(OverlayMode::Labels, Label::Boundary, Label::Marking).colour, fs::label_colour(Label::Boundary));
  EXPECT_EQ(fs::style_for(OverlayMode::Prediction, Label::Boundary, Label::Marking).colour,
            fs::label_colour(Label::Marking));
  for (auto mode : {OverlayMode::Labels, OverlayMode::Prediction, OverlayMode::Agreement}) {
    EXPECT_GE(fs::legend(mode).size(), 3u);
  }
}

TEST(FrameStats, MedianOverARollingWindow) {
  fs::FrameStats stats(5);
  EXPECT_EQ(stats.median_ms(), 0);
  for (double s : {0.010, 0.030, 0.020}) stats.add(s);
  EXPECT_NEAR(stats.median_ms(), 20, 1e-9);
  for (double s : {0.001, 0.001, 0.001, 0.001}) stats.add(s);  // pushes the oldest out
  EXPECT_EQ(stats.size(), 5u);
  EXPECT_NEAR(stats.median_ms(), 1, 1e-9);
  EXPECT_NEAR(stats.last_ms(), 1, 1e-9);
  const auto h = stats.history_ms();
  ASSERT_EQ(h.size(), 5u);
  EXPECT_NEAR(h.front(), 20, 1e-4);  // oldest first
  EXPECT_NEAR(fs::median({4, 1, 3, 2}), 2.5, 1e-12);
}

TEST(StudioArgs, ParsesAndRejects) {
  const auto a = fs::parse_studio_args({"proj.json", "--window-size", "1024x700", "--bench-frames", "50"});
  EXPECT_EQ(a.input, "proj.json");
  EXPECT_EQ(a.window_width, 1024);
  EXPECT_EQ(a.window_height, 700);
  EXPECT_EQ(a.bench_frames, 50);
  EXPECT_THROW(fs::parse_studio_args({"--window-size", "big"}), fieldlines::Error);
  EXPECT_THROW(fs::parse_studio_args({"--bench-frames", "-3"}), fieldlines::Error);
  EXPECT_THROW(fs::parse_studio_args({"--bench-frames"}), fieldlines::Error);
  EXPECT_TRUE(a.bench_features);
  EXPECT_FALSE(fs::parse_studio_args({"--bench-frames", "5", "--bench-no-features"}).bench_features);
  EXPECT_THROW(fs::parse_studio_args({"--bench-no-features"}), fieldlines::Error);  // nothing to bench
  EXPECT_THROW(fs::parse_studio_args({"--frobnicate"}), fieldlines::Error);
  EXPECT_THROW(fs::parse_studio_args({"a", "b"}), fieldlines::Error);
  EXPECT_TRUE(fs::parse_studio_args({"--last"}).last);
  EXPECT_TRUE(fs::parse_studio_args({}).auto_train);  // live retraining is on unless asked
  EXPECT_FALSE(fs::parse_studio_args({"--no-auto-train"}).auto_train);
  EXPECT_TRUE(fs::parse_studio_args({}).input.empty());  // nothing: the demo
  EXPECT_FALSE(fs::parse_studio_args({}).last);
  EXPECT_THROW(fs::parse_studio_args({"--last", "p.json"}), fieldlines::Error);
  EXPECT_TRUE(fs::parse_studio_args({"--version"}).version);
  EXPECT_EQ(fs::parse_studio_args({"--camera", "head.json"}).camera_file, "head.json");
  EXPECT_TRUE(fs::parse_studio_args({}).camera_file.empty());
  EXPECT_THROW(fs::parse_studio_args({"--camera"}), fieldlines::Error);
}

TEST(RecentProjects, MostRecentFirstWithoutDuplicates) {
  studio_test::TempDir dir("recent");
  std::vector<std::string> recent;
  fs::remember(recent, "/a.json");
  fs::remember(recent, "/b.json");
  fs::remember(recent, "/a.json");
  EXPECT_EQ(recent, (std::vector<std::string>{"/a.json", "/b.json"}));
  for (int i = 0; i < 20; ++i) fs::remember(recent, "/p" + std::to_string(i), 10);
  EXPECT_EQ(recent.size(), 10u);
  EXPECT_EQ(recent.front(), "/p19");
  const auto file = dir.path() / "cfg" / "recent.txt";
  fs::save_recent(file, recent);
  EXPECT_EQ(fs::load_recent(file), recent);
  EXPECT_TRUE(fs::load_recent(dir.path() / "missing.txt").empty());
}

TEST(OpenProject, FolderGetsAProjectFileAndIsReopened) {
  studio_test::TempDir dir("open");
  studio_test::write_project(dir.path(), 2, 3);
  std::filesystem::remove(dir.path() / "project.json");
  const auto opened = fs::open_project(dir.path());
  EXPECT_EQ(opened.file, dir.path() / fs::kFolderProjectName);
  EXPECT_TRUE(std::filesystem::exists(opened.file));
  EXPECT_TRUE(opened.needs_detection);
  ASSERT_EQ(opened.project.images.size(), 2u);
  EXPECT_EQ(opened.project.images[0].path, "img_00.png");
  // A save killed mid-write an hour ago left its temporary file: reopening clears it.
  const auto debris = dir.path() / (fieldlines::temporary_prefix(fs::kFolderProjectName) + "4242");
  fieldlines::write_file_atomically(debris, "{\"half");
  std::filesystem::last_write_time(debris, std::filesystem::file_time_type::clock::now() - std::chrono::hours(1));
  EXPECT_EQ(fs::open_project(opened.file).project.images.size(), 2u);
  EXPECT_FALSE(std::filesystem::exists(debris));
  EXPECT_THROW(fs::open_project(dir.path() / "nope"), fieldlines::Error);
  studio_test::TempDir empty("empty");
  EXPECT_THROW(fs::open_project(empty.path()), fieldlines::Error);
}
