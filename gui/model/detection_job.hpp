#pragma once
// Detects segments in many images on a worker thread (one LineDetector, reused), reporting each
// image as it finishes; the UI thread polls once per frame and shows the progress.
#include <atomic>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "fieldlines/detect/detector.hpp"
#include "gui/model/message_queue.hpp"

namespace fieldlines::studio {

struct DetectionResult {
  std::size_t image = 0;          // the caller's index
  std::vector<Segment> segments;  // labels as predicted by the detector's thresholds
  double detect_ms = 0;           // detector time only (not file loading)
  std::string error;              // non-empty when the image could not be loaded or detected
};

class DetectionJob {
 public:
  DetectionJob() = default;
  ~DetectionJob();
  DetectionJob(const DetectionJob&) = delete;
  DetectionJob& operator=(const DetectionJob&) = delete;

  struct Item {
    std::size_t image;
    std::filesystem::path path;
  };
  // Starts on a worker thread; a running job is cancelled and joined first.
  void start(std::vector<Item> items, const DetectorParams& params, const Thresholds& thresholds);
  void cancel();
  bool running() const { return running_; }
  // Results finished since the last poll (UI thread, once per frame).
  std::vector<DetectionResult> poll();
  void wait();  // blocks until done (tests, shutdown); results stay queued for poll()

  std::size_t total() const { return total_; }
  std::size_t done() const { return done_.load(); }
  float progress() const { return total_ ? static_cast<float>(done()) / static_cast<float>(total_) : 1.0f; }

 private:
  MessageQueue<DetectionResult> queue_;
  std::jthread worker_;
  std::atomic<std::size_t> done_{0};
  std::atomic<bool> finished_{false};
  std::size_t total_ = 0;
  bool running_ = false;
};

}  // namespace fieldlines::studio
