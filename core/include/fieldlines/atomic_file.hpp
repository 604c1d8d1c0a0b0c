#pragma once
// Crash-safe file replacement: a save either fully happens or leaves the old file untouched.
#include <filesystem>
#include <string>
#include <string_view>

namespace fieldlines {

// Writes `contents` to a temporary file in the same folder, flushes it to disk and renames it
// over `path` (rename is atomic within one file system). Throws fieldlines::Error naming the path
// when any step fails; the temporary file is removed on failure.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

// Reads a whole file; throws fieldlines::Error naming the path when it cannot be read.
std::string read_file(const std::filesystem::path& path);

}  // namespace fieldlines
