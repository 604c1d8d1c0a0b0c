// Crash safety of the studio's autosave: the real studio under Xvfb labels one segment over and
// over (xdotool holding M and B, one save per key) and is killed with SIGKILL at seeded moments,
// a third of them a few microseconds after the save's temporary file appears (inotify). After
// every kill the project file must load and be the old project or a complete newer one: same
// images and segments, only the driven segment's label changed. The next start reopens it.
// The review loop is killed the same way: P (propose), Enter (accept, with auto-train
// retraining in the background and saving its thresholds) and Ctrl+Z, over and over.
// ctest-label: slow

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <thread>

#include "fieldlines/data/project.hpp"
#include "tests/save_watch.hpp"
#include "x_session.hpp"

namespace fs = std::filesystem;
using fieldlines::Label;
using fieldlines::test::temporaries;
using fieldlines::test::wait_for_creation;
using namespace std::chrono_literals;

namespace {

constexpr int kKills = 15;

class StudioCrash : public studio_test::StudioUnderX {
 protected:
  void SetUp() override {
    StudioUnderX::SetUp();
    // Large enough that a save takes milliseconds: 12 images x 400 segments.
    use_project(12, 400);
  }
  // Waits until a save's temporary file appears, then `in_save` more, and SIGKILLs the studio
  // (and the key sender) there.
  void kill_inside_a_save(studio_test::Child& studio, studio_test::Child& keys, std::chrono::microseconds in_save) {
    const int watch = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    ASSERT_GE(watch, 0);
    ASSERT_GE(::inotify_add_watch(watch, dir().c_str(), IN_CREATE), 0);
    EXPECT_TRUE(wait_for_creation(watch, fieldlines::temporary_prefix(project_), 10s)) << "no save started";
    std::this_thread::sleep_for(in_save);
    ::close(watch);
    kill_both(studio, keys);
  }
  static void kill_both(studio_test::Child& studio, studio_test::Child& keys) {
    studio.kill(SIGKILL);
    studio.wait();
    keys.kill(SIGKILL);
  }
  // The project on disk loads and has the original's images and segment geometry.
  fieldlines::Project load_intact(const fieldlines::Project& original, int kill) const {
    fieldlines::Project now;
    EXPECT_NO_THROW(now = fieldlines::Project::load(project_)) << "kill " << kill << " left a project that does not load";
    EXPECT_EQ(now.images.size(), original.images.size());
    for (std::size_t i = 0; i < std::min(now.images.size(), original.images.size()); ++i) {
      const auto& a = now.images[i].segments;
      const auto& b = original.images[i].segments;
      EXPECT_EQ(a.size(), b.size()) << "kill " << kill << ", image " << i;
      for (std::size_t j = 0; j < std::min(a.size(), b.size()); ++j) EXPECT_FLOAT_EQ(a[j].x0, b[j].x0);
    }
    return now;
  }
};

TEST_F(StudioCrash, KilledDuringAutosavesLeavesOldOrCompleteProject) {
  const fieldlines::Project original = fieldlines::Project::load(project_);
  std::mt19937 rng(20261129);
  std::uniform_int_distribution<int> anywhere_ms(0, 1500), in_save_us(0, 100);
  int mid_save = 0, changed = 0;
  for (int k = 0; k < kKills; ++k) {
    auto studio = start_studio();
    ASSERT_TRUE(studio->running()) << log();
    const std::size_t target = static_cast<std::size_t>(k) * 7 % segments_.size();
    hover(target);
    const int temps_before = temporaries(project_);
    // M, B, M, B ... on the hovered segment: every key press changes its label and saves.
    studio_test::Child keys({"/usr/bin/xdotool", "key", "--delay", "15", "--repeat", "400", "m", "b"},
                            {"DISPLAY=" + display_.name}, dir() / "xdotool.log");
    if (k % 3 == 2) {
      std::this_thread::sleep_for(200ms);  // let a few saves complete first
      kill_inside_a_save(*studio, keys, std::chrono::microseconds(in_save_us(rng)));
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(anywhere_ms(rng)));
      kill_both(*studio, keys);
    }
    if (temporaries(project_) > temps_before) ++mid_save;

    const fieldlines::Project now = load_intact(original, k);
    if (HasFailure()) return;
    for (std::size_t i = 0; i < now.images.size(); ++i) {
      const auto& a = now.images[i].segments;
      for (std::size_t j = 0; j < a.size(); ++j) {
        // Only the segments driven so far may carry labels, and only the ones M and B give.
        const bool driven = i == 0 && j % 7 == 0 && j <= target;
        if (!driven) {
          EXPECT_EQ(a[j].label, Label::Unlabelled) << "kill " << k << ", image " << i << ", segment " << j;
        }
      }
    }
    const Label l = now.images[0].segments[target].label;
    EXPECT_TRUE(l == Label::Unlabelled || l == Label::Marking || l == Label::Boundary) << static_cast<int>(l);
    if (l != Label::Unlabelled) ++changed;
  }
  std::printf("studio: %d kills, %d landed inside a save (temporary file left), %d after the driven label changed\n",
              kKills, mid_save, changed);
  // Most kills come long after the first save, so the label must have reached the disk.
  EXPECT_GT(changed, kKills / 2);
}

TEST_F(StudioCrash, KilledWhileProposingAcceptingAndRetrainingLeavesAValidProject) {
  constexpr int kReviewKills = 8;
  const fieldlines::Project original = fieldlines::Project::load(project_);
  std::mt19937 rng(20261201);
  std::uniform_int_distribution<int> anywhere_ms(300, 2500), in_save_us(0, 100);
  int progressed = 0;
  std::size_t most_labels = 0;
  for (int k = 0; k < kReviewKills; ++k) {
    auto studio = start_studio();
    ASSERT_TRUE(studio->running()) << log();
    studio_test::Child keys({"/usr/bin/xdotool", "key", "--delay", "40", "--repeat", "100", "p", "Return", "Return",
                             "ctrl+z", "Return"},
                            {"DISPLAY=" + display_.name}, dir() / "xdotool.log");
    if (k % 2 == 1) {
      std::this_thread::sleep_for(300ms);
      kill_inside_a_save(*studio, keys, std::chrono::microseconds(in_save_us(rng)));
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(anywhere_ms(rng)));
      kill_both(*studio, keys);
    }
    const fieldlines::Project now = load_intact(original, k);
    if (HasFailure()) return;
    for (std::size_t i = 0; i < now.images.size(); ++i) {
      // Proposals are all or nothing per image (an accepted one stays, for undo, under its label).
      const auto& proposals = now.images[i].proposals;
      EXPECT_TRUE(proposals.empty() || proposals.size() == now.images[i].segments.size()) << "kill " << k << ", image " << i;
    }
    most_labels = std::max(most_labels, now.labelled_count());
    progressed += now.labelled_count() > 0;
  }
  std::printf("studio review loop: %d kills, %d left accepted labels on disk (at most %zu)\n", kReviewKills,
              progressed, most_labels);
  EXPECT_GT(progressed, kReviewKills / 2);
}

}  // namespace
