#pragma once
// Where this build's tests find the sources, ../shared and the CLI. The paths are compiled into
// one object (test_paths.cpp), not into every test: a clone at another path then changes that
// object alone, and ccache still holds every other test object.
#include <filesystem>

namespace fieldlines::test {

std::filesystem::path shared_dir();  // ../shared, or -DFIELDLINES_SHARED_DIR
std::filesystem::path source_dir();  // the project's root
std::filesystem::path cli_path();    // the built `fieldlines` tool

}  // namespace fieldlines::test
