#include "app/cli/video_stream.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include <opencv2/videoio.hpp>

#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/steady_features.hpp"
#include "fieldlines/data/overlay.hpp"
#include "fieldlines/data/video_io.hpp"

namespace fieldlines::cli {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

cv::VideoCapture open_source(const std::string& source) {
  cv::VideoCapture capture;
  // /dev/videoN is a camera index for V4L2; anything else is a file or stream URL.
  constexpr std::string_view camera_prefix = "/dev/video";
  if (source.rfind(camera_prefix, 0) == 0 && source.size() > camera_prefix.size() &&
      source.find_first_not_of("0123456789", camera_prefix.size()) == std::string::npos) {
    capture.open(std::stoi(source.substr(camera_prefix.size())), cv::CAP_V4L2);
  } else {
    std::error_code ec;
    if (source.find("://") == std::string::npos && !std::filesystem::is_regular_file(source, ec))
      throw Error("--video " + source + ": no such file");
    open_video_file(capture, source);
  }
  if (!capture.isOpened()) throw Error("--video " + source + ": cannot open (missing file, not a video, or no such camera)");
  return capture;
}

}  // namespace

int run_video_detection(const VideoOptions& options, const ThresholdsFile& config) {
  cv::VideoCapture capture = open_source(options.source);
  LineDetector detector(config.detector, config.thresholds);
  detector.set_camera(options.camera);
  cv::VideoWriter writer;
  std::vector<Segment> segments;
  std::vector<double> latencies;  // grab + decode + detect (+ draw), per frame
  long frames = 0, markings = 0, boundaries = 0;
  // --steady: frames where a circle (or any junction) was seen, and where the steady features
  // have one; a localiser sees the second.
  std::optional<SteadyFeatures> steady;
  if (options.steady_ms) steady.emplace(SteadyParams{.hold_ms = *options.steady_ms});
  long circle_seen = 0, circle_steady = 0, junctions_seen = 0, junctions_steady = 0;
  cv::Mat frame;
  const auto start = Clock::now();
  auto last_report = start;

  while (options.max_frames < 0 || frames < options.max_frames) {
    const auto t0 = Clock::now();
    if (!capture.read(frame) || frame.empty()) break;
    detector.detect(frame, segments);
    if (steady) {
      // The stream's own clock where it has one; else the frame's place at the nominal rate.
      const double position_ms = capture.get(cv::CAP_PROP_POS_MSEC), fps = capture.get(cv::CAP_PROP_FPS);
      const double t = position_ms > 0 ? position_ms : frames * 1000.0 / (fps > 0 ? fps : 30);
      const GroundFeatures& seen = detector.ground_features();
      const GroundFeatures& held = steady->update(seen, t);
      circle_seen += !seen.ellipses.empty(), circle_steady += !held.ellipses.empty();
      junctions_seen += !seen.intersections.empty(), junctions_steady += !held.intersections.empty();
    }
    if (options.overlay_out) {
      const cv::Mat drawn = draw_overlay(frame, segments);
      if (!writer.isOpened()) {
        const double fps = capture.get(cv::CAP_PROP_FPS);
        writer.open(options.overlay_out->string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), fps > 0 ? fps : 30,
                    drawn.size());
        if (!writer.isOpened())
          throw Error("--video-out " + options.overlay_out->string() + ": cannot write a video there");
      }
      writer.write(drawn);
    }
    latencies.push_back(ms_since(t0));
    for (const Segment& s : segments) {
      markings += s.label == Label::Marking;
      boundaries += s.label == Label::Boundary;
    }
    ++frames;
    if (!options.quiet && std::chrono::duration<double>(Clock::now() - last_report).count() >= 0.5) {
      last_report = Clock::now();
      std::fprintf(stderr, "\rvideo: %ld frames, %.1f fps, latency %.2f ms (p90 %.2f)   ", frames,
                   frames * 1000.0 / ms_since(start), percentile(latencies, 0.5), percentile(latencies, 0.9));
      std::fflush(stderr);
    }
  }
  if (!options.quiet && frames > 0) std::fputc('\n', stderr);
  if (frames == 0) throw Error("--video " + options.source + ": no frame could be read");

  const double seconds = ms_since(start) / 1000.0;
  std::printf("%ld frames in %.2f s: %.1f fps, latency median %.2f ms, p90 %.2f ms; %ld marking and %ld boundary segments\n",
              frames, seconds, frames / seconds, percentile(latencies, 0.5), percentile(latencies, 0.9), markings,
              boundaries);
  if (steady)
    std::printf("steady (%.0f ms): a centre circle in %ld frames as seen, %ld held; a junction in %ld as seen, %ld held\n",
                *options.steady_ms, circle_seen, circle_steady, junctions_seen, junctions_steady);
  if (options.overlay_out) std::printf("overlay video written to %s\n", options.overlay_out->string().c_str());
  return 0;
}

}  // namespace fieldlines::cli
