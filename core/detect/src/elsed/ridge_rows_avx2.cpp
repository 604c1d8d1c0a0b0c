#include "ridge_rows_avx2.hpp"

#include "avx2_target.hpp"

namespace fieldlines::elsed::avx2 {

#ifdef FIELDLINES_AVX2
namespace {

AVX2_FN inline __m256i load(const std::uint8_t* p) { return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p)); }
AVX2_FN inline void store(std::int16_t* p, __m256i v) { _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), v); }

// 16 of a block's columns from x (bytes: the ridges `ax`, `ay`, and 0xFF where dy's sign turns),
// widened: dx, dy and mag written in the Sobel's units (4 per grey level), zero below the
// threshold; returns the direction (1: horizontal) in 16-bit lanes, zero below it too.
AVX2_FN inline __m256i write_half(__m128i ax8, __m128i ay8, __m128i neg8, __m256i below, int x, const RidgeRow& out) {
  const __m256i gx = _mm256_slli_epi16(_mm256_cvtepu8_epi16(ax8), 2), gy = _mm256_slli_epi16(_mm256_cvtepu8_epi16(ay8), 2);
  const __m256i m = _mm256_add_epi16(gx, gy);
  const __m256i kept = _mm256_cmpgt_epi16(m, below);
  const __m256i signed_gy = _mm256_blendv_epi8(gy, _mm256_sub_epi16(_mm256_setzero_si256(), gy), _mm256_cvtepi8_epi16(neg8));
  store(out.dx + x, _mm256_and_si256(gx, kept));
  store(out.dy + x, _mm256_and_si256(signed_gy, kept));
  store(out.mag + x, _mm256_and_si256(m, kept));
  return _mm256_and_si256(_mm256_and_si256(_mm256_cmpgt_epi16(gy, gx), kept), _mm256_set1_epi16(1));
}

// See ridge_pass.cpp's ridge_row: ridges in bytes (a saturating difference is the clamp at zero),
// 32 columns at a time; a block with a pixel that may reach the threshold is written whole.
template <int R>
AVX2_FN int ridge_row_r(const std::uint8_t* const* rows, int x0, int x1, int threshold, int least, const RidgeRow& out) {
  constexpr int D = kRidgeDiagonal<R>;
  const __m256i floor = _mm256_set1_epi8(static_cast<char>(least));
  const __m256i below = _mm256_set1_epi16(static_cast<short>(threshold - 1));
  const std::uint8_t* const g = rows[R];
  const auto block = [&](int x) AVX2_FN {
    const std::uint8_t* p = g + x;
    // The most over d of the lesser rise, c - max(side, other side), as c less the least such max.
    const __m256i c = load(p);
    __m256i sx = _mm256_max_epu8(load(p - 1), load(p + 1)), sy = _mm256_max_epu8(load(rows[R - 1] + x), load(rows[R + 1] + x));
    for (int d = 2; d <= R; ++d) {
      sx = _mm256_min_epu8(sx, _mm256_max_epu8(load(p - d), load(p + d)));
      sy = _mm256_min_epu8(sy, _mm256_max_epu8(load(rows[R - d] + x), load(rows[R + d] + x)));
    }
    const __m256i ax = _mm256_subs_epu8(c, sx), ay = _mm256_subs_epu8(c, sy);
    const __m256i sum = _mm256_adds_epu8(ax, ay);  // sum >= least as max(sum, least) == sum
    const auto may = static_cast<unsigned>(_mm256_movemask_epi8(_mm256_cmpeq_epi8(_mm256_max_epu8(sum, floor), sum)));
    if (may == 0) return;  // no line here
    __m256i f = _mm256_setzero_si256(), r = f;
    for (int d = 1; d <= D; ++d) {
      f = _mm256_max_epu8(f, _mm256_min_epu8(_mm256_subs_epu8(c, load(rows[R - d] + x - d)),
                                             _mm256_subs_epu8(c, load(rows[R + d] + x + d))));
      r = _mm256_max_epu8(r, _mm256_min_epu8(_mm256_subs_epu8(c, load(rows[R - d] + x + d)),
                                             _mm256_subs_epu8(c, load(rows[R + d] + x - d))));
    }
    const __m256i neg = _mm256_xor_si256(_mm256_cmpeq_epi8(_mm256_max_epu8(r, f), f), _mm256_set1_epi8(-1));  // r > f
    // Each half of 16 columns is a block of its own: a few ridge pixels on textured turf leave
    // the other half unwritten (a third fewer bytes written, and cleared the next frame).
    const auto half = [&](__m128i ax8, __m128i ay8, __m128i neg8, int at) AVX2_FN {
      const __m256i dir = write_half(ax8, ay8, neg8, below, at, out);
      _mm_storeu_si128(reinterpret_cast<__m128i*>(out.state + at),
                       _mm_packus_epi16(_mm256_castsi256_si128(dir), _mm256_extracti128_si256(dir, 1)));
      out.blocks[(*out.block_count)++] = out.first + static_cast<std::uint32_t>(at);
    };
    if (may & 0xFFFFu) half(_mm256_castsi256_si128(ax), _mm256_castsi256_si128(ay), _mm256_castsi256_si128(neg), x);
    if (may >> 16)
      half(_mm256_extracti128_si256(ax, 1), _mm256_extracti128_si256(ay, 1), _mm256_extracti128_si256(neg, 1), x + 16);
  };
  if (x1 - x0 < 32) return x0;
  int x = x0;
  for (; x + 32 <= x1; x += 32) block(x);
  if (x < x1) block(x1 - 32);  // the row's last columns, in a block overlapping the one before
  return x1;
}

}  // namespace

int ridge_row(const std::uint8_t* const* rows, int reach, int x0, int x1, int threshold, int least, const RidgeRow& out) {
  switch (reach) {
    case 1: return ridge_row_r<1>(rows, x0, x1, threshold, least, out);
    case 2: return ridge_row_r<2>(rows, x0, x1, threshold, least, out);
    case 3: return ridge_row_r<3>(rows, x0, x1, threshold, least, out);
    case 4: return ridge_row_r<4>(rows, x0, x1, threshold, least, out);
    case 5: return ridge_row_r<5>(rows, x0, x1, threshold, least, out);
    case 6: return ridge_row_r<6>(rows, x0, x1, threshold, least, out);
    case 7: return ridge_row_r<7>(rows, x0, x1, threshold, least, out);
    case 8: return ridge_row_r<8>(rows, x0, x1, threshold, least, out);
    default: return x0;
  }
}

#else

int ridge_row(const std::uint8_t* const*, int, int x0, int, int, int, const RidgeRow&) { return x0; }

#endif

}  // namespace fieldlines::elsed::avx2
