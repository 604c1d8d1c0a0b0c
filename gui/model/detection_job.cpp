#include "gui/model/detection_job.hpp"

#include <chrono>
#include <exception>

#include "fieldlines/data/image_io.hpp"

namespace fieldlines::studio {

DetectionJob::~DetectionJob() {
  if (worker_.joinable()) {
    worker_.request_stop();
    worker_.join();
  }
}

void DetectionJob::start(std::vector<Item> items, const DetectorParams& params, const Thresholds& thresholds) {
  if (worker_.joinable()) {
    worker_.request_stop();
    worker_.join();
  }
  queue_.drain();
  total_ = items.size();
  done_ = 0;
  finished_ = false;
  running_ = true;
  worker_ = std::jthread([this, items = std::move(items), params, thresholds](std::stop_token stop) {
    try {
      LineDetector detector(params, thresholds);
      for (const Item& item : items) {
        if (stop.stop_requested()) break;
        DetectionResult r;
        r.image = item.image;
        try {
          const cv::Mat image = load_image(item.path);
          const auto t0 = std::chrono::steady_clock::now();
          detector.detect(image, r.segments);
          r.detect_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        } catch (const std::exception& e) {
          r.error = e.what();
        }
        queue_.push(std::move(r));
        ++done_;
      }
    } catch (const std::exception& e) {  // bad parameters: report once, against no image
      DetectionResult r;
      r.image = static_cast<std::size_t>(-1);
      r.error = e.what();
      queue_.push(std::move(r));
    }
    finished_ = true;
  });
}

void DetectionJob::cancel() {
  if (worker_.joinable()) worker_.request_stop();
}

std::vector<DetectionResult> DetectionJob::poll() {
  std::vector<DetectionResult> out = queue_.drain();
  if (running_ && finished_) {
    if (worker_.joinable()) worker_.join();
    // Anything pushed between the drain and the join is still queued: take it too.
    for (DetectionResult& r : queue_.drain()) out.push_back(std::move(r));
    running_ = false;
  }
  return out;
}

void DetectionJob::wait() {
  if (worker_.joinable()) worker_.join();
}

}  // namespace fieldlines::studio
