#include "fieldlines/detect/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>

#include "fieldlines/detect/error.hpp"

namespace fieldlines {
namespace {

std::string errno_text() { return std::strerror(errno); }

// Closes the descriptor and removes the temporary file unless the rename succeeded.
class TempFile {
 public:
  explicit TempFile(std::filesystem::path path) : path_(std::move(path)) {
    fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  }
  ~TempFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) {
      std::error_code ec;
      std::filesystem::remove(path_, ec);
    }
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  int fd() const { return fd_; }
  bool close() {
    const int fd = fd_;
    fd_ = -1;
    return ::close(fd) == 0;
  }
  void commit() { committed_ = true; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  bool committed_ = false;
};

}  // namespace

std::string temporary_prefix(const std::filesystem::path& path) {
  std::string prefix = ".";
  prefix += path.filename().string();
  prefix += ".tmp";
  return prefix;
}

namespace {

// Writes all of `contents` to `fd`; false with errno set on failure.
bool write_all(int fd, std::string_view contents) {
  const char* data = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
  if (path.empty()) throw Error("cannot save: empty file name");
  // A device or a pipe (/dev/null, /dev/stdout, a FIFO) is written in place: renaming a file
  // over it would replace the device itself (as root, /dev/null with a regular file).
  std::error_code ec;
  const std::filesystem::file_type type = std::filesystem::status(path, ec).type();
  if (!ec && (type == std::filesystem::file_type::character || type == std::filesystem::file_type::block ||
              type == std::filesystem::file_type::fifo || type == std::filesystem::file_type::socket)) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) throw Error("cannot save '" + path.string() + "': " + errno_text());
    const bool written = write_all(fd, contents);
    const std::string why = written ? std::string() : errno_text();
    if (::close(fd) != 0 && written) throw Error("cannot save '" + path.string() + "': " + errno_text());
    if (!written) throw Error("cannot save '" + path.string() + "': " + why);
    return;
  }
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : ".";
  // A random suffix keeps concurrent savers (two studio windows) from sharing a temporary file.
  std::random_device rd;
  TempFile tmp(dir / (temporary_prefix(path) + std::to_string(rd() % 1000000)));
  if (tmp.fd() < 0) throw Error("cannot save '" + path.string() + "': " + errno_text());
  if (!write_all(tmp.fd(), contents)) throw Error("cannot save '" + path.string() + "': " + errno_text());
  // fsync before rename: otherwise a power cut can leave the new name pointing at empty data.
  if (::fsync(tmp.fd()) != 0) throw Error("cannot save '" + path.string() + "': " + errno_text());
  if (!tmp.close()) throw Error("cannot save '" + path.string() + "': " + errno_text());
  if (::rename(tmp.path().c_str(), path.c_str()) != 0)
    throw Error("cannot save '" + path.string() + "': " + errno_text());
  tmp.commit();
  // Persist the directory entry too (best effort: some file systems refuse fsync on folders).
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

int remove_stale_temporaries(const std::filesystem::path& path, std::filesystem::file_time_type::duration min_age) {
  namespace fs = std::filesystem;
  const fs::path dir = path.has_parent_path() ? path.parent_path() : ".";
  const std::string prefix = temporary_prefix(path);
  const auto now = fs::file_time_type::clock::now();
  int removed = 0;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= prefix.size() || name.rfind(prefix, 0) != 0) continue;
    if (name.find_first_not_of("0123456789", prefix.size()) != std::string::npos) continue;
    std::error_code e;
    const auto written = fs::last_write_time(it->path(), e);
    if (!e && now - written >= min_age && fs::remove(it->path(), e)) ++removed;
  }
  return removed;
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open '" + path.string() + "'");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw Error("cannot read '" + path.string() + "'");
  return ss.str();
}

}  // namespace fieldlines
