#pragma once
// Crash-safe file replacement: a save either fully happens or leaves the old file untouched.
#include <chrono>
#include <filesystem>
#include <string>
#include <string_view>

namespace fieldlines {

// Writes `contents` to a temporary file in the same folder, flushes it to disk and renames it
// over `path` (rename is atomic within one file system). Throws fieldlines::Error naming the path
// when any step fails; the temporary file is removed on failure. An existing device, pipe or
// socket at `path` (/dev/null, /dev/stdout) is written in place instead: a rename would replace it.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

// Name prefix of the temporary files a save of `path` writes beside it (".NAME.tmp" plus a
// number): hidden, and in the same folder so the rename stays within one file system.
std::string temporary_prefix(const std::filesystem::path& path);

// Removes the temporary files that saves of `path` killed mid-write (SIGKILL, power cut) left
// beside it, when older than `min_age` (a younger one may belong to a save in progress).
// Best effort, never throws; returns how many were removed.
int remove_stale_temporaries(const std::filesystem::path& path,
                             std::filesystem::file_time_type::duration min_age = std::chrono::minutes(1));

// Reads a whole file; throws fieldlines::Error naming the path when it cannot be read.
std::string read_file(const std::filesystem::path& path);

}  // namespace fieldlines
