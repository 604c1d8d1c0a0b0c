#pragma once
// Figures honest for few images. With five labelled images the test split is one image, and its
// F1 says how well one picture went, not how well the next will: below kMinTestImages test
// images the studio shows leave-one-image-out figures instead (each labelled image in turn held
// out, the review loop's rule trained on the others, the counts pooled over every image), or
// says that there is not enough to judge.
#include <cstddef>
#include <stop_token>
#include <string>

#include "fieldlines/data/labelled_set.hpp"
#include "fieldlines/train/metrics.hpp"
#include "fieldlines/train/review.hpp"

namespace fieldlines::studio {

inline constexpr std::size_t kMinTestImages = 5;

// "" with kMinTestImages or more; else e.g. "1 test image: not enough to judge".
std::string not_enough_to_judge(std::size_t test_images);

struct LeaveOneOut {
  Counts pooled;           // over every held-out image
  std::size_t images = 0;  // labelled images held out in turn; 0: not computed (fewer than 2)
};

// `fit`: calibrate(every segment, start), label-free, so one fit serves every fold; `labelled`:
// the human labels with their images. Stops early (images = 0) when `stop` is requested.
LeaveOneOut leave_one_image_out(const Calibration& fit, const LabelledSet& labelled, const Thresholds& start,
                                const ProposalParams& params, std::stop_token stop = {});

}  // namespace fieldlines::studio
