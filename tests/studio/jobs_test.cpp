// Background jobs without a window: training start/progress/cancel/finish/apply and detection,
// always handed over through poll() on the calling ("UI") thread.
// Long (~500 lines) because the job type and the jobs built on it (training, detection, video
// frames) share one poll-until-done harness, and their start/cancel/failure cases read best
// side by side.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include "fieldlines/train/detector_calibration.hpp"
#include "fixtures.hpp"
#include "tests/painted_field.hpp"
#include "gui/model/figures.hpp"
#include "gui/model/job.hpp"
#include "gui/model/open_project.hpp"
#include "gui/model/project_detection.hpp"
#include "gui/model/message_queue.hpp"
#include "gui/model/studio_controller.hpp"
#include "gui/model/studio_files.hpp"
#include "gui/model/training_job.hpp"
#include "gui/model/video_frames.hpp"

namespace fs = fieldlines::studio;
using fieldlines::Label;
using namespace std::chrono_literals;

namespace {

// A labelled session: every grid segment labelled with what the default thresholds predict,
// except that odd images' markings are labelled "none" so training has something to fix.
struct Labelled {
  Labelled() : dir("jobs"), file(studio_test::write_project(dir.path(), 6, 12)) {
    fieldlines::Project p = fieldlines::Project::load(file);
    for (std::size_t img = 0; img < p.images.size(); ++img) {
      auto& segs = p.images[img].segments;
      for (std::size_t i = 0; i < segs.size(); ++i) {
        segs[i].label = i % 2 ? Label::Boundary : Label::Marking;
        segs[i].saliency = static_cast<float>(100 + 20 * i);  // lengths spread over 100..320
      }
    }
    p.save(file);
  }
  studio_test::TempDir dir;
  std::filesystem::path file;
};

fieldlines::TrainParams small_training(int iterations) {
  fieldlines::TrainParams p;
  p.target = fieldlines::TrainClass::Marking;
  p.pso.particles = 12;
  p.pso.iterations = iterations;
  p.polish = false;
  return p;
}

}  // namespace

TEST(MessageQueue, DeliversEverythingFromManyThreadsOnce) {
  fs::MessageQueue<int> q;
  std::vector<std::thread> workers;
  for (int t = 0; t < 4; ++t) {
    workers.emplace_back([&q, t] {
      for (int i = 0; i < 1000; ++i) q.push(t * 1000 + i);
    });
  }
  std::vector<int> got;
  while (got.size() < 4000) {
    for (int v : q.drain()) got.push_back(v);
  }
  for (auto& w : workers) w.join();
  EXPECT_TRUE(q.drain().empty());
  std::sort(got.begin(), got.end());
  for (int i = 0; i < 4000; ++i) ASSERT_EQ(got[static_cast<std::size_t>(i)], i);
}

// Polls like the UI thread until the job has ended; returns every progress message, in order.
template <typename Job>
auto poll_to_the_end(Job& job) {
  decltype(job.poll()) all;
  const auto end = std::chrono::steady_clock::now() + 30s;
  while (job.running() && std::chrono::steady_clock::now() < end) {
    for (auto& p : job.poll()) all.push_back(std::move(p));
    std::this_thread::sleep_for(1ms);
  }
  return all;
}

TEST(Job, ReportsProgressInOrderThenExactlyOneResult) {
  fs::Job<int, std::string> job;
  EXPECT_FALSE(job.running());
  job.start([](std::stop_token, const auto& report) {
    for (int i = 1; i <= 100; ++i) report(i);
    return std::string("done");
  });
  EXPECT_TRUE(job.running());
  const std::vector<int> progress = poll_to_the_end(job);
  ASSERT_FALSE(job.running());
  ASSERT_EQ(progress.size(), 100u);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(progress[static_cast<std::size_t>(i)], i + 1);
  ASSERT_TRUE(job.outcome().has_value());
  ASSERT_TRUE(job.outcome()->ok());
  EXPECT_EQ(job.outcome()->value(), "done");
  EXPECT_TRUE(job.poll().empty());
}

