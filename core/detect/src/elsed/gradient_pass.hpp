#pragma once
// Private: the detector's first stage in one pass over the image, row by row.
//
// BGR -> grey -> Gaussian -> Sobel x/y -> L1 magnitude, edge direction and threshold, with only a
// few rows in flight (a ring of smoothed rows), so the grey and blurred images are never written
// out and the stage touches each input pixel once. Every step reproduces, bit for bit, what
// OpenCV 4's 8-bit calls give (cvtColor BGR2GRAY, GaussianBlur with its fixed-point kernel and
// BORDER_REFLECT_101, Sobel 3x3 CV_16S with BORDER_REPLICATE): the method's segments depend on
// exact gradient ties, so "close" is not enough. tests/gradient_pass_test.cpp compares them.
#include <cstdint>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "elsed_types.hpp"
#include "ridge_pass.hpp"

#pragma GCC visibility push(hidden)  // private to the library (see line_model.hpp)

namespace fieldlines::elsed {

// OpenCV's 8-bit Gaussian kernel: 8 fraction bits (raw values sum to 256), rounded by error
// diffusion from the centre outwards as GaussianBlur builds it. ksize odd; < 3 gives {256}.
void gaussian_kernel_q8(int ksize, double sigma, std::vector<std::uint16_t>& out);

class GradientPass {
 public:
  // Allocates the kernel; call when the parameters change, not per frame.
  void configure(int gaussian_kernel, double gaussian_sigma, int gradient_threshold);
  void set_threshold(int gradient_threshold) { threshold_ = gradient_threshold; }  // per frame: no kernel
  // bgr: 8-bit, 3 channels, at least 1x1. Sizes `maps` (by capacity) and fills all of it. With
  // `ridge`, also writes the thin-line pass's ridge rows (ridge_pass.hpp) into ridge->maps from
  // the smoothed rows in its ring, listing what it wrote in `blocks`.
  void run(const cv::Mat& bgr, GradientMaps& maps, const RidgeTarget* ridge = nullptr, RidgeBlocks* blocks = nullptr);
  // Rows [row_begin, row_end) of `maps`, already sized for bgr (size_maps): the same bits as the
  // whole-image pass, since the band reads the rows above and below it that its ring needs and
  // borders only the image's first and last rows. Passes on separate threads may fill disjoint
  // bands of one `maps` at once (each pass has its own scratch).
  void run_rows(const cv::Mat& bgr, GradientMaps& maps, int row_begin, int row_end, const RidgeTarget* ridge = nullptr,
                RidgeBlocks* blocks = nullptr);
  static void size_maps(const cv::Mat& bgr, GradientMaps& maps);
  // Row bands worth running for `rows` rows on `threads` threads: at each band edge 2r + 2
  // smoothed rows are computed by both neighbours, so no band is thinner than kMinBandRows or
  // twice the kernel; 1 means the whole image in one pass.
  int band_count(int rows, int threads) const;
  static constexpr int kMinBandRows = 32;

 private:
  bool use_avx2_ = false;  // the CPU has AVX2: gradient_rows_avx2's kernels instead of SSE2/NEON
  int radius_ = 0;
  int threshold_ = 0;
  std::vector<std::uint16_t> kernel_{256};
  // Scratch, sized to the widest image seen. Rows carry slack so vector loops may run past w.
  std::vector<std::uint8_t> grey_;     // one grey row with radius_ reflected pixels each side
  std::vector<std::uint16_t> hrows_;   // ring of 2*radius_+1 horizontally smoothed rows
  std::vector<std::uint8_t> brows_;    // ring of 3 (2 reach + 1 with ridges) smoothed rows, one replicated pixel each side
};

}  // namespace fieldlines::elsed

#pragma GCC visibility pop
