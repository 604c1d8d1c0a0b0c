// The status bar's text without a window: the cut with "..." (gui/model/ellipsize.hpp) and what
// the notes say and in which order (gui/model/status_line.hpp).
#include <gtest/gtest.h>

#include <string>

#include "fixtures.hpp"
#include "gui/model/ellipsize.hpp"
#include "gui/model/status_line.hpp"

namespace fs = fieldlines::studio;

namespace {

// A monospace font of 7 px a character (a UTF-8 sequence is one character).
float mono(std::string_view t) {
  float n = 0;
  for (const char ch : t) n += (static_cast<unsigned char>(ch) & 0xC0) != 0x80;
  return n * 7;
}

TEST(StudioEllipsize, TextThatFitsIsKeptAndLongerTextIsCutToTheWidthWithThreeDots) {
  EXPECT_EQ(fs::ellipsize("short", 35, mono), "short");
  EXPECT_EQ(fs::ellipsize("a longer line", 70, mono), "a longe...");  // 7 characters + ... = 10
  EXPECT_LE(mono(fs::ellipsize("a longer line", 70, mono)), 70);
  // Never ends on a space before the dots, never cuts inside a character.
  EXPECT_EQ(fs::ellipsize("ab cd", 28, mono), "a...");
  EXPECT_EQ(fs::ellipsize("ab cdef", 42, mono), "ab...");
  EXPECT_EQ(fs::ellipsize("\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9", 34, mono), "\xc3\xa9...");
  // No room even for the dots: nothing.
  EXPECT_EQ(fs::ellipsize("anything", 21, mono), "...");
  EXPECT_EQ(fs::ellipsize("anything", 20, mono), "");
  // Every width: the result fits, and one more character would not.
  const std::string text = "the quick brown fox jumps over the lazy dog";
  for (float w = 21; w < mono(text); w += 3) {
    const std::string cut = fs::ellipsize(text, w, mono);
    EXPECT_LE(mono(cut), w) << w;
    EXPECT_GT(mono(cut) + 7, w - 7) << w << " " << cut;
  }
}

TEST(StudioStatusLine, CountersAndNotesMostUrgentFirst) {
  studio_test::TempDir dir("status-line");
  const auto file = studio_test::write_project(dir.path(), 2, 6);
  fs::ControllerOptions options;
  options.load_pixels = false;
  fs::StudioController c(fieldlines::Project::load(file), file, options);
  const std::string counters = fs::status_counters(c, 1.5, 12.34);
  EXPECT_EQ(counters.find("image 1/2  |"), 0u) << counters;
  EXPECT_EQ(counters.substr(counters.size() - 10), "img_00.png") << counters;  // last: cut first
  EXPECT_NE(counters.find("0/6 labelled"), std::string::npos) << counters;
  EXPECT_NE(counters.find("12 to review"), std::string::npos) << counters;
  EXPECT_NE(counters.find("zoom 150%"), std::string::npos) << counters;
  EXPECT_TRUE(fs::status_notes(c, "").empty());
  const std::size_t one[] = {0};
  ASSERT_TRUE(c.label(one, fieldlines::Label::Marking));
  const auto notes = fs::status_notes(c, "accepted 3 proposals");
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_EQ(notes[0].text, "accepted 3 proposals");
  EXPECT_EQ(notes[1].text, "saved");
}

}  // namespace
