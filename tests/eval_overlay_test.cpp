// `fieldlines eval --draw` and the truth walk behind it (GtEdges::walk): every visible truth edge
// is found, lost by the classification or missed, the way recall counts it, and the overlay shows
// which, per frame, with the hand-drawn field boundary.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cli_test_support.hpp"
#include "fieldlines/data/palette.hpp"
#include "fieldlines/synth/gt_eval.hpp"
#include "fieldlines/synth/hand_truth.hpp"
#include "painted_field.hpp"

namespace fs = std::filesystem;
namespace fl = fieldlines;
using fl::test::CliRun;
using fl::test::run_cli;

namespace {

// Two painted lines 10 px wide across a 640x480 frame, the field's edge at row 60: the first at
// row 200, the second at row 360.
nlohmann::json two_lines(const std::string& image) {
  return {{"schema", "fieldlines-hand-truth"},
          {"version", 1},
          {"image", image},
          {"width", 640},
          {"height", 480},
          {"annotated_by", "test"},
          {"features",
           {{{"label", "marking"}, {"name", "painted"}, {"points", {{40, 200, 10}, {600, 200, 10}}}},
            {{"label", "marking"}, {"name", "second"}, {"points", {{40, 360, 10}, {600, 360, 10}}}},
            {{"label", "field_boundary"}, {"name", "edge"}, {"points", {{0, 60, 0}, {639, 60, 0}}}}}}};
}

fl::Segment along(float y, fl::Label label) { return {.x0 = 40, .y0 = y, .x1 = 600, .y1 = y, .label = label}; }

TEST(EvalOverlay, EveryEdgePointIsFoundLostOrMissedAsRecallCountsIt) {
  const fl::synth::HandTruth hand = fl::synth::hand_truth_from_json(two_lines("a.png"), "t.json");
  const fl::GtEdges edges(hand.truth);
  // The first line's upper edge (row 195) a marking, its lower edge (205) a segment labelled none;
  // nothing on the second line.
  const std::vector<fl::Segment> segments{along(195, fl::Label::Marking), along(205, fl::Label::None)};
  double seen[3] = {0, 0, 0};
  edges.walk(segments, [&](const fl::GtEdges::Edge&, float, float y, float step, fl::GtEdges::Seen s) {
    seen[static_cast<int>(s)] += step;
    if (std::abs(y - 195) < 1) {
      EXPECT_EQ(s, fl::GtEdges::Seen::Found);
    } else if (std::abs(y - 205) < 1) {
      EXPECT_EQ(s, fl::GtEdges::Seen::OnSegment);
    } else {
      EXPECT_EQ(s, fl::GtEdges::Seen::Missed);
    }
  });
  EXPECT_NEAR(seen[0], 560, 2);
  EXPECT_NEAR(seen[1], 560, 2);
  EXPECT_NEAR(seen[2], 2 * 560, 4);
  // What recall counts is what the walk calls found.
  const fl::GtScore score = edges.score(segments);
  EXPECT_NEAR(score.marking.covered_px, seen[0], 1e-3);
  EXPECT_NEAR(score.marking.visible_px, seen[0] + seen[1] + seen[2], 1);
}

class EvalDraw : public fl::test::TempDirTest {};

// Pixels of `colour` (a palette colour, exactly) in the rows [y0, y1).
int count_colour(const cv::Mat& bgr, fl::palette::Rgb colour, int y0, int y1) {
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < bgr.cols; ++x) {
      const cv::Vec3b p = bgr.at<cv::Vec3b>(y, x);
      n += p[0] == colour.b && p[1] == colour.g && p[2] == colour.r;
    }
  return n;
}

TEST_F(EvalDraw, AnOverlayPerFrameShowsTheFoundAndTheMissedLinesAndTheDrawnBoundary) {
  // The image shows the first line only: the truth's second is missed.
  cv::Mat clean(480, 640, CV_8UC3, fl::test::kTurf);
  cv::rectangle(clean, cv::Point(0, 0), cv::Point(639, 59), fl::test::kDark, cv::FILLED);
  cv::rectangle(clean, cv::Point(40, 195), cv::Point(600, 204), fl::test::kPaint, cv::FILLED);
  write_image("data/a.png", fl::test::noisy(clean));
  fs::create_directories(dir_ / "truth");
  std::ofstream(dir_ / "truth" / "a.json") << two_lines("a.png").dump();
  const fs::path out = dir_ / "overlays";
  const CliRun r = run_cli({"eval", "--hand", (dir_ / "truth").string(), "--data", (dir_ / "data").string(), "--draw",
                            out.string()},
                           dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("overlays written to"), std::string::npos) << r.out;
  const cv::Mat overlay = cv::imread((out / "truth" / "a.png").string());
  ASSERT_FALSE(overlay.empty());
  ASSERT_EQ(overlay.size(), cv::Size(640, 480));
  const int found = count_colour(overlay, fl::palette::kTruthFound, 185, 215);
  EXPECT_GT(found, 600) << "the painted line's edges are found";
  EXPECT_LT(count_colour(overlay, fl::palette::kMissedPaint, 185, 215), found / 10) << "at most its ends are missed";
  EXPECT_GT(count_colour(overlay, fl::palette::kMissedPaint, 350, 370), 500) << "the line the frame lacks is missed";
  EXPECT_GT(count_colour(overlay, fl::palette::kTruthFound, 57, 64), 300) << "the drawn field boundary";

  // A --draw that is a file, not a folder: a clear error before anything runs.
  std::ofstream(dir_ / "taken") << "x";
  const CliRun bad = run_cli({"eval", "--hand", (dir_ / "truth").string(), "--data", (dir_ / "data").string(), "--draw",
                              (dir_ / "taken").string()},
                             dir_);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--draw"), std::string::npos) << bad.err;
}

}  // namespace
