// `fieldlines detect --video`: streams from a file, live readout, overlay video, clear errors.
#include <gtest/gtest.h>
#include <opencv2/videoio.hpp>

#include <fstream>

#include "cli_test_support.hpp"
#include "fieldlines/detect/camera_file.hpp"
#include "painted_field.hpp"

namespace fieldlines::test {
namespace {

class CliVideo : public TempDirTest {
 protected:
  std::filesystem::path write_video(int frames) {
    const auto path = dir_ / "match.avi";
    cv::VideoWriter writer(path.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 30, {640, 480});
    EXPECT_TRUE(writer.isOpened());
    for (int i = 0; i < frames; ++i) writer.write(synthetic_field(640, 480, i % 20));
    return path;
  }
};

TEST_F(CliVideo, ProcessesEveryFrameAndWritesTheOverlayVideo) {
  const auto video = write_video(24);
  const auto out = dir_ / "lines.avi";
  const CliRun r = run_cli({"detect", "--video", video.string(), "--video-out", out.string()}, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("24 frames"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fps"), std::string::npos);
  EXPECT_EQ(r.out.find(" 0 marking"), std::string::npos) << "the painted lines must be found: " << r.out;
  cv::VideoCapture written(out.string());
  ASSERT_TRUE(written.isOpened());
  int frames = 0;
  for (cv::Mat f; written.read(f);) ++frames;
  EXPECT_EQ(frames, 24);
}

TEST_F(CliVideo, StopsAfterMaxFrames) {
  const auto video = write_video(30);
  const CliRun r = run_cli({"detect", "--video", video.string(), "--max-frames", "7", "--quiet"}, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("7 frames"), std::string::npos) << r.out;
}

TEST_F(CliVideo, MissingOrCorruptSourceIsAClearError) {
  CliRun r = run_cli({"detect", "--video", (dir_ / "absent.avi").string()}, dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no such file"), std::string::npos) << r.err;
  std::ofstream(dir_ / "junk.avi") << "this is not a video";
  r = run_cli({"detect", "--video", (dir_ / "junk.avi").string()}, dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("junk.avi"), std::string::npos) << r.err;
}

TEST_F(CliVideo, VideoOptionsDoNotMixWithImageOptions) {
  const auto video = write_video(2);
  CliRun r = run_cli({"detect", "--video", video.string(), "--json", (dir_ / "x.json").string()}, dir_);
  EXPECT_EQ(r.exit_code, 2);
  r = run_cli({"detect", "--max-frames", "3", video.string()}, dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("go with --video"), std::string::npos) << r.err;
}

// --steady: a circle the detector misses on one frame in three (the painted arc gone from those
// frames) is held on the ground over the gap; without a camera the option is refused.
TEST_F(CliVideo, SteadyHoldsTheCircleOverFramesThatMissIt) {
  const GroundCamera camera = ground_camera(30);
  cv::Mat arc = painted_ground_circle(camera, {0.8, 0}, 0.75, 7);
  cv::Mat noise(arc.size(), CV_8UC3);
  cv::randu(noise, 0, 8);
  arc += noise;
  cv::Mat turf(arc.size(), CV_8UC3, arc.at<cv::Vec3b>(arc.rows - 1, 0));
  const auto video = dir_ / "arc.avi";
  {
    cv::VideoWriter writer(video.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 30, arc.size());
    ASSERT_TRUE(writer.isOpened());
    for (int i = 0; i < 12; ++i) writer.write(i % 3 == 2 ? turf : arc);
  }
  const auto camera_file = dir_ / "camera.json";
  std::ofstream(camera_file) << to_json(camera).dump();
  const CliRun r = run_cli({"detect", "--video", video.string(), "--features", "--camera", camera_file.string(),
                            "--steady", "80", "--quiet"},
                           dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("a centre circle in 8 frames as seen, 12 held"), std::string::npos) << r.out;
  const CliRun refused = run_cli({"detect", "--video", video.string(), "--steady", "80"}, dir_);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("--steady needs"), std::string::npos) << refused.err;
}

}  // namespace
}  // namespace fieldlines::test