TEST(Job, WhatTheWorkThrowsIsTheError) {
  fs::Job<int, int> job;
  job.start([](std::stop_token, const auto& report) -> int {
    report(1);
    throw fieldlines::Error("cannot start: bad parameter");
  });
  job.wait();
  EXPECT_EQ(job.poll(), std::vector<int>{1});
  ASSERT_TRUE(job.outcome().has_value());
  EXPECT_FALSE(job.outcome()->ok());
  EXPECT_EQ(job.outcome()->error(), "cannot start: bad parameter");
}

TEST(Job, StartStopsAndJoinsTheRunningWorkAndDropsItsMessages) {
  fs::Job<int, int> job;
  std::atomic<bool> first_ended{false};
  job.start([&](std::stop_token stop, const auto& report) {
    while (!stop.stop_requested()) report(-1);
    first_ended = true;
    return -1;
  });
  std::this_thread::sleep_for(5ms);
  job.start([](std::stop_token, const auto& report) {
    report(42);
    return 7;
  });
  EXPECT_TRUE(first_ended);  // stopped and joined before the second began
  const std::vector<int> progress = poll_to_the_end(job);
  EXPECT_EQ(progress, std::vector<int>{42});
  ASSERT_TRUE(job.outcome()->ok());
  EXPECT_EQ(job.outcome()->value(), 7);
}

TEST(Job, DestroyingARunningJobStopsAndJoinsIt) {
  std::atomic<bool> ended{false};
  {
    fs::Job<int, int> job;
    job.start([&](std::stop_token stop, const auto&) {
      while (!stop.stop_requested()) std::this_thread::sleep_for(1ms);
      ended = true;
      return 0;
    });
  }
  EXPECT_TRUE(ended);
}

TEST(TrainingJob, RunsToTheEndAndReportsEveryIteration) {
  Labelled data;
  fs::StudioController c(fieldlines::Project::load(data.file), data.file);
  auto t = c.thresholds();
  t.marking.thresholds.min_length = 300;  // misses most markings: training must lower it
  c.set_thresholds(t);
  const long missed = c.train_counts().marking.fn;
  ASSERT_GT(missed, 0);

  c.start_training(small_training(15));
  EXPECT_TRUE(c.training().running());
  c.training().wait();
  ASSERT_FALSE(c.training().running());
  const auto& outcome = c.training().outcome();
  ASSERT_TRUE(outcome.has_value());
  ASSERT_TRUE(outcome->ok()) << outcome->error();
  EXPECT_FALSE(outcome->value().run.cancelled);
  EXPECT_EQ(outcome->value().run.iterations_run, 15);
  EXPECT_EQ(c.training().best_scores().size(), 15u);
  for (std::size_t i = 1; i < c.training().best_scores().size(); ++i) {
    EXPECT_GE(c.training().best_scores()[i], c.training().best_scores()[i - 1]);  // global best never drops
  }
  ASSERT_TRUE(c.training().latest().has_value());
  EXPECT_EQ(c.training().latest()->particles.size(), 12u);
  // The test split (2 of the 6 labelled images) is counted apart from the train split.
  EXPECT_GT(outcome->value().test_counts.marking.tp + outcome->value().test_counts.marking.fn, 0);

  ASSERT_TRUE(c.apply_training_result());
  EXPECT_EQ(c.thresholds(), outcome->value().run.thresholds);
  // Applying is saved at once (no poll, no pause): a crash right after loses nothing.
  EXPECT_FALSE(c.has_unsaved_settings());
  EXPECT_EQ(fieldlines::Project::load(data.file).thresholds, outcome->value().run.thresholds);
  EXPECT_LT(c.train_counts().marking.fn, missed);  // live metrics follow the applied thresholds
  // Apply's confirmation names the applied figures on the test split, n/a where a class has none.
  const fieldlines::Counts& test = c.test_counts();
  EXPECT_EQ(fs::applied_summary(test, "test"),
            "applied: marking P " + fs::format_figure(test.marking, test.marking.precision()) + " R " +
                fs::format_figure(test.marking, test.marking.recall()) + " | boundary P " +
                fs::format_figure(test.boundary, test.boundary.precision()) + " R " +
                fs::format_figure(test.boundary, test.boundary.recall()) + " on the test split");
  EXPECT_EQ(fs::applied_summary(fieldlines::Counts{}, "test"),
            "applied: marking P n/a R n/a | boundary P n/a R n/a on the test split");
}

