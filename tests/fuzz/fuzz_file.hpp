#pragma once
// Fuzz-harness helper: the file readers take paths, so each input goes to a per-process temp file.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace fieldlines::fuzz {

inline std::filesystem::path write_input(const char* name, const std::uint8_t* data, std::size_t size) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("fieldlines-fuzz-" + std::to_string(::getpid()) + "-" + name);
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                                 static_cast<std::streamsize>(size));
  return path;
}

}  // namespace fieldlines::fuzz
