#include "dynslam/core/AtomicFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace fs = std::filesystem;

namespace dynslam::core {
namespace {

std::string temporaryPathFor(const std::string& path) {
  const fs::path target(path);
  const std::string name =
      "." + target.filename().string() + "." + std::to_string(::getpid()) + ".tmp";
  return (target.parent_path() / name).string();
}

[[noreturn]] void fail(const std::string& path, const std::string& temporary, const char* what,
                       int error) {
  ::unlink(temporary.c_str());
  throw std::runtime_error("cannot write '" + path + "': " + what + ": " + std::strerror(error));
}

/// fsync before the rename: without it a power cut could leave the new name on an empty file.
void syncAndRename(const std::string& temporary, const std::string& path) {
  const int fd = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail(path, temporary, "reopening its temporary file", errno);
  const bool synced = ::fsync(fd) == 0;
  const int syncError = errno;
  ::close(fd);
  if (!synced) fail(path, temporary, "fsync", syncError);
  if (::rename(temporary.c_str(), path.c_str()) != 0) fail(path, temporary, "rename", errno);
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::string& content) {
  const std::string temporary = temporaryPathFor(path);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) fail(path, temporary, "creating its temporary file", errno);
  size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : EIO;
      ::close(fd);
      fail(path, temporary, "write", error);
    }
    written += size_t(n);
  }
  if (::close(fd) != 0) fail(path, temporary, "close", errno);
  syncAndRename(temporary, path);
}

void replaceFileAtomically(const std::string& path,
                           const std::function<void(const std::string& temporary)>& write) {
  const std::string temporary = temporaryPathFor(path);
  try {
    write(temporary);
  } catch (...) {
    ::unlink(temporary.c_str());
    throw;
  }
  syncAndRename(temporary, path);
}

}  // namespace dynslam::core