// The progress line ends on the polish, with the score the result shows ("best 82" beside
// "score 84" was the complaint); the curve keeps one point per PSO iteration.
TEST(TrainingJob, ThePolishIsTheLastSnapshotWithTheResultsScore) {
  Labelled data;
  fs::StudioController c(fieldlines::Project::load(data.file), data.file);
  auto t = c.thresholds();
  t.marking.thresholds.min_length = 300;
  c.set_thresholds(t);
  auto params = small_training(2);
  params.polish = true;
  c.start_training(params);
  c.training().wait();
  const auto& outcome = c.training().outcome();
  ASSERT_TRUE(outcome.has_value() && outcome->ok());
  const fieldlines::TrainResult& run = outcome->value().run;
  EXPECT_EQ(c.training().best_scores().size(), 2u);
  ASSERT_TRUE(c.training().latest().has_value());
  const fs::TrainingSnapshot& last = *c.training().latest();
  EXPECT_EQ(last.phase, fieldlines::TrainingPhase::Polish);
  EXPECT_EQ(last.best_score, run.score);
  EXPECT_EQ(last.best, run.thresholds);
  EXPECT_EQ(last.pso_best_score, c.training().best_scores().back());
  EXPECT_EQ(last.eta_s, 0);
  EXPECT_FALSE(last.particles.empty());
  char score[32];
  std::snprintf(score, sizeof score, "%.3f", run.score);
  const std::string line = fs::progress_line(last);
  EXPECT_EQ(line.rfind("polish: best " + std::string(score), 0), 0u) << line;

  // Without the polish the line stays on the swarm.
  c.start_training(small_training(2));
  c.training().wait();
  ASSERT_TRUE(c.training().latest().has_value());
  EXPECT_EQ(c.training().latest()->phase, fieldlines::TrainingPhase::Pso);
  EXPECT_EQ(fs::progress_line(*c.training().latest()).rfind("PSO 2/2: best ", 0), 0u);
}

TEST(TrainingJob, CancelStopsEarlyWithTheBestSoFar) {
  Labelled data;
  fs::StudioController c(fieldlines::Project::load(data.file), data.file);
  c.start_training(small_training(1'000'000));
  // Wait for the first progress message through the UI-thread poll, then cancel.
  const auto end = std::chrono::steady_clock::now() + 30s;
  while (!c.training().latest() && std::chrono::steady_clock::now() < end) {
    c.poll();
    std::this_thread::sleep_for(5ms);
  }
  ASSERT_TRUE(c.training().latest().has_value());
  c.cancel_training();
  c.training().wait();
  const auto& outcome = c.training().outcome();
  ASSERT_TRUE(outcome.has_value());
  ASSERT_TRUE(outcome->ok()) << outcome->error();
  EXPECT_TRUE(outcome->value().run.cancelled);  // a stop is a result (the best so far), not an error
  EXPECT_LT(outcome->value().run.iterations_run, 1'000'000);
  EXPECT_GE(outcome->value().run.iterations_run, 1);
}

