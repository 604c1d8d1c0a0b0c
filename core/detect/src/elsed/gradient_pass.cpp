#include "gradient_pass.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <opencv2/core/base.hpp>
#include <opencv2/core/hal/intrin.hpp>

#include "gradient_rows_avx2.hpp"

namespace fieldlines::elsed {
namespace {

// Scratch rows are this much longer than the image so 8-lane loops may run past the last pixel.
constexpr int kSlack = 16;  // AVX2 rows: 16 lanes

// cvtColor(BGR2GRAY) for 8 bit: 15-bit fixed point, rounded (OpenCV 4's BY15/GY15/RY15, not
// the 14-bit R2Y/G2Y/B2Y of its YUV conversions).
constexpr int kB2Y = 3735, kG2Y = 19235, kR2Y = 9798, kYShift = 15;

inline std::uint8_t grey_of(const std::uint8_t* p) {
  return static_cast<std::uint8_t>((p[0] * kB2Y + p[1] * kG2Y + p[2] * kR2Y + (1 << (kYShift - 1))) >> kYShift);
}

void grey_row(const std::uint8_t* bgr, int w, std::uint8_t* out, bool use_avx2) {
  int x = use_avx2 ? avx2::grey_row(bgr, w, out) : 0;
#if CV_SIMD128
  // Pairs (b, g) and (r, 1) against (B2Y, G2Y) and (R2Y, rounding): one multiply-add each.
  const cv::v_int16x8 c_bg(kB2Y, kG2Y, kB2Y, kG2Y, kB2Y, kG2Y, kB2Y, kG2Y);
  const cv::v_int16x8 c_r1(kR2Y, 1 << (kYShift - 1), kR2Y, 1 << (kYShift - 1), kR2Y, 1 << (kYShift - 1), kR2Y,
                           1 << (kYShift - 1));
  const cv::v_int16x8 one = cv::v_setall_s16(1);
  const auto grey8 = [&](const cv::v_uint16x8& b, const cv::v_uint16x8& g, const cv::v_uint16x8& r) {
    cv::v_int16x8 bg0, bg1, r0, r1;
    cv::v_zip(cv::v_reinterpret_as_s16(b), cv::v_reinterpret_as_s16(g), bg0, bg1);
    cv::v_zip(cv::v_reinterpret_as_s16(r), one, r0, r1);
    const cv::v_int32x4 y0 = cv::v_shr<kYShift>(cv::v_dotprod(bg0, c_bg) + cv::v_dotprod(r0, c_r1));
    const cv::v_int32x4 y1 = cv::v_shr<kYShift>(cv::v_dotprod(bg1, c_bg) + cv::v_dotprod(r1, c_r1));
    return cv::v_pack(y0, y1);
  };
  for (; x + 16 <= w; x += 16) {
    cv::v_uint8x16 b, g, r;
    cv::v_load_deinterleave(bgr + 3 * x, b, g, r);
    cv::v_uint16x8 b0, b1, g0, g1, r0, r1;
    cv::v_expand(b, b0, b1);
    cv::v_expand(g, g0, g1);
    cv::v_expand(r, r0, r1);
    cv::v_store(out + x, cv::v_pack_u(grey8(b0, g0, r0), grey8(b1, g1, r1)));
  }
#endif
  for (; x < w; ++x) out[x] = grey_of(bgr + 3 * x);
}

// out[x] = sum_i k[i] * g[x + i] over a row padded by r on each side: the exact raw value of
// OpenCV's ufixedpoint16 horizontal pass (at most 255 * 256, so 16 bits never overflow).
// R > 0 fixes the radius at compile time (unrolled taps, kernel in registers); R = 0 reads r.
template <int R>
void smooth_h(const std::uint8_t* g, int w, const std::uint16_t* k, int r, std::uint16_t* out) {
  if constexpr (R > 0) r = R;
  int x = 0;
#if CV_SIMD128
  cv::v_uint16x8 kv[16];  // r <= 15
  for (int i = 0; i <= r; ++i) kv[i] = cv::v_setall_u16(k[i]);
  for (; x < w; x += 8) {  // rows carry kSlack, so the last vector may run past w
    cv::v_uint16x8 acc = cv::v_mul_wrap(cv::v_load_expand(g + x + r), kv[r]);
    for (int i = 0; i < r; ++i) {
      const cv::v_uint16x8 pair = cv::v_load_expand(g + x + i) + cv::v_load_expand(g + x + 2 * r - i);
      acc = acc + cv::v_mul_wrap(pair, kv[i]);
    }
    cv::v_store(out + x, acc);
  }
#endif
  for (; x < w; ++x) {
    unsigned acc = 0;
    for (int i = 0; i <= 2 * r; ++i) acc += static_cast<unsigned>(k[i]) * g[x + i];
    out[x] = static_cast<std::uint16_t>(acc);
  }
}

// out[x] = (sum_j k[j] * rows[j][x] + 2^15) >> 16, OpenCV's ufixedpoint32 vertical pass and its
// rounding, without 32-bit lanes: with H = 256 hi + lo, the sum is 256 A + L for
// A = sum k hi and L = sum k lo (each at most 65280), and (256 A + L + 2^15) >> 16 equals
// (A + (L >> 8) + 128) >> 8, where A + (L >> 8) = floor(sum / 256) <= 65280 cannot overflow.
template <int R>
void smooth_v(const std::uint16_t* const* rows, int w, const std::uint16_t* k, int r, std::uint8_t* out) {
  if constexpr (R > 0) r = R;
  int x = 0;
#if CV_SIMD128
  const cv::v_uint16x8 low_byte = cv::v_setall_u16(0xFF), half = cv::v_setall_u16(128);
  cv::v_uint16x8 kv[16];
  for (int i = 0; i <= r; ++i) kv[i] = cv::v_setall_u16(k[i]);
  for (; x < w; x += 8) {
    const cv::v_uint16x8 c = cv::v_load(rows[r] + x);
    cv::v_uint16x8 hi = cv::v_mul_wrap(cv::v_shr<8>(c), kv[r]), lo = cv::v_mul_wrap(c & low_byte, kv[r]);
    for (int i = 0; i < r; ++i) {
      const cv::v_uint16x8 a = cv::v_load(rows[i] + x), b = cv::v_load(rows[2 * r - i] + x);
      hi = hi + cv::v_mul_wrap(cv::v_shr<8>(a) + cv::v_shr<8>(b), kv[i]);
      lo = lo + cv::v_mul_wrap((a & low_byte) + (b & low_byte), kv[i]);
    }
    cv::v_pack_store(out + x, cv::v_shr<8>(hi + cv::v_shr<8>(lo) + half));
  }
#endif
  for (; x < w; ++x) {
    std::uint32_t acc = 0;
    for (int j = 0; j <= 2 * r; ++j) acc += static_cast<std::uint32_t>(k[j]) * rows[j][x];
    out[x] = static_cast<std::uint8_t>((acc + (1u << 15)) >> 16);
  }
}

using SmoothH = void (*)(const std::uint8_t*, int, const std::uint16_t*, int, std::uint16_t*);
using SmoothV = void (*)(const std::uint16_t* const*, int, const std::uint16_t*, int, std::uint8_t*);

// The kernels the method and original ELSED use (7x7, 5x5) and their neighbours, unrolled.
SmoothH smooth_h_for(int r, bool use_avx2) {
  if (use_avx2) return avx2::smooth_h;
  switch (r) {
    case 1: return smooth_h<1>;
    case 2: return smooth_h<2>;
    case 3: return smooth_h<3>;
    case 4: return smooth_h<4>;
    default: return smooth_h<0>;
  }
}
SmoothV smooth_v_for(int r, bool use_avx2) {
  if (use_avx2) return avx2::smooth_v;
  switch (r) {
    case 1: return smooth_v<1>;
    case 2: return smooth_v<2>;
    case 3: return smooth_v<3>;
    case 4: return smooth_v<4>;
    default: return smooth_v<0>;
  }
}

struct GradientRow {
  std::int16_t* dx;
  std::int16_t* dy;
  std::int16_t* mag;
  PixelState* state;  // the direction; Mark::Free
};

inline void sobel_px(const std::uint8_t* a, const std::uint8_t* b, const std::uint8_t* c, int x, int threshold,
                     const GradientRow& o) {
  const int gx = (a[x + 2] - a[x]) + 2 * (b[x + 2] - b[x]) + (c[x + 2] - c[x]);
  const int gy = (c[x] + 2 * c[x + 1] + c[x + 2]) - (a[x] + 2 * a[x + 1] + a[x + 2]);
  const int ax = std::abs(gx), ay = std::abs(gy), sum = ax + ay;  // at most 2040: fits int16
  o.dx[x] = static_cast<std::int16_t>(gx);
  o.dy[x] = static_cast<std::int16_t>(gy);
  o.mag[x] = static_cast<std::int16_t>(sum < threshold ? 0 : sum);
  o.state[x] = static_cast<PixelState>(ax >= ay ? EdgeDir::Vertical : EdgeDir::Horizontal);
}

// Sobel 3x3 of three smoothed rows (each padded by one pixel, so a[x + 1] is pixel x) and the
// per-pixel products. Output rows are exactly w long: the last vector overlaps the one before.
void sobel_row(const std::uint8_t* a, const std::uint8_t* b, const std::uint8_t* c, int w, int threshold,
               const GradientRow& o, bool use_avx2) {
  int x = use_avx2 ? avx2::sobel_row(a, b, c, w, threshold, o.dx, o.dy, o.mag, o.state) : 0;
  if (x == w) return;
#if CV_SIMD128
  if (w >= 8) {
    const cv::v_uint16x8 thr = cv::v_setall_u16(static_cast<std::uint16_t>(threshold)), one = cv::v_setall_u16(1);
    const auto at = [](const std::uint8_t* p) { return cv::v_reinterpret_as_s16(cv::v_load_expand(p)); };
    for (;;) {
      const cv::v_int16x8 a0 = at(a + x), a1 = at(a + x + 1), a2 = at(a + x + 2);
      const cv::v_int16x8 b0 = at(b + x), b2 = at(b + x + 2);
      const cv::v_int16x8 c0 = at(c + x), c1 = at(c + x + 1), c2 = at(c + x + 2);
      const cv::v_int16x8 gx = (a2 - a0) + cv::v_shl<1>(b2 - b0) + (c2 - c0);
      const cv::v_int16x8 gy = (c0 + cv::v_shl<1>(c1) + c2) - (a0 + cv::v_shl<1>(a1) + a2);
      const cv::v_uint16x8 ax = cv::v_abs(gx), ay = cv::v_abs(gy), sum = ax + ay;
      cv::v_store(o.dx + x, gx);
      cv::v_store(o.dy + x, gy);
      cv::v_store(o.mag + x, cv::v_reinterpret_as_s16(sum & (sum >= thr)));
      cv::v_pack_store(o.state + x, (ay > ax) & one);
      if (x + 8 == w) return;
      x = std::min(x + 8, w - 8);
    }
  }
#endif
  for (; x < w; ++x) sobel_px(a, b, c, x, threshold, o);
}

// One grey row, reflected at its ends, then smoothed horizontally into `out`.
void smooth_row_h(const cv::Mat& bgr, int source_row, std::uint8_t* g, const std::uint16_t* k, int r, SmoothH pass,
                  bool use_avx2, std::uint16_t* out) {
  const int w = bgr.cols;
  grey_row(bgr.ptr<std::uint8_t>(source_row), w, g + r, use_avx2);
  for (int i = 1; i <= r; ++i) {  // GaussianBlur's default border, BORDER_REFLECT_101
    g[r - i] = g[r + cv::borderInterpolate(-i, w, cv::BORDER_REFLECT_101)];
    g[r + w - 1 + i] = g[r + cv::borderInterpolate(w - 1 + i, w, cv::BORDER_REFLECT_101)];
  }
  pass(g, w, k, r, out);
}

}  // namespace

void gaussian_kernel_q8(int ksize, double sigma, std::vector<std::uint16_t>& out) {
  if (ksize < 3) {
    out.assign(1, 256);
    return;
  }
  // getGaussianKernelBitExact: half-integer steps (x = 2i - (n - 1)) against sigma / 2, the
  // centre weighs exp(0) = 1.
  const int half = ksize / 2;
  const double scale2x = -0.5 * 0.25 / (sigma * sigma);
  out.assign(static_cast<std::size_t>(ksize), 0);
  double values[16];  // half <= 15: the validated kernel is at most 31
  double sum = 0;
  for (int i = 0, x = 1 - ksize; i < half; ++i, x += 2) {
    values[i] = std::exp(static_cast<double>(x * x) * scale2x);
    sum += values[i];
  }
  sum = sum * 2 + 1;
  const double mul = 1 / sum;
  // getGaussianKernelFixedPoint_ED: round each outer tap carrying the error inwards; the centre
  // takes what is left so the kernel sums to exactly 256.
  double err = 0;
  int total = 0;
  for (int i = 0; i < half; ++i) {
    const double adjusted = values[i] * mul * 256.0 + err;
    const int v = cvRound(adjusted);
    err = adjusted - v;
    out[i] = out[ksize - 1 - i] = static_cast<std::uint16_t>(v);
    total += v;
  }
  out[half] = static_cast<std::uint16_t>(256 - 2 * total);
}

bool avx2::wanted() {
  static const bool cpu_has_avx2 = available();
  return cpu_has_avx2 && std::getenv("FIELDLINES_NO_AVX2") == nullptr;
}

void GradientPass::configure(int gaussian_kernel, double gaussian_sigma, int gradient_threshold) {
  gaussian_kernel_q8(gaussian_kernel, gaussian_sigma, kernel_);
  radius_ = static_cast<int>(kernel_.size()) / 2;
  threshold_ = gradient_threshold;
  use_avx2_ = avx2::wanted();
}

void GradientPass::size_maps(const cv::Mat& bgr, GradientMaps& maps) {
  const std::size_t n = static_cast<std::size_t>(bgr.cols) * static_cast<std::size_t>(bgr.rows);
  maps.width = bgr.cols;
  maps.height = bgr.rows;
  maps.dx.resize(n);
  maps.dy.resize(n);
  maps.mag.resize(n);
  maps.state.resize(n);
}

void GradientPass::run(const cv::Mat& bgr, GradientMaps& maps, const RidgeTarget* ridge, RidgeBlocks* blocks) {
  size_maps(bgr, maps);
  run_rows(bgr, maps, 0, bgr.rows, ridge, blocks);
}

int GradientPass::band_count(int rows, int threads) const {
  const int min_rows = std::max(kMinBandRows, 2 * (2 * radius_ + 1));
  return std::clamp(rows / min_rows, 1, std::max(threads, 1));
}

void GradientPass::run_rows(const cv::Mat& bgr, GradientMaps& maps, int row_begin, int row_end, const RidgeTarget* ridge,
                            RidgeBlocks* blocks) {
  const int w = bgr.cols, h = bgr.rows, r = radius_, taps = 2 * r + 1;
  if (row_begin >= row_end) return;
  // The ridge rows of this band (ridge_pass.hpp): [max(reach, first_row), min(band, h - reach)).
  const int reach = ridge ? ridge->reach : 0;
  const int band_first = std::max(row_begin, reach);
  const int ridge_first = std::max(band_first, ridge ? ridge->first_row : 0);
  const int ridge_last = ridge ? std::min({row_end, ridge->maps->height, h - reach}) : 0;
  // The buffers are sized for the band's ridge rows whatever first_row is: a frame's field top
  // moves, and a warm frame allocates nothing.
  const bool ridge_band = blocks && band_first < ridge_last;
  const bool ridges = ridge_band && ridge_first < ridge_last;
  const int slots = ridge_band ? std::max(3, 2 * reach + 1) : 3;  // the ring holds what both read
  const std::size_t h_stride = static_cast<std::size_t>(w) + kSlack;
  const std::size_t b_stride = static_cast<std::size_t>(w) + 2 + kSlack;
  // Grow only: a smaller frame reuses the larger one's capacity.
  grey_.resize(std::max(grey_.size(), static_cast<std::size_t>(w + 2 * r + kSlack)));
  hrows_.resize(std::max(hrows_.size(), h_stride * static_cast<std::size_t>(taps)));
  brows_.resize(std::max(brows_.size(), b_stride * static_cast<std::size_t>(slots)));
  if (ridge_band) blocks->starts.resize(std::max(blocks->starts.size(), blocks->count + max_ridge_blocks(w, ridge_last - band_first)));

  // Sobel row y reads smoothed rows y-1..y+1 (replicated at the edges), ridge row y rows
  // y-reach..y+reach; smoothed row yb reads grey rows yb-r..yb+r (reflected). `virtual_row` walks
  // the reflected grey rows once each.
  const int first_b = std::max(ridges ? std::min(row_begin - 1, ridge_first - reach) : row_begin - 1, 0);
  const int last_b = std::min(ridges ? std::max(row_end, ridge_last - 1 + reach) : row_end, h - 1);
  const int first_virtual = first_b - r;
  int virtual_row = first_virtual;
  const auto h_slot = [&](int v) { return hrows_.data() + static_cast<std::size_t>((v - first_virtual) % taps) * h_stride; };
  const auto b_slot = [&](int yb) { return brows_.data() + static_cast<std::size_t>(yb % slots) * b_stride; };
  const std::uint8_t* ridge_rows[2 * kMaxRidgeReach + 1];
  const auto ridge_row_at = [&](int y) {
    for (int k = 0; k <= 2 * reach; ++k) ridge_rows[k] = b_slot(y - reach + k) + 1;
    GradientMaps& m = *ridge->maps;
    const std::size_t at = static_cast<std::size_t>(y) * static_cast<std::size_t>(w);
    ridge_row(ridge_rows, w, *ridge,
              {m.dx.data() + at, m.dy.data() + at, m.mag.data() + at, m.state.data() + at, static_cast<std::uint32_t>(at),
               blocks->starts.data(), &blocks->count});
  };
  const std::uint16_t* rows[32];
  const SmoothH h_pass = smooth_h_for(r, use_avx2_);
  const SmoothV v_pass = smooth_v_for(r, use_avx2_);
  const auto sobel = [&](int y) {
    const std::size_t at = static_cast<std::size_t>(y) * static_cast<std::size_t>(w);
    const GradientRow o{maps.dx.data() + at, maps.dy.data() + at, maps.mag.data() + at, maps.state.data() + at};
    sobel_row(b_slot(std::max(y - 1, 0)), b_slot(y), b_slot(std::min(y + 1, h - 1)), w, threshold_, o, use_avx2_);
  };

  for (int yb = first_b; yb <= last_b; ++yb) {
    for (; virtual_row <= yb + r; ++virtual_row)
      smooth_row_h(bgr, cv::borderInterpolate(virtual_row, h, cv::BORDER_REFLECT_101), grey_.data(), kernel_.data(), r,
                   h_pass, use_avx2_, h_slot(virtual_row));
    for (int t = 0; t < taps; ++t) rows[t] = h_slot(yb - r + t);
    std::uint8_t* b = b_slot(yb);
    v_pass(rows, w, kernel_.data(), r, b + 1);
    b[0] = b[1];  // Sobel's BORDER_REPLICATE
    b[w + 1] = b[w];
    if (yb - 1 >= row_begin && yb - 1 < row_end) sobel(yb - 1);
    if (ridges && yb - reach >= ridge_first && yb - reach < ridge_last) ridge_row_at(yb - reach);
    if (yb == h - 1 && yb < row_end) sobel(yb);
  }
}

}  // namespace fieldlines::elsed
