#pragma once
// Where the CLI's commands save their outputs (JSON, CSV, overlays): always atomically, so an
// interrupted run never leaves a half-written file behind.
#include <filesystem>
#include <string_view>

namespace fieldlines::cli {

// Throws fieldlines::Error naming the path when the file cannot be written.
void write_output_file(const std::filesystem::path& path, std::string_view contents);

// Fails early (before a long batch) when `path` could not be written later: its folder is
// missing or `path` is a folder. Throws fieldlines::Error naming the option and the path.
void check_output_path(std::string_view option, const std::filesystem::path& path);

}  // namespace fieldlines::cli