TEST(TrainingJob, NothingLabelledIsAnErrorNotACrash) {
  studio_test::TempDir dir("nolabels");
  const auto file = studio_test::write_project(dir.path(), 2, 4);
  fs::StudioController c(fieldlines::Project::load(file), file);
  c.start_training(small_training(5));
  c.training().wait();
  ASSERT_TRUE(c.training().outcome().has_value());
  EXPECT_FALSE(c.training().outcome()->ok());
  EXPECT_FALSE(c.training().outcome()->error().empty());
  EXPECT_FALSE(c.apply_training_result());
}

// The Train tab trains and counts what the robot's detector lets each segment be: nones its
// stripes check drops are neither false positives nor a reason to shrink the box.
TEST(TrainingJob, TrainsAndCountsThroughTheDetectorsGates) {
  std::vector<fieldlines::Segment> segs;
  fs::ProposalGate gate;
  fieldlines::Segment s;
  s.grad_y = {-100, -60, -100};  // a marking's colours
  for (int i = 0; i < 19; ++i) {
    s.saliency = i < 10 ? 200 : 30;
    s.label = i < 15 ? Label::Marking : Label::None;
    segs.push_back(s);
    gate.may_mark.push_back(i < 15);
    gate.may_bound.push_back(1);
  }
  fieldlines::TrainParams p = small_training(10);
  p.objective = fieldlines::parse_objective("tp-fp:1.5");
  p.polish = true;
  p.marking_bounds.length = {10, 300};  // the cluster is shorter than the paper's box allows
  fs::TrainingJob job;
  job.start(segs, segs, {}, p, gate, gate);
  job.wait();
  ASSERT_TRUE(job.outcome().has_value());
  ASSERT_TRUE(job.outcome()->ok()) << job.outcome()->error();
  const fs::TrainingResult& r = job.outcome()->value();
  EXPECT_LE(r.run.thresholds.marking.thresholds.min_length, 30);
  EXPECT_EQ(r.train_counts.marking.tp, 15);
  EXPECT_EQ(r.train_counts.marking.fp, 0);
  EXPECT_EQ(r.test_counts, r.train_counts);
  job.start(segs, segs, {}, p);  // ungated: the four nones cost the cluster
  job.wait();
  ASSERT_TRUE(job.outcome()->ok());
  EXPECT_GT(job.outcome()->value().run.thresholds.marking.thresholds.min_length, 30);
}

TEST(TrainingJob, RestartReplacesARunningJob) {
  Labelled data;
  fs::StudioController c(fieldlines::Project::load(data.file), data.file);
  c.start_training(small_training(1'000'000));
  c.start_training(small_training(4));  // cancels and joins the first
  c.training().wait();
  ASSERT_TRUE(c.training().outcome().has_value());
  ASSERT_TRUE(c.training().outcome()->ok());
  EXPECT_EQ(c.training().outcome()->value().run.iterations_run, 4);
  EXPECT_EQ(c.training().best_scores().size(), 4u);
}

