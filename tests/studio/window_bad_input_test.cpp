// Bad input for the studio binary (docs/bad_input.md, "The studio"). A bad path, a damaged or
// newer project file, an empty folder or a bad option stop before any window opens: a message on
// stderr naming the file, exit 2, the file untouched. A corrupt video is refused with a message.
// A folder of damaged and unusual pictures opens, every failure is reported by name, the good
// pictures are detected and labelled, and the studio quits cleanly.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/data/project.hpp"
#include "fieldlines/synth/synth.hpp"
#include "x_session.hpp"

namespace fs = std::filesystem;
using fieldlines::read_file;
using fieldlines::write_file_atomically;
using namespace std::chrono_literals;

namespace {

class StudioBadInput : public studio_test::StudioUnderX {
 protected:
  struct Outcome {
    int exit_code;
    std::string output;
  };
  // Runs the studio with `args`; `with_display` false leaves DISPLAY unset, so reaching the
  // window would fail with a GLFW message instead of the expected one.
  Outcome run_studio(const std::vector<std::string>& args, bool with_display = false) {
    std::vector<std::string> argv = {studio_test::studio_path().string()};
    argv.insert(argv.end(), args.begin(), args.end());
    const fs::path log = dir() / ("run" + std::to_string(++runs_) + ".log");
    std::vector<std::string> env = {"XDG_CONFIG_HOME=" + (dir() / "config").string(),
                                    "XDG_DATA_HOME=" + (dir() / "data").string(), "LIBGL_ALWAYS_SOFTWARE=1"};
    env.push_back(with_display ? "DISPLAY=" + display_.name : "DISPLAY=");
    studio_test::Child child(argv, env, log);
    EXPECT_TRUE(studio_test::wait_for([&] { return !child.running(); }, 60s)) << "still running: " << args[0];
    return {child.exit_code(), read_file(log)};
  }
  int runs_ = 0;
};

TEST_F(StudioBadInput, MissingPathIsAMessageAndExit2) {
  const auto r = run_studio({(dir() / "nowhere").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("nowhere: no such project file or image folder"), std::string::npos) << r.output;
}

TEST_F(StudioBadInput, MalformedProjectIsNamedAndNeverOverwritten) {
  const fs::path file = dir() / "p.json";
  for (const std::string text : {"{\"format\": \"fieldlines-project\", \"version\": 1, \"images\": [",
                                 "", "[1, 2, 3]", "{\"format\": \"fieldlines-project\", \"version\": 99, \"images\": []}"}) {
    write_file_atomically(file, text);
    const auto r = run_studio({file.string()});
    EXPECT_EQ(r.exit_code, 2) << text;
    EXPECT_NE(r.output.find(file.string() + ": "), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("GLFW"), std::string::npos) << "reached the window: " << r.output;
    EXPECT_EQ(read_file(file), text);
  }
}

TEST_F(StudioBadInput, FolderWithoutImagesAndBadOptionsAreMessages) {
  fs::create_directories(dir() / "empty");
  auto r = run_studio({(dir() / "empty").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("no images"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir() / "empty" / "fieldlines-project.json"));
  r = run_studio({"--every", "0", (dir() / "empty").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--every: expected an integer"), std::string::npos) << r.output;
  r = run_studio({"--last"});  // a private config folder: nothing opened before
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--last: no recent project"), std::string::npos) << r.output;
  r = run_studio({"--frobnicate"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("unknown option --frobnicate"), std::string::npos) << r.output;
  // A camera file that is missing or has no height: named, before any window opens.
  r = run_studio({"--camera", (dir() / "none.json").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("none.json"), std::string::npos) << r.output;
  write_file_atomically(dir() / "camera.json",
                        R"({"format": "fieldlines-camera", "version": 1, "fx": 640, "fy": 640, "cx": 319.5,)"
                        R"( "cy": 239.5, "pitch_deg": 30, "roll_deg": 0})");
  r = run_studio({"--camera", (dir() / "camera.json").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("height_m"), std::string::npos) << r.output;
}

TEST_F(StudioBadInput, CorruptVideoIsRefusedWithAMessage) {
  const fs::path video = dir() / "match.mp4";
  write_file_atomically(video, std::string(4096, 'x'));
  const auto r = run_studio({video.string()}, true);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("match.mp4"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir() / "match-every10")) << "a half-written frames folder was left";
}

// The good case beside the corrupt one: the frames are extracted while the normal main loop
// shows the progress, then the frames folder opens as a project in the same window.
TEST_F(StudioBadInput, VideoBecomesAFramesProjectInTheSameLoop) {
  const fs::path video = dir() / "match.avi";
  {
    cv::VideoWriter writer(video.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25, {320, 240});
    ASSERT_TRUE(writer.isOpened());
    const auto sample = fieldlines::synth::generate(fieldlines::synth::SynthParams{}, 5, 0);
    cv::Mat frame;
    cv::resize(sample.bgr, frame, {320, 240});
    for (int i = 0; i < 25; ++i) writer.write(frame);
  }
  project_ = video;
  auto studio = start_studio();  // returns once the state file exists: a project is open
  ASSERT_TRUE(studio->running()) << log();
  const fs::path folder = dir() / "match-every10";
  for (const char* name : {"frame_000000.png", "frame_000010.png", "frame_000020.png"}) {
    EXPECT_TRUE(fs::exists(folder / name)) << name;
  }
  EXPECT_FALSE(fs::exists(folder / "frame_000001.png"));
  ASSERT_EQ(studio_test::run(x("key ctrl+q")), 0);
  ASSERT_TRUE(studio_test::wait_for([&] { return !studio->running(); }, 15s));
  EXPECT_EQ(studio->exit_code(), 0) << log();
  EXPECT_EQ(fieldlines::Project::load(folder / "fieldlines-project.json").images.size(), 3u);
}

TEST_F(StudioBadInput, DamagedAndUnusualPicturesAreReportedAndTheRestWorks) {
  const fs::path folder = dir() / "pictures";
  fs::create_directories(folder);
  const fieldlines::synth::SynthParams params;
  const auto sample = fieldlines::synth::generate(params, 3, 0);
  cv::imwrite((folder / "a_good.png").string(), sample.bgr);
  cv::Mat grey, deep;
  cv::cvtColor(sample.bgr, grey, cv::COLOR_BGR2GRAY);
  sample.bgr.convertTo(deep, CV_16UC3, 256.0);
  cv::imwrite((folder / "b_grey.png").string(), grey);
  cv::imwrite((folder / "c_deep16.png").string(), deep);
  cv::imwrite((folder / "d_tiny.png").string(), cv::Mat(1, 1, CV_8UC3, cv::Scalar(0, 128, 0)));
  const std::string png = read_file(folder / "a_good.png");
  write_file_atomically(folder / "e_truncated.png", png.substr(0, png.size() / 3));
  write_file_atomically(folder / "f_empty.png", "");
  write_file_atomically(folder / "g_text.jpg", "not a picture");

  project_ = folder;
  auto studio = start_studio();
  ASSERT_TRUE(studio->running()) << log();
  // The summary grows as images finish: read it once the whole detection has ended.
  ASSERT_TRUE(studio_test::wait_for([&] {
    const auto state = studio_test::read_state(state_);
    return state["detection"] != "" && state["detecting"] == false;
  }, 60s)) << log();
  const std::string summary = studio_test::read_state(state_)["detection"];
  EXPECT_NE(summary.find("detected 4 images"), std::string::npos) << summary;
  EXPECT_NE(summary.find("3 failed"), std::string::npos) << summary;

  // The first picture is good: label one of its segments.
  const fs::path file = folder / "fieldlines-project.json";
  segments_ = fieldlines::Project::load(file).images[0].segments;
  ASSERT_FALSE(segments_.empty());
  hover(0);
  act_and_wait_for_save("key m");

  // Walk to the truncated picture (index 4): the view says why it cannot be shown.
  ASSERT_EQ(studio_test::run(x("mousemove 5 5")), 0);
  for (int i = 0; i < 4; ++i) ASSERT_EQ(studio_test::run(x("key Right")), 0);
  ASSERT_TRUE(studio_test::wait_for([&] { return studio_test::read_state(state_)["image"] == 4; }, 10s));
  ASSERT_TRUE(studio_test::wait_for([&] { return studio_test::read_state(state_)["image_error"] != ""; }, 10s));
  const std::string why = studio_test::read_state(state_)["image_error"];
  EXPECT_NE(why.find("e_truncated.png"), std::string::npos) << why;

  ASSERT_EQ(studio_test::run(x("key ctrl+q")), 0);
  ASSERT_TRUE(studio_test::wait_for([&] { return !studio->running(); }, 15s));
  EXPECT_EQ(studio->exit_code(), 0) << log();
  const auto p = fieldlines::Project::load(file);
  ASSERT_EQ(p.images.size(), 7u);
  EXPECT_EQ(p.images[0].segments[0].label, fieldlines::Label::Marking);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_GT(p.images[i].detect_ms, 0) << p.images[i].path;
  for (std::size_t i = 4; i < 7; ++i) EXPECT_EQ(p.images[i].detect_ms, 0) << p.images[i].path;
}

}  // namespace
