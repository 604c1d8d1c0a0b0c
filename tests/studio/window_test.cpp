// The real studio window under Xvfb (Mesa llvmpipe), driven with xdotool like a user: hover and
// click segments, press keys, check the project file on disk, capture the screen, SIGKILL the
// process mid-session and reopen. Also writes the panel screenshots to docs/screenshots/.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "fieldlines/atomic_file.hpp"
#include "fieldlines/dataset.hpp"
#include "fieldlines/synth.hpp"
#include "fixtures.hpp"
#include "hit_test.hpp"
#include "overlay_style.hpp"
#include "view_transform.hpp"

namespace fs = std::filesystem;
using fieldlines::Label;
using namespace std::chrono_literals;

namespace {

constexpr int kWidth = 1280, kHeight = 800;

// A child process, killed (SIGKILL) and reaped by the destructor if still running.
class Child {
 public:
  Child(const std::vector<std::string>& argv, const std::vector<std::string>& extra_env, const fs::path& log) {
    std::vector<std::string> env;
    for (char** e = environ; *e; ++e) env.emplace_back(*e);
    for (const auto& e : extra_env) env.push_back(e);
    pid_ = ::fork();
    if (pid_ == 0) {
      const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
      if (fd >= 0) {
        ::dup2(fd, 1);
        ::dup2(fd, 2);
      }
      std::vector<char*> a, e;
      for (const auto& s : argv) a.push_back(const_cast<char*>(s.c_str()));
      for (const auto& s : env) e.push_back(const_cast<char*>(s.c_str()));
      a.push_back(nullptr);
      e.push_back(nullptr);
      ::execve(a[0], a.data(), e.data());
      ::_exit(127);
    }
  }
  ~Child() {
    if (running()) kill(SIGKILL);
    wait();
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  bool running() {
    if (status_) return false;
    int st = 0;
    if (::waitpid(pid_, &st, WNOHANG) == pid_) status_ = st;
    return !status_;
  }
  void kill(int sig) { ::kill(pid_, sig); }
  int wait() {
    if (!status_) {
      int st = 0;
      ::waitpid(pid_, &st, 0);
      status_ = st;
    }
    return *status_;
  }
  // Exit code, or -1 until it has exited normally.
  int exit_code() { return !running() && WIFEXITED(*status_) ? WEXITSTATUS(*status_) : -1; }

 private:
  pid_t pid_ = -1;
  std::optional<int> status_;
};

bool wait_for(const std::function<bool()>& done, std::chrono::milliseconds timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(50ms);
  }
  return done();
}

int run(const std::string& command) { return std::system(command.c_str()); }

// The studio's automation state file (--state-file), or null while it does not exist yet.
nlohmann::json read_state(const fs::path& file) {
  try {
    return nlohmann::json::parse(fieldlines::read_file(file));
  } catch (const std::exception&) {
    return nullptr;
  }
}

struct Display {
  std::string name;
  std::unique_ptr<Child> server;
};

// Starts Xvfb with a 24-bit 1280x800 screen on a display number it picks itself (-displayfd),
// so parallel test runs never share a display.
Display start_xvfb(const fs::path& log) {
  int fds[2];
  if (::pipe(fds) != 0) return {};
  Display d;
  d.server = std::make_unique<Child>(
      std::vector<std::string>{"/usr/bin/Xvfb", "-displayfd", std::to_string(fds[1]), "-screen", "0",
                               std::to_string(kWidth) + "x" + std::to_string(kHeight) + "x24", "-nolisten", "tcp"},
      std::vector<std::string>{}, log);
  ::close(fds[1]);
  std::string number;
  char c = 0;
  while (::read(fds[0], &c, 1) == 1 && c != '\n') number += c;
  ::close(fds[0]);
  if (!number.empty()) d.name = ":" + number;
  return d;
}

class StudioWindow : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(fs::exists("/usr/bin/Xvfb")) << "install xvfb";
    ASSERT_EQ(run("command -v xdotool >/dev/null && command -v import >/dev/null"), 0) << "install xdotool and imagemagick";
    display_ = start_xvfb(dir_.path() / "xvfb.log");
    ASSERT_FALSE(display_.name.empty()) << "no free X display";
    // Two 640x480 images with 12 known segments each.
    project_ = studio_test::write_project(dir_.path(), 2, 12, 640, 480);
    segments_ = fieldlines::Project::load(project_).images[0].segments;
  }

  std::unique_ptr<Child> start_studio() {
    auto child = std::make_unique<Child>(
        std::vector<std::string>{FIELDLINES_STUDIO_PATH, project_.string(), "--window-size",
                                 std::to_string(kWidth) + "x" + std::to_string(kHeight), "--state-file", state_.string()},
        std::vector<std::string>{"DISPLAY=" + display_.name, "XDG_CONFIG_HOME=" + (dir_.path() / "config").string(),
                                 "LIBGL_ALWAYS_SOFTWARE=1"},
        dir_.path() / "studio.log");
    fs::remove(state_);
    EXPECT_TRUE(wait_for([&] { return !read_state(state_).is_null(); }, 30s)) << log();
    return child;
  }

  std::string log() const {
    try {
      return fieldlines::read_file(dir_.path() / "studio.log");
    } catch (const std::exception&) {
      return "";
    }
  }

  std::string x(const std::string& args) const { return "DISPLAY=" + display_.name + " xdotool " + args; }

  // Screen position of segment i's midpoint from the studio's current view transform.
  std::pair<int, int> on_screen(std::size_t i) const {
    const nlohmann::json st = read_state(state_);
    fieldlines::studio::ViewTransform view;
    view.set(st["scale"].get<float>(), {st["offset"][0].get<float>(), st["offset"][1].get<float>()});
    const auto s = fieldlines::studio::to_screen(segments_[i], view);
    return {static_cast<int>(std::lround((s.a.x + s.b.x) / 2)), static_cast<int>(std::lround((s.a.y + s.b.y) / 2))};
  }

  // Moves the pointer onto segment i and waits until the studio reports it hovered.
  void hover(std::size_t i) {
    const auto [px, py] = on_screen(i);
    ASSERT_EQ(run(x("mousemove " + std::to_string(px) + " " + std::to_string(py))), 0);
    ASSERT_TRUE(wait_for([&] { return read_state(state_)["hovered"] == static_cast<long>(i); }, 10s))
        << "segment " << i << " not hovered at " << px << "," << py << ": " << read_state(state_).dump();
  }

  // Runs an xdotool action and waits for the studio to have saved once more.
  void act_and_wait_for_save(const std::string& xdotool_args) {
    const auto before = read_state(state_)["save_count"].get<int>();
    ASSERT_EQ(run(x(xdotool_args)), 0);
    ASSERT_TRUE(wait_for([&] { return read_state(state_)["save_count"].get<int>() > before; }, 10s))
        << xdotool_args << ": no save";
  }

  fs::path screenshot(const std::string& name) const {
    const fs::path out = dir_.path() / (name + ".png");
    EXPECT_EQ(run("DISPLAY=" + display_.name + " import -window root " + out.string()), 0);
    return out;
  }

  studio_test::TempDir dir_{"window"};
  Display display_;
  fs::path project_;
  fs::path state_ = dir_.path() / "state.json";
  std::vector<fieldlines::Segment> segments_;
};

