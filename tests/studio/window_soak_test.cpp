// Soak: the real studio under Xvfb driven with seeded random clicks, drags, wheel turns and keys
// (labels, undo/redo, navigation, panels, training start/stop) for $FIELDLINES_SOAK_SECONDS
// (default 40; docs/studio.md's figure is from 600). Every second the studio must still be running;
// its resident memory after warm-up must stay flat; at the end it quits cleanly (exit 0), the
// project loads, and its log holds no error.
// ctest-label: slow

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "fieldlines/data/project.hpp"
#include "fieldlines/synth/synth.hpp"
#include "x_session.hpp"

namespace fs = std::filesystem;
using namespace std::chrono_literals;

namespace {

int soak_seconds() {
  const char* s = std::getenv("FIELDLINES_SOAK_SECONDS");
  const int v = s ? std::atoi(s) : 0;
  return v > 0 ? v : 40;
}

// One random user action as xdotool arguments. Never Ctrl+Q: the soak ends the session itself.
std::string random_action(std::mt19937& rng, int width, int height) {
  static const std::vector<std::string> keys = {"m", "b", "n", "c", "Left", "Right", "e", "f", "F1", "F2", "F3", "F4",
                                                "F5", "F6", "ctrl+z", "ctrl+shift+z", "ctrl+y", "ctrl+t"};
  std::uniform_int_distribution<int> kind(0, 9), px(0, width - 1), py(0, height - 1);
  std::uniform_int_distribution<std::size_t> key(0, keys.size() - 1);
  const auto at = [&] { return std::to_string(px(rng)) + " " + std::to_string(py(rng)); };
  switch (kind(rng)) {
    case 0: case 1: case 2: return "mousemove " + at();
    case 3: return "mousemove " + at() + " click 1";
    case 4: return "mousemove " + at() + " click 3";
    case 5: return "mousemove " + at() + " click " + std::string(py(rng) % 2 ? "4" : "5");  // wheel
    case 6: return "mousemove " + at() + " mousedown 1 mousemove " + at() + " mouseup 1";  // drag
    case 7: return "mousemove " + at() + " mousedown 3 mousemove " + at() + " mouseup 3";  // pan
    default: return "key " + keys[key(rng)];
  }
}

class StudioSoak : public studio_test::StudioUnderX {};

TEST_F(StudioSoak, RandomClicksAndKeysKeepMemoryFlatAndLoseNothing) {
  // Six synthetic field pictures: the studio detects them in the background on start.
  const fs::path folder = dir() / "pictures";
  fs::create_directories(folder);
  const fieldlines::synth::SynthParams params;
  for (int i = 0; i < 6; ++i) fieldlines::synth::write_sample(fieldlines::synth::generate(params, 5, i), folder);
  project_ = folder;
  auto studio = start_studio();
  ASSERT_TRUE(studio->running()) << log();

  const int seconds = soak_seconds();
  const auto warm_up = std::chrono::seconds(std::min(10, seconds / 4));
  std::mt19937 rng(20261129);
  const auto start = std::chrono::steady_clock::now();
  auto next_sample = start;
  long rss_start = -1, rss_end = -1, rss_peak = 0;
  int actions = 0;
  while (std::chrono::steady_clock::now() - start < std::chrono::seconds(seconds)) {
    const std::string action = random_action(rng, kWidth, kHeight);
    ASSERT_EQ(studio_test::run(x(action)), 0) << action;
    ++actions;
    if (std::chrono::steady_clock::now() >= next_sample) {
      next_sample += 1s;
      ASSERT_TRUE(studio->running()) << "the studio died after " << actions << " actions, last: " << action << "\n"
                                     << log();
      const long rss = studio_test::rss_kib(studio->pid());
      rss_peak = std::max(rss_peak, rss);
      if (rss_start < 0 && std::chrono::steady_clock::now() - start >= warm_up) rss_start = rss;
      rss_end = rss;
    }
  }
  const int saves = studio_test::read_state(state_)["save_count"].get<int>();
  // Let a training run started by the last keys finish or stop, then quit like a user.
  ASSERT_EQ(studio_test::run(x("mousemove 5 5")), 0);
  if (studio_test::read_state(state_)["training"] == true) {
    ASSERT_EQ(studio_test::run(x("key ctrl+t")), 0);
  }
  ASSERT_EQ(studio_test::run(x("key ctrl+q")), 0);
  ASSERT_TRUE(studio_test::wait_for([&] { return !studio->running(); }, 30s)) << "no exit after Ctrl+Q";
  EXPECT_EQ(studio->exit_code(), 0) << log();

  std::printf("soak: %d s, %d actions, %d saves, RSS after %lld s warm-up %.1f MiB, at the end %.1f MiB, peak %.1f MiB\n",
              seconds, actions, saves, static_cast<long long>(warm_up.count()), rss_start / 1024.0, rss_end / 1024.0,
              rss_peak / 1024.0);
  ASSERT_GT(rss_start, 0);
  EXPECT_GT(saves, 0) << "the random actions never changed a label";
  // Flat: under 32 MiB (or 15 %) of growth after warm-up, whatever the duration.
  EXPECT_LT(rss_end - rss_start, std::max(32L * 1024, rss_start * 15 / 100));

  const fieldlines::Project project = fieldlines::Project::load(folder / "fieldlines-project.json");
  EXPECT_EQ(project.images.size(), 6u);
  const std::string text = log();
  for (const char* bad : {"error", "Error", "ERROR", "Sanitizer", "terminate"}) {
    EXPECT_EQ(text.find(bad), std::string::npos) << "studio log:\n" << text;
  }
}

}  // namespace
