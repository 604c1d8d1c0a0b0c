#include "output_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "fieldlines/error.hpp"

namespace fieldlines::cli {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& path, const std::string& what) {
  throw Error("cannot write " + path.string() + ": " + what + " (" + std::strerror(errno) + ")");
}

}  // namespace

// Temporary file in the same folder (so rename is atomic), written, fsync'ed, then renamed
// over the target. TODO: switch to fieldlines::write_file_atomically once atomic_file.hpp lands.
void write_output_file(const fs::path& path, std::string_view contents) {
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::string tmp_name = ".";  // built with += : GCC 12 warns falsely on "." + std::string&&
  tmp_name += path.filename().string();
  tmp_name += ".tmp";
  tmp_name += std::to_string(::getpid());
  const fs::path tmp = dir / tmp_name;
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail(path, "cannot create a temporary file");
  std::size_t written = 0;
  while (written < contents.size()) {
    const auto n = ::write(fd, contents.data() + written, contents.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ::close(fd);
      ::unlink(tmp.c_str());
      fail(path, "write failed");
    }
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    ::unlink(tmp.c_str());
    fail(path, "flush failed");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    ::unlink(tmp.c_str());
    fail(path, "rename failed");
  }
}

void check_output_path(std::string_view option, const fs::path& path) {
  std::error_code ec;
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (!fs::is_directory(parent, ec))
    throw Error(std::string(option) + " " + path.string() + ": folder " + parent.string() + " does not exist");
  if (fs::is_directory(path, ec))
    throw Error(std::string(option) + " " + path.string() + ": is a folder, expected a file name");
}

}  // namespace fieldlines::cli