TEST(DetectionJob, DetectsAFolderProjectInTheBackgroundAndKeepsLabels) {
  studio_test::TempDir dir("detect");
  // Three pictures with long white lines on green; the project has no segments yet.
  fieldlines::Project p;
  for (int i = 0; i < 3; ++i) {
    fieldlines::Segment a, b;
    a.x0 = 30, a.y0 = 60.0f + 40 * i, a.x1 = 600, a.y1 = 80.0f + 40 * i;
    b.x0 = 320, b.y0 = 20, b.x1 = 330, b.y1 = 460;
    std::string name = "f";  // built piecewise: GCC 12 warns falsely (-Wrestrict) on "f" + to_string
    name += std::to_string(i);
    name += ".png";
    cv::imwrite((dir.path() / name).string(), studio_test::field_image(640, 480, {a, b}));
    p.images.push_back({name, {}, 0});
  }
  const auto file = dir.path() / "p.json";
  p.save(file);
  fs::StudioController c(fieldlines::Project::load(file), file);
  EXPECT_TRUE(c.needs_detection(0));
  c.detect_all(true);
  EXPECT_EQ(c.detection().total(), 3u);
  const auto end = std::chrono::steady_clock::now() + 60s;
  while (c.detection().running() && std::chrono::steady_clock::now() < end) {
    c.poll();
    std::this_thread::sleep_for(5ms);
  }
  ASSERT_FALSE(c.detection().running());
  EXPECT_EQ(c.detection().done(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_FALSE(c.needs_detection(i)) << i;
    EXPECT_GE(c.project().images[i].segments.size(), 2u) << i;  // both edges of each line at least
    EXPECT_GT(c.project().images[i].detect_ms, 0) << i;
  }
  EXPECT_GT(c.mean_detect_ms(), 0);
  EXPECT_EQ(c.current_detect_ms(), c.project().images[0].detect_ms);
  EXPECT_EQ(fieldlines::Project::load(file).images[2].segments.size(), c.project().images[2].segments.size());

  // Label one segment, re-detect everything: the label follows the same line.
  const std::size_t first[] = {0};
  ASSERT_TRUE(c.label(first, Label::Marking));
  const auto labelled = c.segments()[0];
  c.detect_all(false);
  c.detection().wait();
  c.poll();
  std::size_t marked = 0;
  for (const auto& s : c.project().images[0].segments) {
    if (s.label == Label::Marking && std::abs(s.y0 - labelled.y0) < 3) ++marked;
  }
  EXPECT_GE(marked, 1u);
  EXPECT_FALSE(c.can_undo());  // segment indices changed: history cleared
  EXPECT_EQ(c.detection_report().detected, 3u);
  EXPECT_EQ(c.detection_report().labels_kept, 1u);
  EXPECT_EQ(c.detection_report().labels_lost, 0u);
  EXPECT_EQ(c.detection_report().summary(), "detected 3 images; 1 labels kept");
}

// The robot's camera (the studio's --camera) reaches the detections: an arc of a circle close
// by, which only the fit on the turf finds (ground_circle_test), is the image's ellipse with it
// and none without.
TEST(DetectionJob, TheRobotsCameraFitsTheCircleOnTheTurf) {
  studio_test::TempDir dir("detect-camera");
  const fieldlines::GroundCamera camera = fieldlines::test::ground_camera(30, 2);
  cv::imwrite((dir.path() / "arc.png").string(),
              fieldlines::test::noisy(fieldlines::test::painted_ground_circle(camera, {0.8, 0.05}, 0.75, 7)));
  fieldlines::Project p;
  p.images.push_back({"arc.png", {}, 0});
  const auto file = dir.path() / "p.json";
  p.save(file);
  for (const bool known : {false, true}) {
    SCOPED_TRACE(known);
    fs::ControllerOptions options;
    if (known) options.camera = camera;
    fs::StudioController c(fieldlines::Project::load(file), file, options);
    c.detect_all(false);  // the first round's autosave has detected it already
    c.detection().wait();
    c.poll();
    ASSERT_EQ(c.detection().done(), 1u);
    EXPECT_EQ(c.field_features().ellipses.size(), known ? 1u : 0u);
  }
}

// A folder's new project has its detector chosen from its frames at its first detection, as
// `fieldlines calibrate` chooses it (the built-in one draws a half to three quarters of a real
// field's lines); the project keeps it, and the exported file runs it. A project once detected,
// or with a detector of its own, keeps its detector.
TEST(DetectionJob, AFolderProjectsFirstDetectionChoosesTheDetectorFromItsFrames) {
  studio_test::TempDir dir("detect-choose");
  const std::filesystem::path frames = dir.path() / "frames";
  std::filesystem::create_directories(frames);
  std::vector<cv::Mat> images;
  for (int i = 0; i < 3; ++i) {
    fieldlines::Segment line;
    line.x0 = 20, line.y0 = 100.0f + 30 * i, line.x1 = 600, line.y1 = 140.0f + 30 * i;
    images.push_back(fieldlines::test::noisy(studio_test::field_image(640, 480, {line})));
    cv::imwrite((frames / ("f" + std::to_string(i) + ".png")).string(), images.back());
  }
  fs::OpenedProject opened = fs::open_project(frames);
  ASSERT_TRUE(fs::chooses_detector(opened.project));
  fs::StudioController c(std::move(opened.project), opened.file);
  c.detect_all(true);
  c.detection().wait();
  c.poll();
  const fieldlines::DetectorCalibrationParams rule;
  fieldlines::FieldContrast contrast(rule, fs::folder_detector());
  for (const cv::Mat& image : images) contrast.add_image(image);
  const fieldlines::DetectorParams chosen = fieldlines::calibrated_detector(fs::folder_detector(), contrast, rule);
  ASSERT_FALSE(chosen == fs::folder_detector());
  EXPECT_TRUE(c.project().detector == chosen);
  EXPECT_TRUE(fieldlines::Project::load(opened.file).detector == chosen) << "saved with the project";
  EXPECT_NE(c.detection_report().summary().find("with the detector chosen from them"), std::string::npos)
      << c.detection_report().summary();
  EXPECT_EQ(c.detection().measured(), 3u);
  // The choice is recorded as `fieldlines calibrate` records it, saved with the project and
  // written into the exported file's provenance: whoever reads the robot's file later sees why
  // its detector is what it is.
  const nlohmann::json record = fieldlines::detector_provenance(contrast, chosen);
  EXPECT_EQ(c.project().detector_choice, record) << c.project().detector_choice.dump();
  EXPECT_EQ(fieldlines::Project::load(opened.file).detector_choice, record);
  const std::filesystem::path exported = dir.path() / "robot.json";
  fs::export_thresholds(c, exported);
  EXPECT_EQ(fieldlines::load_thresholds_file(exported).provenance["detector"], record);

  // Detected once: detected again with the same detector, whatever it is.
  EXPECT_FALSE(fs::chooses_detector(c.project()));
  fieldlines::DetectorParams own = c.project().detector;
  own.min_line_length = 30;
  c.set_detector_params(own);
  EXPECT_TRUE(c.project().detector_choice.is_null()) << "set by hand: no longer what the frames chose";
  fs::export_thresholds(c, exported);
  EXPECT_FALSE(fieldlines::load_thresholds_file(exported).provenance.contains("detector"));
  c.detect_all(false);
  c.detection().wait();
  c.poll();
  EXPECT_TRUE(c.project().detector == own);
  EXPECT_EQ(c.detection().bar_text(), "detecting 3/3");
  // The Thresholds tab's "Choose from the frames": chosen again from the current detector, every
  // image detected again, the labels following by geometry.
  const std::size_t first[] = {0};
  ASSERT_TRUE(c.label(first, Label::Marking));
  c.choose_detector_from_frames();
  c.detection().wait();
  c.poll();
  fieldlines::FieldContrast again(rule, own);
  for (const cv::Mat& image : images) again.add_image(image);
  EXPECT_TRUE(c.project().detector == fieldlines::calibrated_detector(own, again, rule));
  EXPECT_EQ(c.project().detector_choice["frames_with_field"], 3) << "recorded again";
  EXPECT_EQ(c.detection_report().labels_kept, 1u);
  EXPECT_EQ(c.detection().measured(), 3u);
  // A folder project whose detector was set before its first detection keeps it too.
  fieldlines::Project fresh = fs::project_for_folder(frames, opened.file);
  fresh.detector.gaussian_kernel = 3;
  EXPECT_FALSE(fs::chooses_detector(fresh));
}

TEST(DetectionJob, CorruptImageIsReportedByNameAndTheOthersAreDetected) {
  studio_test::TempDir dir("detect-bad");
  fieldlines::Project p;
  fieldlines::Segment line;  // tilted: exactly horizontal edges between anchor rows are never drawn
  line.x0 = 20, line.y0 = 100, line.x1 = 300, line.y1 = 130;
  cv::imwrite((dir.path() / "good.png").string(), studio_test::field_image(320, 240, {line}));
  fieldlines::write_file_atomically(dir.path() / "bad.png", "\x89PNG\r\n\x1a\n truncated");
  p.images.push_back({"good.png", {}, 0});
  p.images.push_back({"bad.png", {}, 0});
  const auto file = dir.path() / "p.json";
  p.save(file);
  fs::StudioController c(fieldlines::Project::load(file), file);
  c.detect_all(true);
  c.detection().wait();
  c.poll();
  EXPECT_EQ(c.detection_report().detected, 1u);
  ASSERT_EQ(c.detection_report().failed.size(), 1u);
  EXPECT_EQ(c.detection_report().failed[0].first, 1u);
  EXPECT_NE(c.detection_error(1).find("bad.png"), std::string::npos) << c.detection_error(1);
  EXPECT_TRUE(c.detection_error(0).empty());
  EXPECT_NE(c.detection_report().summary().find("1 failed: "), std::string::npos) << c.detection_report().summary();
  EXPECT_GT(c.project().images[0].segments.size(), 0u);
  EXPECT_TRUE(c.needs_detection(1));  // still undetected: "Detect new images" tries it again
}

TEST(DetectionJob, BadParametersFailTheJobNotAnImage) {
  studio_test::TempDir dir("detect-params");
  const auto file = studio_test::write_project(dir.path(), 2, 2);
  fs::StudioController c(fieldlines::Project::load(file), file);
  auto params = c.detector_params();
  params.scan_interval = 0;  // rejected by LineDetector
  c.set_detector_params(params);
  c.detect_all(false);
  c.detection().wait();
  c.poll();
  EXPECT_FALSE(c.detection().running());
  ASSERT_TRUE(c.detection().outcome().has_value());
  EXPECT_FALSE(c.detection().outcome()->ok());
  EXPECT_TRUE(c.detection_report().failed.empty());  // no image is blamed
  EXPECT_EQ(c.detection_report().detected, 0u);
  EXPECT_NE(c.detection_report().summary().find("detection could not start: detector parameter scan_interval"),
            std::string::npos)
      << c.detection_report().summary();
  EXPECT_EQ(c.project().images[0].segments.size(), 2u);  // the old segments stay
}

TEST(VideoFramesJob, KeepsEveryNthFrameAsPng) {
  studio_test::TempDir dir("video");
  const auto video = dir.path() / "match.avi";
  {
    cv::VideoWriter writer(video.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25, {160, 120});
    ASSERT_TRUE(writer.isOpened());
    for (int i = 0; i < 25; ++i) {
      fieldlines::Segment s;
      s.x0 = 10, s.y0 = static_cast<float>(10 + 4 * i), s.x1 = 150, s.y1 = s.y0;
      writer.write(studio_test::field_image(160, 120, {s}));
    }
  }
  EXPECT_TRUE(fs::has_video_extension(video));
  EXPECT_TRUE(fs::has_video_extension("A.MP4"));
  EXPECT_FALSE(fs::has_video_extension("a.png"));
  const auto folder = fs::frames_folder_for(video, 10);
  EXPECT_EQ(folder, dir.path() / "match-every10");
  EXPECT_EQ(fs::frames_folder_for(video, 15), dir.path() / "match-every15");
  fs::VideoFramesJob job;
  job.start(video, folder, {10});
  job.wait();
  ASSERT_TRUE(job.finished());
  ASSERT_TRUE(job.outcome()->ok()) << job.outcome()->error();
  EXPECT_EQ(job.outcome()->value(), 3);  // frames 0, 10, 20
  EXPECT_EQ(job.written(), 3);
  EXPECT_FLOAT_EQ(job.progress(), 1);
  for (const char* name : {"frame_000000.png", "frame_000010.png", "frame_000020.png"}) {
    const cv::Mat frame = cv::imread((folder / name).string());
    EXPECT_EQ(frame.cols, 160) << name;
  }
  EXPECT_FALSE(std::filesystem::exists(folder / "frame_000001.png"));
}

TEST(VideoFramesJob, UnreadableVideoIsAnError) {
  studio_test::TempDir dir("badvideo");
  const auto video = dir.path() / "broken.mp4";
  fieldlines::write_file_atomically(video, "not a video at all");
  fs::VideoFramesJob job;
  job.start(video, dir.path() / "frames", {5});
  job.wait();
  ASSERT_TRUE(job.finished());
  EXPECT_FALSE(job.outcome()->ok());
  EXPECT_NE(job.outcome()->error().find("broken.mp4"), std::string::npos) << job.outcome()->error();
  EXPECT_EQ(job.written(), 0);
}

namespace {
// An MJPG video of `frames` green frames.
void write_video(const std::filesystem::path& video, int frames, cv::Size size) {
  cv::VideoWriter writer(video.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25, size);
  ASSERT_TRUE(writer.isOpened());
  for (int i = 0; i < frames; ++i) writer.write(studio_test::field_image(size.width, size.height, {}));
}
}  // namespace

TEST(VideoImport, ExtractsThenIsDoneAndReusesAnExistingFolder) {
  studio_test::TempDir dir("import");
  const auto video = dir.path() / "clip.avi";
  write_video(video, 12, {96, 64});
  {
    fs::VideoImport import(video, 5);
    EXPECT_EQ(import.folder(), dir.path() / "clip-every5");
    const auto end = std::chrono::steady_clock::now() + 30s;
    while (!import.done() && std::chrono::steady_clock::now() < end) {
      import.poll();
      std::this_thread::sleep_for(1ms);
    }
    ASSERT_TRUE(import.done());
    EXPECT_EQ(import.written(), 3);  // frames 0, 5, 10
  }
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "clip-every5" / "frame_000010.png"));  // kept once done
  const fs::VideoImport again(video, 5);
  EXPECT_TRUE(again.done());  // the folder exists: reused as it is, nothing extracted
  EXPECT_EQ(again.written(), 0);
}

