#include "core/output_path.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace mg {
namespace {

namespace fs = std::filesystem;

// Creating a file is the only reliable writability test: access(2) ignores read-only mounts
// and root's override, and /proc-like file systems accept neither.
void probe_writable(const std::string& option, const std::string& dir) {
  const std::string probe = (fs::path(dir) / (".mergeguard-probe." + std::to_string(::getpid()))).string();
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) throw OutputPathError(option, dir, std::string("not writable (") + std::strerror(errno) + ")");
  ::close(fd);
  ::unlink(probe.c_str());
}

}  // namespace

void prepare_output_dir(const std::string& option, const std::string& dir) {
  if (dir.empty()) throw OutputPathError(option, "''", "empty path");
  std::error_code ec;
  const fs::file_status st = fs::status(dir, ec);
  if (fs::exists(st) && !fs::is_directory(st)) throw OutputPathError(option, dir, "exists and is not a directory");
  if (!fs::exists(st)) {
    fs::create_directories(dir, ec);
    if (ec) throw OutputPathError(option, dir, "cannot create the directory (" + ec.message() + ")");
  }
  probe_writable(option, dir);
}

void check_output_file(const std::string& option, const std::string& file) {
  std::error_code ec;
  if (fs::is_directory(file, ec)) throw OutputPathError(option, file, "is a directory, expected a file");
  const fs::path parent = fs::path(file).parent_path();
  probe_writable(option, parent.empty() ? std::string(".") : parent.string());
}

}  // namespace mg
