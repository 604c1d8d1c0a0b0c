#include "x_session.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <thread>

#include <opencv2/imgcodecs.hpp>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/data/project.hpp"
#include "gui/model/hit_test.hpp"
#include "gui/model/view_transform.hpp"

namespace fs = std::filesystem;
using namespace std::chrono_literals;

namespace studio_test {

fs::path studio_path() { return FIELDLINES_STUDIO_PATH; }
fs::path default_screenshot_dir() { return FIELDLINES_SCREENSHOT_DIR; }

Child::Child(const std::vector<std::string>& argv, const std::vector<std::string>& extra_env, const fs::path& log) {
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

Child::~Child() {
  if (running()) kill(SIGKILL);
  wait();
}

bool Child::running() {
  if (status_) return false;
  int st = 0;
  if (::waitpid(pid_, &st, WNOHANG) == pid_) status_ = st;
  return !status_;
}

void Child::kill(int sig) { ::kill(pid_, sig); }

int Child::wait() {
  if (!status_) {
    int st = 0;
    ::waitpid(pid_, &st, 0);
    status_ = st;
  }
  return *status_;
}

int Child::exit_code() { return !running() && WIFEXITED(*status_) ? WEXITSTATUS(*status_) : -1; }

bool wait_for(const std::function<bool()>& done, std::chrono::milliseconds timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(50ms);
  }
  return done();
}

int run(const std::string& command) { return std::system(command.c_str()); }

nlohmann::json read_state(const fs::path& file) {
  try {
    return nlohmann::json::parse(fieldlines::read_file(file));
  } catch (const std::exception&) {
    return nullptr;
  }
}

long rss_kib(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string key;
  while (status >> key) {
    if (key == "VmRSS:") {
      long kib = -1;
      status >> kib;
      return kib;
    }
    status.ignore(4096, '\n');
  }
  return -1;
}

std::vector<int> rows_of_colour(const fs::path& screenshot, std::array<int, 3> rgb) {
  const cv::Mat shot = cv::imread(screenshot.string());
  std::vector<int> centres;
  int run_start = -1;
  for (int y = 30; y <= shot.rows - 30; ++y) {
    const cv::Vec3b p = shot.at<cv::Vec3b>(y, 878);  // BGR, just inside the side panel
    const bool hit = std::abs(p[2] - rgb[0]) <= 8 && std::abs(p[1] - rgb[1]) <= 8 && std::abs(p[0] - rgb[2]) <= 8;
    if (hit && run_start < 0) run_start = y;
    if (!hit && run_start >= 0) {
      if (y - run_start >= 10) centres.push_back((run_start + y) / 2);
      run_start = -1;
    }
  }
  return centres;
}

Display start_xvfb(const fs::path& log, int width, int height) {
  int fds[2];
  if (::pipe(fds) != 0) return {};
  Display d;
  d.server = std::make_unique<Child>(
      std::vector<std::string>{"/usr/bin/Xvfb", "-displayfd", std::to_string(fds[1]), "-screen", "0",
                               std::to_string(width) + "x" + std::to_string(height) + "x24", "-nolisten", "tcp"},
      std::vector<std::string>{}, log);
  ::close(fds[1]);
  std::string number;
  char c = 0;
  while (::read(fds[0], &c, 1) == 1 && c != '\n') number += c;
  ::close(fds[0]);
  if (!number.empty()) d.name = ":" + number;
  return d;
}

void StudioUnderX::SetUp() {
  ASSERT_TRUE(fs::exists("/usr/bin/Xvfb")) << "install xvfb";
  ASSERT_EQ(run("command -v xdotool >/dev/null && command -v import >/dev/null"), 0)
      << "install xdotool and imagemagick";
  display_ = start_xvfb(dir_.path() / "xvfb.log", kWidth, kHeight);
  ASSERT_FALSE(display_.name.empty()) << "no free X display";
}

void StudioUnderX::use_project(int images, int segments) {
  project_ = write_project(dir(), images, segments, 640, 480);
  segments_ = fieldlines::Project::load(project_).images[0].segments;
}

std::unique_ptr<Child> StudioUnderX::start_studio() {
  fs::remove(state_);
  auto child = std::make_unique<Child>(
      std::vector<std::string>{studio_path().string(), project_.string(), "--window-size",
                               std::to_string(kWidth) + "x" + std::to_string(kHeight), "--state-file", state_.string()},
      // A private config and data folder: recent projects and the demo never touch the user's.
      std::vector<std::string>{"DISPLAY=" + display_.name, "XDG_CONFIG_HOME=" + (dir_.path() / "config").string(),
                               "XDG_DATA_HOME=" + (dir_.path() / "data").string(), "LIBGL_ALWAYS_SOFTWARE=1"},
      dir_.path() / "studio.log");
  EXPECT_TRUE(wait_for([&] { return !read_state(state_).is_null(); }, 30s)) << log();
  return child;
}

std::string StudioUnderX::log() const {
  try {
    return fieldlines::read_file(dir_.path() / "studio.log");
  } catch (const std::exception&) {
    return "";
  }
}

std::string StudioUnderX::x(const std::string& args) const { return "DISPLAY=" + display_.name + " xdotool " + args; }

std::pair<int, int> StudioUnderX::on_screen(std::size_t i) const {
  const nlohmann::json st = read_state(state_);
  fieldlines::studio::ViewTransform view;
  view.set(st["scale"].get<float>(), {st["offset"][0].get<float>(), st["offset"][1].get<float>()});
  const auto s = fieldlines::studio::to_screen(segments_[i], view);
  return {static_cast<int>(std::lround((s.a.x + s.b.x) / 2)), static_cast<int>(std::lround((s.a.y + s.b.y) / 2))};
}

void StudioUnderX::hover(std::size_t i) {
  const auto [px, py] = on_screen(i);
  ASSERT_EQ(run(x("mousemove " + std::to_string(px) + " " + std::to_string(py))), 0);
  ASSERT_TRUE(wait_for([&] { return read_state(state_)["hovered"] == static_cast<long>(i); }, 10s))
      << "segment " << i << " not hovered at " << px << "," << py << ": " << read_state(state_).dump();
}

void StudioUnderX::act_and_wait_for_save(const std::string& xdotool_args) {
  const auto before = read_state(state_)["save_count"].get<int>();
  ASSERT_EQ(run(x(xdotool_args)), 0);
  ASSERT_TRUE(wait_for([&] { return read_state(state_)["save_count"].get<int>() > before; }, 10s))
      << xdotool_args << ": no save";
}

fs::path StudioUnderX::screenshot(const std::string& name) const {
  const fs::path out = dir_.path() / (name + ".png");
  EXPECT_EQ(run("DISPLAY=" + display_.name + " import -window root " + out.string()), 0);
  return out;
}

}  // namespace studio_test
