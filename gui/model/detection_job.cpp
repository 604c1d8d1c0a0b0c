#include "gui/model/detection_job.hpp"

#include <chrono>
#include <exception>
#include <optional>
#include <span>
#include <vector>

#include "fieldlines/data/image_io.hpp"
#include "fieldlines/detect/stripes.hpp"
#include "fieldlines/train/detector_calibration.hpp"

namespace fieldlines::studio {
namespace {

// The stripes check on every segment, not only on those the detector's thresholds call markings,
// as the detector runs it and, in the same pass, with thin lines accepted.
std::vector<StripeVerdict> verdicts(StripeCheck& check, const cv::Mat& image, const FieldColours& field,
                                    std::span<const Segment> segments, const DetectorParams& params) {
  if (!check.run_with_thin_lines(image, field, segments, params))
    return std::vector<StripeVerdict>(segments.size(), StripeVerdict::Unchecked);
  std::vector<StripeVerdict> out;
  out.reserve(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i)
    out.push_back(check.flags()[i] ? StripeVerdict::Stripe
                                   : (check.thin_flags()[i] ? StripeVerdict::ThinLine : StripeVerdict::NotStripe));
  return out;
}

// The detector for the venue the frames show, as `fieldlines calibrate` chooses it and records
// it; an image that cannot be read is skipped here (its detection says why). Counts the images
// in `measured`.
std::shared_ptr<const DetectorChoice> chosen_detector(const std::vector<DetectionJob::Item>& items,
                                                      const DetectorParams& given, const std::stop_token& stop,
                                                      std::atomic<std::size_t>& measured) {
  const DetectorCalibrationParams rule;
  FieldContrast contrast(rule, given);
  for (const DetectionJob::Item& item : items) {
    if (stop.stop_requested()) break;
    try {
      contrast.add_image(load_image(item.path));
    } catch (const std::exception&) {
      // Unreadable: measured by no one; its detection below reports why.
    }
    ++measured;
  }
  const DetectorParams chosen = calibrated_detector(given, contrast, rule);
  return std::make_shared<const DetectorChoice>(
      DetectorChoice{chosen, detector_provenance(contrast, chosen)});
}

}  // namespace

void DetectionJob::start(std::vector<Item> items, const DetectorParams& params, const Thresholds& thresholds,
                         const std::optional<GroundCamera>& camera, bool choose_detector) {
  total_ = items.size();
  done_ = 0;
  measured_ = choose_detector ? std::make_shared<std::atomic<std::size_t>>(0) : nullptr;
  job_.start([items = std::move(items), params, thresholds, camera, measured = measured_](std::stop_token stop,
                                                                                          const auto& report) {
    std::shared_ptr<const DetectorChoice> chosen;
    if (measured) chosen = chosen_detector(items, params, stop, *measured);
    const DetectorParams every = with_every_feature(chosen ? chosen->params : params);
    LineDetector detector(every, thresholds);  // throws on bad parameters (or camera): the job's error
    detector.set_find_field_boundary(true);
    detector.set_camera(camera);
    StripeCheck stripes;
    std::size_t processed = 0;
    for (const Item& item : items) {
      if (stop.stop_requested()) break;
      DetectionResult r;
      r.image = item.image;
      r.chosen_detector = chosen;
      try {
        const cv::Mat image = load_image(item.path);
        const auto t0 = std::chrono::steady_clock::now();
        detector.detect(image, r.segments);
        r.detect_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        r.features = detector.features();
        r.stripes = verdicts(stripes, image, detector.stripe_colours(), r.segments, every);
      } catch (const std::exception& e) {
        r.error = e.what();  // this image only; the others go on
      }
      report(std::move(r));
      ++processed;
    }
    return processed;
  });
}

float DetectionJob::bar_progress() const {
  if (!measuring()) return progress();
  return total_ ? static_cast<float>(measured()) / static_cast<float>(total_) : 1.0f;
}

std::string DetectionJob::bar_text() const {
  const bool choosing = measuring();
  return std::string(choosing ? "measuring " : "detecting ") + std::to_string(choosing ? measured() : done_) + "/" +
         std::to_string(total_);
}

std::vector<DetectionResult> DetectionJob::poll() {
  std::vector<DetectionResult> results = job_.poll();
  done_ += results.size();
  return results;
}

}  // namespace fieldlines::studio
