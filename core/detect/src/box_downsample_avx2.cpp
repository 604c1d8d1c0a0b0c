#include "box_downsample_avx2.hpp"

#include "elsed/avx2_target.hpp"

namespace fieldlines::avx2 {

#ifdef FIELDLINES_AVX2
namespace {

AVX2_FN inline __m128i load16(const std::uint8_t* p) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p)); }
AVX2_FN inline __m256i load_u16(const std::uint16_t* p) {
  return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p));
}
AVX2_FN inline void store32(void* p, __m256i v) { _mm256_store_si256(static_cast<__m256i*>(p), v); }

}  // namespace

// Blocks of 64 output pixels (576 input bytes per row), in three sweeps so that no load reads
// what a store just before it wrote (a load that straddles a pending store stalls): the three
// rows summed into 16-bit lanes; each lane with those 3 and 6 on (the next two pixels of its
// channel), so that lane 9 x + c holds cell x's channel c, rounded and divided by 9 (a
// multiply-high by 7282 / 65536, exact for sums up to 9 * 255 + 4) and packed to bytes; the
// bytes of the cells' first lanes (3 of every 9) shuffled together. Summing and dividing three
// times the lanes needed costs less than gathering them first.
AVX2_FN int cells3_row(const std::uint8_t* r0, const std::uint8_t* r1, const std::uint8_t* r2, int w,
                       std::uint8_t* out) {
  constexpr int kPixels = 64, kBytes = 9 * kPixels;  // output pixels and input bytes per row of a block
  alignas(32) std::uint16_t sums[kBytes + 16];  // + the lanes the 3- and 6-lane shifts read past the block
  alignas(32) std::uint8_t cells[kBytes];
  for (int k = kBytes; k < kBytes + 16; ++k) sums[k] = 0;
  const __m256i round = _mm256_set1_epi16(4), ninth = _mm256_set1_epi16(7282);
  // Bytes 0-2 and 9-11 of 16: two cells' B, G, R.
  const __m128i pick = _mm_setr_epi8(0, 1, 2, 9, 10, 11, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1);
  int x0 = 0;
  for (; x0 + kPixels <= w; x0 += kPixels) {
    const int at = 9 * x0;
    for (int k = 0; k < kBytes; k += 16) {
      const __m256i a = _mm256_cvtepu8_epi16(load16(r0 + at + k));
      const __m256i b = _mm256_cvtepu8_epi16(load16(r1 + at + k));
      const __m256i c = _mm256_cvtepu8_epi16(load16(r2 + at + k));
      store32(sums + k, _mm256_add_epi16(_mm256_add_epi16(a, b), c));
    }
    // packus interleaves the 128-bit halves of its two inputs: the permute puts them in order.
    for (int k = 0; k < kBytes; k += 32) {
      const auto divided = [&](int i) AVX2_FN {
        const __m256i t = _mm256_add_epi16(_mm256_add_epi16(load_u16(sums + i), load_u16(sums + i + 3)),
                                           _mm256_add_epi16(load_u16(sums + i + 6), round));
        return _mm256_mulhi_epu16(t, ninth);
      };
      store32(cells + k, _mm256_permute4x64_epi64(_mm256_packus_epi16(divided(k), divided(k + 16)), 0xD8));
    }
    std::uint8_t* o = out + 3 * x0;
    for (int j = 0; j + 1 < kPixels / 2; ++j)  // 8-byte stores, 6 bytes each: the next one covers the spill
      _mm_storel_epi64(reinterpret_cast<__m128i*>(o + 6 * j), _mm_shuffle_epi8(load16(cells + 18 * j), pick));
    const int last = kPixels / 2 - 1;
    alignas(16) std::uint8_t two[16];
    _mm_store_si128(reinterpret_cast<__m128i*>(two), _mm_shuffle_epi8(load16(cells + 18 * last), pick));
    for (int i = 0; i < 6; ++i) o[6 * last + i] = two[i];
  }
  return x0;
}
#else
int cells3_row(const std::uint8_t*, const std::uint8_t*, const std::uint8_t*, int, std::uint8_t*) { return 0; }
#endif

}  // namespace fieldlines::avx2
