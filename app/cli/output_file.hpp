#pragma once
// Where the CLI's commands save their outputs (JSON, CSV, overlays): always atomically, so an
// interrupted run never leaves a half-written file behind.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace fieldlines::cli {

// Throws fieldlines::Error naming the path when the file cannot be written.
void write_output_file(const std::filesystem::path& path, std::string_view contents);

// Fails early (before a long batch) when `path` could not be written later: its folder is
// missing or `path` is a folder. Throws fieldlines::Error naming the option and the path.
void check_output_path(std::string_view option, const std::filesystem::path& path);

// Throws fieldlines::Error when `path` is the same file as one of `inputs`: a report written
// over the labels it was made from would destroy them.
void check_not_an_input(std::string_view option, const std::filesystem::path& path,
                        const std::vector<std::string>& inputs);

}  // namespace fieldlines::cli
