// Overlapping segments in the real window: the two edges of a painted line lie within a pixel
// or two, so both are under the cursor. Space hovers the other one (wrapping), and a label key
// moves the hover on to the next unlabelled one, so pressing two keys labels both segments
// instead of silently re-labelling the first.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>
#include <thread>

#include <opencv2/imgcodecs.hpp>

#include "fieldlines/data/project.hpp"
#include "gui/model/hit_test.hpp"
#include "x_session.hpp"

using fieldlines::Label;
using namespace std::chrono_literals;

namespace {

class StudioOverlapWindow : public studio_test::StudioUnderX {
 protected:
  void SetUp() override {
    StudioUnderX::SetUp();
    project_ = studio_test::write_project(dir(), 1, 12, 640, 480);
    auto project = fieldlines::Project::load(project_);
    auto& segments = project.images[0].segments;
    fieldlines::Segment twin = segments[0];  // the line's other edge, 1.5 image px below
    twin.y0 += 1.5f;
    twin.y1 += 1.5f;
    segments.push_back(twin);
    project.save(project_);
    segments_ = segments;
  }
  long hovered() const { return studio_test::read_state(state_)["hovered"].get<long>(); }
  // Near-white pixels 6..9 screen px left of segment i's left end: turf (the painted line's cap
  // ends within 5) unless the hovered segment's endpoint ring is drawn there.
  int white_above_start(const std::string& shot_name, std::size_t i) const {
    const nlohmann::json st = studio_test::read_state(state_);
    fieldlines::studio::ViewTransform view;
    view.set(st["scale"].get<float>(), {st["offset"][0].get<float>(), st["offset"][1].get<float>()});
    const auto end = fieldlines::studio::to_screen(segments_[i], view).a;
    const cv::Mat shot = cv::imread(screenshot(shot_name).string());
    int white = 0;
    const int ex = static_cast<int>(std::lround(end.x)), ey = static_cast<int>(std::lround(end.y));
    for (int y = ey - 4; y <= ey + 4; ++y) {
      for (int x = ex - 9; x <= ex - 6; ++x) {
        if (x < 0 || y < 0 || x >= shot.cols || y >= shot.rows) continue;
        const cv::Vec3b p = shot.at<cv::Vec3b>(y, x);
        white += p[0] > 215 && p[1] > 215 && p[2] > 215;
      }
    }
    return white;
  }
};

}  // namespace

TEST_F(StudioOverlapWindow, SpaceCyclesAndALabelMovesOnToTheOtherSegment) {
  auto studio = start_studio();
  ASSERT_TRUE(studio->running()) << log();
  constexpr long kTwin = 12;

  // Unhovered, the turf just left of segment 0's end is green; hovered, its endpoint ring shows.
  ASSERT_EQ(studio_test::run(x("mousemove 5 5")), 0);
  std::this_thread::sleep_for(300ms);
  const int plain = white_above_start("plain", 0);
  hover(0);  // the pointer on segment 0's centre line: it is the nearest
  std::this_thread::sleep_for(300ms);
  const int highlighted = white_above_start("hovered", 0);
  EXPECT_EQ(plain, 0);
  EXPECT_GE(highlighted, 4) << "no endpoint ring around the hovered segment";
  ASSERT_EQ(studio_test::run(x("key space")), 0);
  EXPECT_TRUE(studio_test::wait_for([&] { return hovered() == kTwin; }, 10s)) << hovered();
  ASSERT_EQ(studio_test::run(x("key space")), 0);
  EXPECT_TRUE(studio_test::wait_for([&] { return hovered() == 0; }, 10s)) << hovered();  // wrapped

  // M labels segment 0; the hover moves on to its twin, so B labels the twin, not 0 again.
  act_and_wait_for_save("key m");
  EXPECT_TRUE(studio_test::wait_for([&] { return hovered() == kTwin; }, 10s)) << hovered();
  act_and_wait_for_save("key b");
  const auto p = fieldlines::Project::load(project_);
  EXPECT_EQ(p.images[0].segments[0].label, Label::Marking);
  EXPECT_EQ(p.images[0].segments[kTwin].label, Label::Boundary);
  // Both labelled now: a further key stays on the hovered twin (it corrects it).
  act_and_wait_for_save("key n");
  EXPECT_EQ(hovered(), kTwin);
  EXPECT_EQ(fieldlines::Project::load(project_).images[0].segments[kTwin].label, Label::None);
  EXPECT_EQ(fieldlines::Project::load(project_).images[0].segments[0].label, Label::Marking);

  ASSERT_EQ(studio_test::run(x("key ctrl+q")), 0);
  EXPECT_TRUE(studio_test::wait_for([&] { return !studio->running(); }, 20s));
  EXPECT_EQ(studio->exit_code(), 0) << log();
}