// Count of pixels within `tol` of an RGB colour along segment i's drawn line.
int colour_hits(const cv::Mat& shot, const std::pair<int, int>& mid, fieldlines::studio::Rgba c, int tol = 40) {
  int hits = 0;
  for (int dx = -30; dx <= 30; ++dx) {
    for (int dy = -3; dy <= 3; ++dy) {
      const int px = mid.first + dx, py = mid.second + dy;
      if (px < 0 || py < 0 || px >= shot.cols || py >= shot.rows) continue;
      const cv::Vec3b p = shot.at<cv::Vec3b>(py, px);  // BGR
      if (std::abs(p[2] - c.r) <= tol && std::abs(p[1] - c.g) <= tol && std::abs(p[0] - c.b) <= tol) ++hits;
    }
  }
  return hits;
}

}  // namespace

TEST_F(StudioWindow, LabelByMouseAndKeysUndoRedoAndSurviveSigkill) {
  auto studio = start_studio();
  ASSERT_TRUE(studio->running()) << log();

  // Segment 0: hover + key M. Segment 1: left click (brush = marking). Segment 2: key B.
  // Segment 3: right click = none. Segment 4: key N, then undone with Ctrl+Z and redone.
  hover(0);
  act_and_wait_for_save("key m");
  hover(1);
  act_and_wait_for_save("click 1");
  hover(2);
  act_and_wait_for_save("key b");
  hover(3);
  act_and_wait_for_save("click 3");
  hover(4);
  act_and_wait_for_save("key n");
  act_and_wait_for_save("key ctrl+z");
  {
    const auto p = fieldlines::Project::load(project_);
    EXPECT_EQ(p.images[0].segments[4].label, Label::Unlabelled);  // undone, on disk
    EXPECT_EQ(p.images[0].segments[3].label, Label::None);
  }
  act_and_wait_for_save("key ctrl+shift+z");

  const auto p = fieldlines::Project::load(project_);
  const auto& s = p.images[0].segments;
  EXPECT_EQ(s[0].label, Label::Marking);
  EXPECT_EQ(s[1].label, Label::Marking);
  EXPECT_EQ(s[2].label, Label::Boundary);
  EXPECT_EQ(s[3].label, Label::None);
  EXPECT_EQ(s[4].label, Label::None);
  for (std::size_t i = 5; i < s.size(); ++i) EXPECT_EQ(s[i].label, Label::Unlabelled) << i;


  // Wheel up over segment 10 zooms at the cursor: the same segment stays under the pointer.
  {
    const float fitted = read_state(state_)["scale"].get<float>();
    hover(10);
    const auto before = on_screen(10);
    ASSERT_EQ(run(x("click 4")), 0);
    ASSERT_TRUE(wait_for([&] { return read_state(state_)["scale"].get<float>() > fitted * 1.1f; }, 10s));
    EXPECT_NEAR(read_state(state_)["scale"].get<float>(), fitted * 1.2f, fitted * 0.01f);
    const auto after = on_screen(10);
    EXPECT_NEAR(after.first, before.first, 1);
    EXPECT_NEAR(after.second, before.second, 1);
    EXPECT_EQ(read_state(state_)["hovered"], 10);
    ASSERT_EQ(run(x("key f")), 0);  // fit again
    ASSERT_TRUE(wait_for([&] { return std::abs(read_state(state_)["scale"].get<float>() - fitted) < 1e-4f; }, 10s));
  }

  // Drag a rectangle across the row of segments 8 and 9: both get the brush label (marking).
  {
    const auto a = on_screen(8), b = on_screen(9);
    ASSERT_EQ(run(x("mousemove " + std::to_string(a.first - 40) + " " + std::to_string(a.second - 10))), 0);
    std::this_thread::sleep_for(150ms);
    ASSERT_EQ(run(x("mousedown 1")), 0);
    std::this_thread::sleep_for(150ms);
    ASSERT_EQ(run(x("mousemove " + std::to_string((a.first + b.first) / 2) + " " + std::to_string(a.second))), 0);
    std::this_thread::sleep_for(150ms);
    act_and_wait_for_save("mousemove " + std::to_string(b.first + 40) + " " + std::to_string(b.second + 10) +
                          " mouseup 1");
    const auto r = fieldlines::Project::load(project_);
    EXPECT_EQ(r.images[0].segments[8].label, Label::Marking);
    EXPECT_EQ(r.images[0].segments[9].label, Label::Marking);
    EXPECT_EQ(r.images[0].segments[10].label, Label::Unlabelled);
    EXPECT_EQ(r.images[0].segments[7].label, Label::Unlabelled);
  }

  // The screen shows the image (green field) and each label's overlay colour on its segment.
  ASSERT_EQ(run(x("mousemove 5 5")), 0);  // away from the segments: no highlight, no tooltip
  ASSERT_TRUE(wait_for([&] { return read_state(state_)["hovered"] == -1; }, 10s));
  std::this_thread::sleep_for(300ms);
  const cv::Mat shot = cv::imread(screenshot("labelled").string());
  ASSERT_FALSE(shot.empty());
  ASSERT_EQ(shot.cols, kWidth);
  const auto field_at = on_screen(6);  // a point between rows of segments: the field's green
  const cv::Vec3b field = shot.at<cv::Vec3b>(field_at.second + 20, field_at.first);
  EXPECT_NEAR(field[1], 140, 12);  // G of the fixture's (40, 140, 40) field
  EXPECT_NEAR(field[0], 40, 12);
  using fieldlines::studio::label_colour;
  EXPECT_GT(colour_hits(shot, on_screen(0), label_colour(Label::Marking)), 40);
  EXPECT_GT(colour_hits(shot, on_screen(2), label_colour(Label::Boundary)), 40);
  EXPECT_GT(colour_hits(shot, on_screen(3), label_colour(Label::None)), 40);
  EXPECT_GT(colour_hits(shot, on_screen(7), label_colour(Label::Unlabelled)), 20);
  EXPECT_EQ(colour_hits(shot, on_screen(7), label_colour(Label::Marking)), 0);

  // Next image with the arrow key, label there, then SIGKILL right after the save.
  ASSERT_EQ(run(x("key Right")), 0);
  ASSERT_TRUE(wait_for([&] { return read_state(state_)["image"] == 1; }, 10s));
  hover(5);
  act_and_wait_for_save("key b");
  studio->kill(SIGKILL);
  studio->wait();

  const auto killed = fieldlines::Project::load(project_);  // valid JSON project, nothing lost
  EXPECT_EQ(killed.images[1].segments[5].label, Label::Boundary);
  EXPECT_EQ(killed.images[0].segments[0].label, Label::Marking);
  for (const auto& entry : fs::directory_iterator(dir_.path())) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << "temporary file left";
  }

  // Reopen: the studio starts on the same file, and the labels are still there after quitting.
  auto again = start_studio();
  ASSERT_TRUE(again->running()) << log();
  hover(6);
  act_and_wait_for_save("key m");
  ASSERT_EQ(run(x("key ctrl+q")), 0);
  ASSERT_TRUE(wait_for([&] { return !again->running(); }, 15s));
  EXPECT_EQ(again->exit_code(), 0);
  const auto reopened = fieldlines::Project::load(project_);
  EXPECT_EQ(reopened.images[1].segments[5].label, Label::Boundary);
  EXPECT_EQ(reopened.images[0].segments[6].label, Label::Marking);
}

