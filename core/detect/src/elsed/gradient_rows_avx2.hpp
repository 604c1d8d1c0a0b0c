#pragma once
// Private: the gradient pass's row kernels in AVX2 (16 lanes of 16 bits), chosen at run time on
// x86-64 CPUs that have it; everywhere else available() is false and gradient_pass.cpp's
// universal-intrinsics kernels (SSE2 / NEON) run. Same arithmetic, same bits: the fused pass is
// bit-exact with OpenCV either way (tests/gradient_pass_test.cpp runs whichever the CPU takes).
#include <cstdint>

namespace fieldlines::elsed::avx2 {

bool available();
// available(), unless FIELDLINES_NO_AVX2 is set: the tests force the SSE2 / NEON kernels with it
// on AVX2 machines, so that their bits are checked too. Read when a pass is configured.
bool wanted();
// Each returns the number of leading pixels it did (0..w); the caller finishes the row.
int grey_row(const std::uint8_t* bgr, int w, std::uint8_t* out);
// Whole rows: may write up to 15 pixels past w (scratch rows carry the slack).
void smooth_h(const std::uint8_t* g, int w, const std::uint16_t* k, int r, std::uint16_t* out);
void smooth_v(const std::uint16_t* const* rows, int w, const std::uint16_t* k, int r, std::uint8_t* out);
int sobel_row(const std::uint8_t* a, const std::uint8_t* b, const std::uint8_t* c, int w, int threshold,
              std::int16_t* dx, std::int16_t* dy, std::int16_t* mag, std::uint8_t* dir);

}  // namespace fieldlines::elsed::avx2
