#pragma once
// The real studio under Xvfb, for the window, crash-safety and soak tests: child processes, a
// private X display, the studio's automation state file and xdotool, behind one gtest fixture.
#include <gtest/gtest.h>

#include <sys/types.h>

#include <array>
#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "fieldlines/detect/segment.hpp"
#include "fixtures.hpp"

namespace studio_test {

// The built studio, and where screenshots go unless $FIELDLINES_SCREENSHOT_DIR says otherwise:
// compiled into x_session.cpp alone, so the window tests' objects do not depend on the clone's
// path (tests/test_paths.hpp says why).
std::filesystem::path studio_path();
std::filesystem::path default_screenshot_dir();

// A child process with stdout/stderr appended to `log`; killed (SIGKILL) and reaped by the
// destructor if still running.
class Child {
 public:
  Child(const std::vector<std::string>& argv, const std::vector<std::string>& extra_env,
        const std::filesystem::path& log);
  ~Child();
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  bool running();
  void kill(int sig);
  int wait();
  int exit_code();  // exit code, or -1 until it has exited normally
  pid_t pid() const { return pid_; }

 private:
  pid_t pid_ = -1;
  std::optional<int> status_;
};

// Polls `done` every 50 ms until it holds or `timeout` passes.
bool wait_for(const std::function<bool()>& done, std::chrono::milliseconds timeout);

int run(const std::string& command);

// The studio's automation state file (--state-file), or null while it does not exist yet.
nlohmann::json read_state(const std::filesystem::path& file);

// Resident set size of a process in KiB (/proc/PID/status VmRSS), or -1 when it is gone.
long rss_kib(pid_t pid);

// Rows of a screenshot's side panel whose left edge (x = 878) has colour `rgb` (a text field's
// frame, a button), as the centres of runs of 10 rows or more, top to bottom: the widgets
// found the way a user sees them.
std::vector<int> rows_of_colour(const std::filesystem::path& screenshot, std::array<int, 3> rgb);

struct Display {
  std::string name;
  std::unique_ptr<Child> server;
};

// Starts Xvfb with a 24-bit width x height screen on a display number it picks itself
// (-displayfd), so parallel test runs never share a display.
Display start_xvfb(const std::filesystem::path& log, int width, int height);

// A fixture owning a temporary folder, a private display and the studio process; a test writes
// its project into dir() and calls start_studio().
class StudioUnderX : public ::testing::Test {
 protected:
  static constexpr int kWidth = 1280, kHeight = 800;

  void SetUp() override;

  // Writes `images` synthetic 640x480 images with `segments` known segments each as the project
  // start_studio() opens; segments_ holds the first image's.
  void use_project(int images, int segments);
  nlohmann::json state() const { return read_state(state_); }
  // Starts the studio on `project_` and waits until it has written its state file.
  std::unique_ptr<Child> start_studio();
  std::string log() const;
  // An xdotool command line on this display.
  std::string x(const std::string& args) const;
  // Screen position of segments_[i]'s midpoint from the studio's current view transform.
  std::pair<int, int> on_screen(std::size_t i) const;
  // Moves the pointer onto segments_[i] and waits until the studio reports it hovered.
  void hover(std::size_t i);
  // Runs an xdotool action and waits for the studio to have saved once more.
  void act_and_wait_for_save(const std::string& xdotool_args);
  std::filesystem::path screenshot(const std::string& name) const;
  const std::filesystem::path& dir() const { return dir_.path(); }

  TempDir dir_{"window"};
  Display display_;
  std::filesystem::path project_;
  std::filesystem::path state_ = dir_.path() / "state.json";
  std::vector<fieldlines::Segment> segments_;
};

}  // namespace studio_test
