// `fieldlines detect --video`: streams from a file, live readout, overlay video, clear errors.
#include <gtest/gtest.h>
#include <opencv2/videoio.hpp>

#include "cli_test_support.hpp"

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

}  // namespace
}  // namespace fieldlines::test
