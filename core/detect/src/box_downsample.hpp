#pragma once
// The coarse pass's input (DetectorParams::coarse_scale): a band of an 8-bit BGR frame averaged
// over cells of f x f pixels. Written out rather than cv::resize(INTER_AREA), which builds its
// tables on every call: this allocates only when `out` changes size.
#include <opencv2/core/mat.hpp>

namespace fieldlines {

// `out` (8-bit BGR, cols / f by rows / f of `band`): each pixel the rounded mean of its cell.
// `band`: 8-bit BGR, its size whole cells of f px (the caller crops); f >= 1. With `avx2` (the CPU
// has it: elsed::avx2::wanted()), cells of 3 px take an AVX2 kernel, twice as fast as the
// portable one (47 -> 23 microseconds for a 640 x 336 band), with the same bits.
void box_downsample(const cv::Mat& band, int f, cv::Mat& out, bool avx2);

}  // namespace fieldlines
