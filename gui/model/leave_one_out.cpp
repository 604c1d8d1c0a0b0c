#include "gui/model/leave_one_out.hpp"

#include "fieldlines/train/splits.hpp"

namespace fieldlines::studio {

std::string not_enough_to_judge(std::size_t test_images) {
  if (test_images >= kMinTestImages) return {};
  return std::to_string(test_images) + " test image" + (test_images == 1 ? "" : "s") + ": not enough to judge";
}

LeaveOneOut leave_one_image_out(const Calibration& fit, const LabelledSet& labelled, const Thresholds& start,
                                const ProposalParams& params, std::stop_token stop) {
  LeaveOneOut out;
  if (labelled.images.size() < 2) return out;
  // k folds by image with k = the number of images: each fold holds out exactly one image.
  const int k = static_cast<int>(labelled.images.size());
  for (const Split& fold : k_fold(labelled, SplitMode::ByImage, k, 0)) {
    if (stop.stop_requested()) return {};
    const LabelledSet train = labelled.subset(fold.train), test = labelled.subset(fold.test);
    const ProposalThresholds made = proposal_thresholds(fit, train.segments, start, params, stop);
    out.pooled += count_labelled(test.segments, made.thresholds);
  }
  out.images = labelled.images.size();
  return out;
}

}  // namespace fieldlines::studio
