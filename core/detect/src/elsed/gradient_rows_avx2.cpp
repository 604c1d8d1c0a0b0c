#include "gradient_rows_avx2.hpp"

#include "avx2_target.hpp"

namespace fieldlines::elsed::avx2 {

#ifdef FIELDLINES_AVX2
namespace {

// Grey = (3735 b + 19235 g + 9798 r + 2^14) >> 15, OpenCV's cvtColor BGR2GRAY for 8 bit.
AVX2_FN inline __m256i grey16(__m256i b, __m256i g, __m256i r) {
  const __m256i c_bg = _mm256_set1_epi32((19235 << 16) | 3735);
  const __m256i c_r1 = _mm256_set1_epi32((16384 << 16) | 9798);
  const __m256i one = _mm256_set1_epi16(1);
  const __m256i lo = _mm256_add_epi32(_mm256_madd_epi16(_mm256_unpacklo_epi16(b, g), c_bg),
                                      _mm256_madd_epi16(_mm256_unpacklo_epi16(r, one), c_r1));
  const __m256i hi = _mm256_add_epi32(_mm256_madd_epi16(_mm256_unpackhi_epi16(b, g), c_bg),
                                      _mm256_madd_epi16(_mm256_unpackhi_epi16(r, one), c_r1));
  // unpacklo/hi work within 128-bit lanes; packs undoes it, so the 16 results stay in order.
  return _mm256_packs_epi32(_mm256_srai_epi32(lo, 15), _mm256_srai_epi32(hi, 15));
}

// 16 u16 lanes to 16 bytes, in order.
AVX2_FN inline void store_u8x16(std::uint8_t* out, __m256i v) {
  const __m256i packed = _mm256_permute4x64_epi64(_mm256_packus_epi16(v, v), 0xD8);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm256_castsi256_si128(packed));
}

AVX2_FN inline __m256i load_u8_as_u16(const std::uint8_t* p) {
  return _mm256_cvtepu8_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)));
}

AVX2_FN inline __m256i load_u16(const std::uint16_t* p) {
  return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p));
}

AVX2_FN inline void store_s16(std::int16_t* p, __m256i v) { _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), v); }

// One channel's 16 bytes out of 48 interleaved ones, widened to 16 bits.
AVX2_FN inline __m256i channel(__m128i a0, __m128i a1, __m128i a2, __m128i m0, __m128i m1, __m128i m2) {
  const __m128i bytes = _mm_or_si128(_mm_or_si128(_mm_shuffle_epi8(a0, m0), _mm_shuffle_epi8(a1, m1)),
                                     _mm_shuffle_epi8(a2, m2));
  return _mm256_cvtepu8_epi16(bytes);
}

template <int R>
AVX2_FN void smooth_h_r(const std::uint8_t* g, int w, const std::uint16_t* k, int r, std::uint16_t* out) {
  if constexpr (R > 0) r = R;
  __m256i kv[16];
  for (int i = 0; i <= r; ++i) kv[i] = _mm256_set1_epi16(static_cast<short>(k[i]));
  for (int x = 0; x < w; x += 16) {
    __m256i acc = _mm256_mullo_epi16(load_u8_as_u16(g + x + r), kv[r]);
    for (int i = 0; i < r; ++i) {
      const __m256i pair = _mm256_add_epi16(load_u8_as_u16(g + x + i), load_u8_as_u16(g + x + 2 * r - i));
      acc = _mm256_add_epi16(acc, _mm256_mullo_epi16(pair, kv[i]));
    }
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + x), acc);
  }
}

// See gradient_pass.cpp's smooth_v for why the hi/lo split rounds exactly like OpenCV.
template <int R>
AVX2_FN void smooth_v_r(const std::uint16_t* const* rows, int w, const std::uint16_t* k, int r, std::uint8_t* out) {
  if constexpr (R > 0) r = R;
  __m256i kv[16];
  for (int i = 0; i <= r; ++i) kv[i] = _mm256_set1_epi16(static_cast<short>(k[i]));
  const __m256i low_byte = _mm256_set1_epi16(0xFF), half = _mm256_set1_epi16(128);
  for (int x = 0; x < w; x += 16) {
    const __m256i c = load_u16(rows[r] + x);
    __m256i hi = _mm256_mullo_epi16(_mm256_srli_epi16(c, 8), kv[r]);
    __m256i lo = _mm256_mullo_epi16(_mm256_and_si256(c, low_byte), kv[r]);
    for (int i = 0; i < r; ++i) {
      const __m256i a = load_u16(rows[i] + x), b = load_u16(rows[2 * r - i] + x);
      hi = _mm256_add_epi16(hi, _mm256_mullo_epi16(_mm256_add_epi16(_mm256_srli_epi16(a, 8), _mm256_srli_epi16(b, 8)), kv[i]));
      lo = _mm256_add_epi16(lo, _mm256_mullo_epi16(_mm256_add_epi16(_mm256_and_si256(a, low_byte), _mm256_and_si256(b, low_byte)), kv[i]));
    }
    const __m256i sum = _mm256_add_epi16(_mm256_add_epi16(hi, _mm256_srli_epi16(lo, 8)), half);
    store_u8x16(out + x, _mm256_srli_epi16(sum, 8));
  }
}

}  // namespace