TEST_F(StudioWindow, PanelScreenshotsOnDetectedSyntheticPictures) {
  // A folder of synthetic field pictures: the studio creates the project and detects in the
  // background; the screenshots for the docs show real detections.
  const fs::path folder = dir_.path() / "pictures";
  fs::create_directories(folder);
  fieldlines::synth::SynthParams params;
  for (int i = 0; i < 5; ++i) fieldlines::synth::write_sample(fieldlines::synth::generate(params, 11, i), folder);
  project_ = folder;
  auto studio = start_studio();
  ASSERT_TRUE(studio->running()) << log();
  const fs::path file = folder / "fieldlines-project.json";
  ASSERT_TRUE(wait_for([&] {
    try {
      const auto p = fieldlines::Project::load(file);
      return std::all_of(p.images.begin(), p.images.end(), [](const auto& e) { return e.detect_ms > 0; });
    } catch (const std::exception&) {
      return false;
    }
  }, 60s)) << log();
  segments_ = fieldlines::Project::load(file).images[0].segments;
  ASSERT_GE(segments_.size(), 4u);

  // A few labels so the panels have something to show.
  hover(0);
  act_and_wait_for_save("key m");
  hover(1);
  act_and_wait_for_save("key b");
  hover(2);
  act_and_wait_for_save("key n");
  hover(3);  // leaves a highlighted segment with its tooltip in the Label screenshot

  const fs::path docs = FIELDLINES_SCREENSHOT_DIR;
  fs::create_directories(docs);
  const char* panels[] = {"Images", "Label", "Thresholds", "Train", "Metrics", "Export"};
  for (int i = 0; i < 6; ++i) {
    if (i == 3) {
      // Train: start a run with Ctrl+T and capture once it has finished.
      ASSERT_EQ(run(x("key ctrl+t")), 0);
      ASSERT_TRUE(wait_for([&] { return read_state(state_)["trained"] == true; }, 120s));
    } else {
      ASSERT_EQ(run(x("key F" + std::to_string(i + 1))), 0);
    }
    ASSERT_TRUE(wait_for([&] { return read_state(state_)["panel"] == panels[i]; }, 10s)) << panels[i];
    std::this_thread::sleep_for(400ms);
    const fs::path shot = screenshot(panels[i]);
    const cv::Mat image = cv::imread(shot.string());
    ASSERT_EQ(image.cols, kWidth);
    std::string name = panels[i];
    name[0] = static_cast<char>(std::tolower(name[0]));
    fs::copy_file(shot, docs / ("studio-" + name + ".png"), fs::copy_options::overwrite_existing);
  }
}