TEST(VideoImport, FailureThrowsAndLeavesNoFolder) {
  studio_test::TempDir dir("import-bad");
  const auto video = dir.path() / "broken.mp4";
  fieldlines::write_file_atomically(video, "not a video at all");
  fs::VideoImport import(video, 5);
  const auto end = std::chrono::steady_clock::now() + 30s;
  bool threw = false;
  while (!threw && std::chrono::steady_clock::now() < end) {
    try {
      import.poll();
    } catch (const fieldlines::Error& e) {
      threw = true;
      EXPECT_NE(std::string(e.what()).find("broken.mp4"), std::string::npos) << e.what();
    }
    std::this_thread::sleep_for(1ms);
  }
  EXPECT_TRUE(threw);
  EXPECT_FALSE(import.done());
  EXPECT_FALSE(std::filesystem::exists(import.folder()));
}

TEST(VideoImport, StoppedBeforeTheEndLeavesNoFolder) {
  studio_test::TempDir dir("import-stop");
  const auto video = dir.path() / "long.avi";
  write_video(video, 400, {320, 240});
  std::filesystem::path folder;
  {
    fs::VideoImport import(video, 1);
    folder = import.folder();
    // Wait for the first frames on disk, then close (the window closed, or Cancel).
    const auto end = std::chrono::steady_clock::now() + 30s;
    while (import.written() == 0 && std::chrono::steady_clock::now() < end) {
      import.poll();
      std::this_thread::sleep_for(1ms);
    }
    ASSERT_GT(import.written(), 0);
    ASSERT_FALSE(import.done());
  }
  // A half-written folder would be reused as complete next time: it must be gone.
  EXPECT_FALSE(std::filesystem::exists(folder));
}