bool available() { return __builtin_cpu_supports("avx2"); }

AVX2_FN int grey_row(const std::uint8_t* bgr, int w, std::uint8_t* out) {
  // 16 pixels = 48 bytes in three loads; byte shuffles pull each channel's 16 bytes together.
  const __m128i b0 = _mm_setr_epi8(0, 3, 6, 9, 12, 15, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1);
  const __m128i b1 = _mm_setr_epi8(-1, -1, -1, -1, -1, -1, 2, 5, 8, 11, 14, -1, -1, -1, -1, -1);
  const __m128i b2 = _mm_setr_epi8(-1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 1, 4, 7, 10, 13);
  const __m128i g0 = _mm_setr_epi8(1, 4, 7, 10, 13, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1);
  const __m128i g1 = _mm_setr_epi8(-1, -1, -1, -1, -1, 0, 3, 6, 9, 12, 15, -1, -1, -1, -1, -1);
  const __m128i g2 = _mm_setr_epi8(-1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 2, 5, 8, 11, 14);
  const __m128i r0 = _mm_setr_epi8(2, 5, 8, 11, 14, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1);
  const __m128i r1 = _mm_setr_epi8(-1, -1, -1, -1, -1, 1, 4, 7, 10, 13, -1, -1, -1, -1, -1, -1);
  const __m128i r2 = _mm_setr_epi8(-1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, 3, 6, 9, 12, 15);
  int x = 0;
  // 32 pixels at a time: each 128-bit lane holds 16 pixels' 48 bytes, so the same in-lane
  // shuffles serve both halves; the lane-wise widening and packing keep the pixels in order.
  const __m256i B0 = _mm256_broadcastsi128_si256(b0), B1 = _mm256_broadcastsi128_si256(b1),
                B2 = _mm256_broadcastsi128_si256(b2), G0 = _mm256_broadcastsi128_si256(g0),
                G1 = _mm256_broadcastsi128_si256(g1), G2 = _mm256_broadcastsi128_si256(g2),
                R0 = _mm256_broadcastsi128_si256(r0), R1 = _mm256_broadcastsi128_si256(r1),
                R2 = _mm256_broadcastsi128_si256(r2);
  const __m256i zero = _mm256_setzero_si256();
  for (; x + 32 <= w; x += 32) {
    const std::uint8_t* p = bgr + 3 * x;
    const __m256i a0 = _mm256_loadu2_m128i(reinterpret_cast<const __m128i*>(p + 48), reinterpret_cast<const __m128i*>(p));
    const __m256i a1 = _mm256_loadu2_m128i(reinterpret_cast<const __m128i*>(p + 64), reinterpret_cast<const __m128i*>(p + 16));
    const __m256i a2 = _mm256_loadu2_m128i(reinterpret_cast<const __m128i*>(p + 80), reinterpret_cast<const __m128i*>(p + 32));
    const __m256i b = _mm256_or_si256(_mm256_or_si256(_mm256_shuffle_epi8(a0, B0), _mm256_shuffle_epi8(a1, B1)),
                                      _mm256_shuffle_epi8(a2, B2));
    const __m256i g = _mm256_or_si256(_mm256_or_si256(_mm256_shuffle_epi8(a0, G0), _mm256_shuffle_epi8(a1, G1)),
                                      _mm256_shuffle_epi8(a2, G2));
    const __m256i r = _mm256_or_si256(_mm256_or_si256(_mm256_shuffle_epi8(a0, R0), _mm256_shuffle_epi8(a1, R1)),
                                      _mm256_shuffle_epi8(a2, R2));
    const __m256i lo = grey16(_mm256_unpacklo_epi8(b, zero), _mm256_unpacklo_epi8(g, zero), _mm256_unpacklo_epi8(r, zero));
    const __m256i hi = grey16(_mm256_unpackhi_epi8(b, zero), _mm256_unpackhi_epi8(g, zero), _mm256_unpackhi_epi8(r, zero));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + x), _mm256_packus_epi16(lo, hi));
  }
  for (; x + 16 <= w; x += 16) {
    const __m128i* p = reinterpret_cast<const __m128i*>(bgr + 3 * x);
    const __m128i a0 = _mm_loadu_si128(p), a1 = _mm_loadu_si128(p + 1), a2 = _mm_loadu_si128(p + 2);
    store_u8x16(out + x, grey16(channel(a0, a1, a2, b0, b1, b2), channel(a0, a1, a2, g0, g1, g2),
                                channel(a0, a1, a2, r0, r1, r2)));
  }
  return x;
}

