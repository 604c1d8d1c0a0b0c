#include "gui/model/detection_job.hpp"

#include <chrono>
#include <exception>

#include "fieldlines/data/image_io.hpp"

namespace fieldlines::studio {

void DetectionJob::start(std::vector<Item> items, const DetectorParams& params, const Thresholds& thresholds) {
  total_ = items.size();
  done_ = 0;
  job_.start([items = std::move(items), params, thresholds](std::stop_token stop, const auto& report) {
    LineDetector detector(with_every_feature(params), thresholds);  // throws on bad parameters: the job's error
    detector.set_find_field_boundary(true);
    std::size_t processed = 0;
    for (const Item& item : items) {
      if (stop.stop_requested()) break;
      DetectionResult r;
      r.image = item.image;
      try {
        const cv::Mat image = load_image(item.path);
        const auto t0 = std::chrono::steady_clock::now();
        detector.detect(image, r.segments);
        r.detect_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        r.features = detector.features();
      } catch (const std::exception& e) {
        r.error = e.what();  // this image only; the others go on
      }
      report(std::move(r));
      ++processed;
    }
    return processed;
  });
}

std::vector<DetectionResult> DetectionJob::poll() {
  std::vector<DetectionResult> results = job_.poll();
  done_ += results.size();
  return results;
}

}  // namespace fieldlines::studio
