#include "core/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace mg {
namespace {

namespace fs = std::filesystem;

std::string temporary_name(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  return path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
}

[[noreturn]] void fail(const std::string& path, const char* what, int err) {
  throw std::runtime_error(path + ": " + what + " (" + std::strerror(err) + ")");
}

void write_all(int fd, const std::string& content, const std::string& path) {
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(path, "write failed", errno);
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) fail(path, "flush failed", errno);
}

// Named temporary, then rename: the fallback where O_TMPFILE is not supported.
void write_via_named_temporary(const std::string& path, const std::string& content) {
  const std::string tmp = temporary_name(path);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail(path, "cannot write", errno);
  try {
    write_all(fd, content, path);
  } catch (...) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw;
  }
  const int close_errno = ::close(fd) != 0 ? errno : 0;
  if (close_errno != 0 || ::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = close_errno != 0 ? close_errno : errno;
    ::unlink(tmp.c_str());
    fail(path, close_errno != 0 ? "flush failed" : "rename failed", err);
  }
}

// Gives the complete unnamed file `fd` its name: linked directly when the name is new (nothing
// to clean up after a crash), else linked under a temporary name and renamed over the old file.
void publish(int fd, const std::string& path) {
  const std::string self = "/proc/self/fd/" + std::to_string(fd);
  if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, path.c_str(), AT_SYMLINK_FOLLOW) == 0) return;
  if (errno != EEXIST) fail(path, "cannot write", errno);
  const std::string tmp = temporary_name(path);
  if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, tmp.c_str(), AT_SYMLINK_FOLLOW) != 0) fail(path, "cannot write", errno);
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    fail(path, "rename failed", err);
  }
}

}  // namespace

void write_file_atomic(const std::string& path, const std::string& content) {
  const fs::path target(path);
  if (target.has_parent_path()) fs::create_directories(target.parent_path());
  const std::string dir = target.has_parent_path() ? target.parent_path().string() : std::string(".");
  static const bool proc_fd = ::access("/proc/self/fd", X_OK) == 0;  // linkat of an unnamed file needs it
  const int fd = proc_fd ? ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0644) : -1;
  if (fd < 0 && (!proc_fd || errno == EOPNOTSUPP || errno == EISDIR || errno == EINVAL))
    return write_via_named_temporary(path, content);
  if (fd < 0) fail(path, "cannot write", errno);
  try {
    write_all(fd, content, path);
    publish(fd, path);
  } catch (...) {
    ::close(fd);  // the unnamed file vanishes with its descriptor
    throw;
  }
  if (::close(fd) != 0) fail(path, "flush failed", errno);
}

void write_files_atomic(const std::vector<std::pair<std::string, std::string>>& path_and_content) {
  std::size_t done = 0;
  try {
    for (; done < path_and_content.size(); ++done) write_file_atomic(path_and_content[done].first, path_and_content[done].second);
  } catch (...) {
    for (std::size_t k = 0; k < done; ++k) ::unlink(path_and_content[k].first.c_str());
    throw;
  }
}

int remove_stale_temporaries(const std::string& dir) {
  std::error_code ec;
  int removed = 0;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    const auto at = name.rfind(".tmp.");
    if (at == std::string::npos) continue;
    long pid = 0;
    unsigned n = 0;
    char extra = 0;
    if (std::sscanf(name.c_str() + at, ".tmp.%ld.%u%c", &pid, &n, &extra) != 2 || pid <= 0) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // its writer may still run
    if (fs::remove(entry.path(), ec)) ++removed;
  }
  return removed;
}

}  // namespace mg
