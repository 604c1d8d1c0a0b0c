#include "test_paths.hpp"

namespace fieldlines::test {

std::filesystem::path shared_dir() { return FIELDLINES_SHARED_DIR; }
std::filesystem::path source_dir() { return FIELDLINES_SOURCE_DIR; }
std::filesystem::path cli_path() { return FIELDLINES_CLI_PATH; }

}  // namespace fieldlines::test
