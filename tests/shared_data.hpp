#pragma once
// Access to ../shared/data (the authors' real data), which is never committed. Where it is
// missing, a test fails under CI (CI=true) and skips with a message elsewhere.
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "test_paths.hpp"

namespace fieldlines::test {

inline bool running_under_ci() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::string(ci) == "true";
}

}  // namespace fieldlines::test

// Use at the top of a test: yields the path, or fails (CI) / skips (elsewhere) when absent.
#define FIELDLINES_REQUIRE_SHARED(relative, out_path)                                           \
  const std::filesystem::path out_path = ::fieldlines::test::shared_dir() / (relative);        \
  if (!std::filesystem::exists(out_path)) {                                                    \
    if (::fieldlines::test::running_under_ci()) {                                              \
      FAIL() << "shared data missing under CI: " << out_path                                   \
             << " (set -DFIELDLINES_SHARED_DIR=...)";                                          \
    } else {                                                                                   \
      GTEST_SKIP() << "shared data not found at " << out_path                                  \
                   << "; set -DFIELDLINES_SHARED_DIR to run this test";                        \
    }                                                                                          \
  }