AVX2_FN void smooth_h(const std::uint8_t* g, int w, const std::uint16_t* k, int r, std::uint16_t* out) {
  switch (r) {
    case 1: return smooth_h_r<1>(g, w, k, r, out);
    case 2: return smooth_h_r<2>(g, w, k, r, out);
    case 3: return smooth_h_r<3>(g, w, k, r, out);
    case 4: return smooth_h_r<4>(g, w, k, r, out);
    default: return smooth_h_r<0>(g, w, k, r, out);
  }
}

AVX2_FN void smooth_v(const std::uint16_t* const* rows, int w, const std::uint16_t* k, int r, std::uint8_t* out) {
  switch (r) {
    case 1: return smooth_v_r<1>(rows, w, k, r, out);
    case 2: return smooth_v_r<2>(rows, w, k, r, out);
    case 3: return smooth_v_r<3>(rows, w, k, r, out);
    case 4: return smooth_v_r<4>(rows, w, k, r, out);
    default: return smooth_v_r<0>(rows, w, k, r, out);
  }
}

AVX2_FN int sobel_row(const std::uint8_t* a, const std::uint8_t* b, const std::uint8_t* c, int w, int threshold,
                      std::int16_t* dx, std::int16_t* dy, std::int16_t* mag, std::uint8_t* dir) {
  if (w < 16) return 0;
  const __m256i thr = _mm256_set1_epi16(static_cast<short>(threshold)), one = _mm256_set1_epi16(1);
  for (int x = 0;;) {
    const __m256i a0 = load_u8_as_u16(a + x), a1 = load_u8_as_u16(a + x + 1), a2 = load_u8_as_u16(a + x + 2);
    const __m256i b0 = load_u8_as_u16(b + x), b2 = load_u8_as_u16(b + x + 2);
    const __m256i c0 = load_u8_as_u16(c + x), c1 = load_u8_as_u16(c + x + 1), c2 = load_u8_as_u16(c + x + 2);
    const __m256i gx = _mm256_add_epi16(_mm256_add_epi16(_mm256_sub_epi16(a2, a0), _mm256_slli_epi16(_mm256_sub_epi16(b2, b0), 1)),
                                        _mm256_sub_epi16(c2, c0));
    const __m256i below = _mm256_add_epi16(_mm256_add_epi16(c0, _mm256_slli_epi16(c1, 1)), c2);
    const __m256i above = _mm256_add_epi16(_mm256_add_epi16(a0, _mm256_slli_epi16(a1, 1)), a2);
    const __m256i gy = _mm256_sub_epi16(below, above);
    const __m256i ax = _mm256_abs_epi16(gx), ay = _mm256_abs_epi16(gy), sum = _mm256_add_epi16(ax, ay);
    store_s16(dx + x, gx);
    store_s16(dy + x, gy);
    store_s16(mag + x, _mm256_andnot_si256(_mm256_cmpgt_epi16(thr, sum), sum));  // zero below the threshold
    store_u8x16(dir + x, _mm256_and_si256(_mm256_cmpgt_epi16(ay, ax), one));
    if (x + 16 == w) return w;
    x = x + 32 <= w ? x + 16 : w - 16;  // the last vector overlaps the one before
  }
}

#else
bool available() { return false; }
int grey_row(const std::uint8_t*, int, std::uint8_t*) { return 0; }
void smooth_h(const std::uint8_t*, int, const std::uint16_t*, int, std::uint16_t*) {}
void smooth_v(const std::uint16_t* const*, int, const std::uint16_t*, int, std::uint8_t*) {}
int sobel_row(const std::uint8_t*, const std::uint8_t*, const std::uint8_t*, int, int, std::int16_t*, std::int16_t*,
              std::int16_t*, std::uint8_t*) {
  return 0;
}
#endif

}  // namespace fieldlines::elsed::avx2
