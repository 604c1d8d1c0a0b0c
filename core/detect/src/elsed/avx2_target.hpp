#pragma once
// Private: what a file of AVX2 kernels includes first. Every function there is compiled for AVX2
// through a target attribute (AVX2_FN), not a file-wide flag, and such a file includes no header
// with inline functions of its own (only the intrinsics): an AVX2 copy of a shared inline
// function could otherwise be the one the linker keeps for every caller. FIELDLINES_AVX2 is
// defined where the compiler can build them (x86-64 GCC or Clang); elsewhere the file's
// functions fall back to doing nothing, and the portable kernels run.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define FIELDLINES_AVX2 1
#define AVX2_FN __attribute__((target("avx2")))
#endif
