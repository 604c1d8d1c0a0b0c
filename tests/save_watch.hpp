#pragma once
// Watching atomic saves from a crash-safety test: the hidden temporary files a save writes beside
// its target (fieldlines::temporary_prefix), and waiting for one to appear.
#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>

#include "fieldlines/detect/atomic_file.hpp"

namespace fieldlines::test {

// Temporary files left beside `file`: the only debris a killed save may leave, never a damaged
// `file`.
inline int temporaries(const std::filesystem::path& file) {
  const std::string prefix = fieldlines::temporary_prefix(file);
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator(file.parent_path()))
    if (e.path().filename().string().rfind(prefix, 0) == 0) ++n;
  return n;
}

// Waits until a file named `prefix`... is created in the folder `inotify_fd` watches, or
// `timeout` passes. Returns whether it appeared.
inline bool wait_for_creation(int inotify_fd, const std::string& prefix, std::chrono::duration<double> timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  alignas(inotify_event) char buf[4096];
  while (std::chrono::steady_clock::now() < end) {
    pollfd p{inotify_fd, POLLIN, 0};
    if (::poll(&p, 1, 5) <= 0) continue;
    const ssize_t n = ::read(inotify_fd, buf, sizeof buf);
    for (ssize_t at = 0; at < n;) {
      const auto* ev = reinterpret_cast<const inotify_event*>(buf + at);
      if (ev->len > 0 && std::string(ev->name).rfind(prefix, 0) == 0) return true;
      at += static_cast<ssize_t>(sizeof(inotify_event) + ev->len);
    }
  }
  return false;
}

}  // namespace fieldlines::test
