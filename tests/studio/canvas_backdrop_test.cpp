// The canvas's backdrop bands around the image (gui/model/canvas_backdrop.hpp).
#include <gtest/gtest.h>

#include "gui/model/canvas_backdrop.hpp"

namespace fs = fieldlines::studio;

namespace {

float area_of(std::span<const fs::Rect> rects) {
  float sum = 0;
  for (const fs::Rect& r : rects) sum += r.width() * r.height();
  return sum;
}

bool overlap(const fs::Rect& a, const fs::Rect& b) {
  return a.min.x < b.max.x && b.min.x < a.max.x && a.min.y < b.max.y && b.min.y < a.max.y;
}

}  // namespace

TEST(CanvasBackdrop, FillsOnlyBesideAFittedImage) {
  const fs::Rect canvas{{6, 6}, {866.5f, 773}};
  const fs::Rect image{{6, 67.25f}, {866.5f, 711.75f}};  // fitted by width: bands above and below
  const fs::Backdrop backdrop(canvas, image);
  ASSERT_EQ(backdrop.bands().size(), 2u);
  EXPECT_EQ(backdrop.bands()[0].max.y, image.min.y);  // the shared edges are the image's own
  EXPECT_EQ(backdrop.bands()[1].min.y, image.max.y);
  EXPECT_FLOAT_EQ(area_of(backdrop.bands()) + image.width() * image.height(), canvas.width() * canvas.height());
}

TEST(CanvasBackdrop, BandsAndImageTileTheCanvasOnce) {
  const fs::Rect canvas{{0, 0}, {100, 80}};
  const fs::Rect image{{20.5f, 10.25f}, {70, 50}};  // inside, off centre: four bands
  const fs::Backdrop backdrop(canvas, image);
  const auto bands = backdrop.bands();
  ASSERT_EQ(bands.size(), 4u);
  for (std::size_t i = 0; i < bands.size(); ++i) {
    EXPECT_FALSE(overlap(bands[i], image)) << i;
    for (std::size_t j = i + 1; j < bands.size(); ++j) EXPECT_FALSE(overlap(bands[i], bands[j])) << i << " " << j;
  }
  EXPECT_FLOAT_EQ(area_of(bands) + image.width() * image.height(), canvas.width() * canvas.height());
}

TEST(CanvasBackdrop, AZoomedInImageLeavesNoBackdrop) {
  const fs::Backdrop backdrop({{0, 0}, {100, 80}}, {{-500, -400}, {900, 700}});
  EXPECT_TRUE(backdrop.bands().empty());
}

TEST(CanvasBackdrop, APannedImageIsClippedToTheCanvas) {
  const fs::Rect canvas{{0, 0}, {100, 80}};
  const fs::Backdrop backdrop(canvas, {{60, -30}, {300, 40}});  // past the top right corner
  ASSERT_EQ(backdrop.bands().size(), 2u);
  EXPECT_FLOAT_EQ(area_of(backdrop.bands()), 100 * 80 - 40 * 40);
}

TEST(CanvasBackdrop, NoImageOrOneOffCanvasLeavesTheWholeCanvas) {
  const fs::Rect canvas{{0, 0}, {100, 80}};
  for (const fs::Rect hole : {fs::Rect{}, fs::Rect{{200, 0}, {300, 80}}, fs::Rect{{10, 10}, {10, 50}}}) {
    const fs::Backdrop backdrop(canvas, hole);
    ASSERT_EQ(backdrop.bands().size(), 1u);
    EXPECT_EQ(backdrop.bands()[0].min, canvas.min);
    EXPECT_EQ(backdrop.bands()[0].max, canvas.max);
  }
}
