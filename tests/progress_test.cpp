// The batch progress report: right mode for the output, one line per 10% in logs, messages
// never mixed into the bar, and safe to advance from several threads.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "app/cli/progress.hpp"

using fieldlines::cli::Progress;
using fieldlines::cli::ProgressParams;
using Mode = ProgressParams::Mode;

namespace {

// A temporary FILE* (not a terminal) whose contents can be read back.
class Capture {
 public:
  Capture() : file_(std::tmpfile()) {}
  ~Capture() { std::fclose(file_); }
  Capture(const Capture&) = delete;
  Capture& operator=(const Capture&) = delete;
  std::FILE* file() { return file_; }
  std::string text() {
    std::fflush(file_);
    std::rewind(file_);
    std::string out;
    for (int c; (c = std::fgetc(file_)) != EOF;) out += static_cast<char>(c);
    return out;
  }

 private:
  std::FILE* file_;
};

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(Progress, AutoPicksLinesForFilesAndNothingForOneItem) {
  Capture a, b;
  EXPECT_EQ(Progress("x", 5, a.file()).mode(), Mode::Lines);
  EXPECT_EQ(Progress("x", 1, b.file()).mode(), Mode::Off);
  EXPECT_EQ(b.text(), "");
}

TEST(Progress, LinesModePrintsOncePerTenPercent) {
  Capture c;
  {
    Progress p("detect", 200, c.file());
    for (int i = 0; i < 200; ++i) p.advance();
  }
  const std::string text = c.text();
  EXPECT_EQ(count(text, "\n"), 10u) << text;
  EXPECT_NE(text.find("detect: 20/200 (10%)"), std::string::npos) << text;
  EXPECT_NE(text.find("detect: 200/200 (100%)"), std::string::npos) << text;
  EXPECT_EQ(text.find('\r'), std::string::npos) << "no terminal control in logs";
}

TEST(Progress, BarModeRedrawsInPlaceAndKeepsMessagesOnTheirOwnLines) {
  Capture c;
  {
    ProgressParams params;
    params.mode = Mode::Bar;
    params.width = 10;
    Progress p("detect", 4, c.file(), params);
    p.advance(2);
    p.message("fieldlines detect: bad.png: empty file (0 bytes)");
    p.advance(2);
  }
  const std::string text = c.text();
  // The message is preceded by a line clear and followed by a newline, never glued to the bar.
  EXPECT_NE(text.find("\r\033[2Kfieldlines detect: bad.png: empty file (0 bytes)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("[##########] 4/4"), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n');
}

TEST(Progress, OffModeStillPrintsMessages) {
  Capture c;
  {
    ProgressParams params;
    params.mode = Mode::Off;
    Progress p("x", 100, c.file(), params);
    p.advance(50);
    p.message("warning");
    p.advance(50);
  }
  EXPECT_EQ(c.text(), "warning\n");
}

TEST(Progress, AdvancingFromSeveralThreadsCountsEveryItem) {
  Capture c;
  {
    Progress p("batch", 4000, c.file());
    std::vector<std::jthread> workers;
    for (int t = 0; t < 4; ++t)
      workers.emplace_back([&p] {
        for (int i = 0; i < 1000; ++i) p.advance();
      });
  }
  const std::string text = c.text();
  EXPECT_NE(text.find("batch: 4000/4000 (100%)"), std::string::npos) << text;
  EXPECT_EQ(count(text, "\n"), 10u) << text;
}
