// A full disk for one directory, for the tests: preloaded (LD_PRELOAD) into a run, it lets
// the files under $CAPSULA_FULL_DISK_DIR grow by $CAPSULA_FULL_DISK_BYTES in all, then
// fails every write that would grow one further with ENOSPC, as a full file system does.
// Writes within a file's present size (an overwrite in place) still succeed, as they do on
// a full disk. Everything else passes through to the C library.
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>

#include <dlfcn.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <unistd.h>

namespace {

std::atomic<long long> grown{0};

// Whether a write of `bytes` at `offset` (-1: the file position) to `fd` may proceed.
bool mayWrite(int fd, long long offset, long long bytes)
{
  const char* directory = std::getenv("CAPSULA_FULL_DISK_DIR");
  const char* budget = std::getenv("CAPSULA_FULL_DISK_BYTES");
  if (directory == nullptr || budget == nullptr || bytes <= 0) {
    return true;
  }
  char target[4096];
  const std::string link = "/proc/self/fd/" + std::to_string(fd);
  const ssize_t length = ::readlink(link.c_str(), target, sizeof(target) - 1);
  if (length <= 0 || std::strncmp(target, directory, std::strlen(directory)) != 0) {
    return true;
  }
  struct stat status {};
  if (::fstat(fd, &status) != 0) {
    return true;
  }
  if (offset < 0) {
    offset = ::lseek(fd, 0, SEEK_CUR);
  }
  const long long growth = offset + bytes - static_cast<long long>(status.st_size);
  if (growth <= 0) {
    return true;
  }
  if (grown.fetch_add(growth) + growth > std::atoll(budget)) {
    errno = ENOSPC;
    return false;
  }
  return true;
}

template <typename Function>
Function next(const char* name)
{
  return reinterpret_cast<Function>(::dlsym(RTLD_NEXT, name));
}

} // namespace

extern "C" {

ssize_t write(int fd, const void* data, size_t size)
{
  static auto real = next<ssize_t (*)(int, const void*, size_t)>("write");
  return mayWrite(fd, -1, static_cast<long long>(size)) ? real(fd, data, size) : -1;
}

ssize_t pwrite(int fd, const void* data, size_t size, off_t offset)
{
  static auto real = next<ssize_t (*)(int, const void*, size_t, off_t)>("pwrite");
  return mayWrite(fd, offset, static_cast<long long>(size)) ? real(fd, data, size, offset) : -1;
}

ssize_t pwrite64(int fd, const void* data, size_t size, off_t offset)
{
  static auto real = next<ssize_t (*)(int, const void*, size_t, off_t)>("pwrite64");
  return mayWrite(fd, offset, static_cast<long long>(size)) ? real(fd, data, size, offset) : -1;
}

ssize_t writev(int fd, const struct iovec* parts, int count)
{
  static auto real = next<ssize_t (*)(int, const struct iovec*, int)>("writev");
  long long size = 0;
  for (int i = 0; i < count; ++i) {
    size += static_cast<long long>(parts[i].iov_len);
  }
  return mayWrite(fd, -1, size) ? real(fd, parts, count) : -1;
}
}
