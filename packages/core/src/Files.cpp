#include "capsula/core/Files.hpp"

#include "capsula/core/Error.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

namespace capsula::core {

namespace fs = std::filesystem;

void ensureWritableDirectory(const std::string& directory)
{
  require<IoError>(!directory.empty(), "The output directory name is empty.");
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) {
    throw IoError("Cannot create output directory '" + directory + "': " + ec.message() +
                  ". Choose another directory with --output or Output/Directory.");
  }
  if (!fs::is_directory(directory)) {
    throw IoError("Output directory '" + directory + "' exists but is not a directory.");
  }
  const std::string probe = temporaryPathFor((fs::path(directory) / ".capsula-write-test").string());
  std::FILE* f = std::fopen(probe.c_str(), "w");
  if (f == nullptr) {
    throw IoError("Output directory '" + directory + "' is not writable: " + std::strerror(errno) +
                  ". Choose another directory with --output or Output/Directory.");
  }
  std::fclose(f);
  std::remove(probe.c_str());
}

std::string temporaryPathFor(const std::string& path)
{
  return path + ".tmp." + std::to_string(::getpid());
}

std::string diskFullAdvice(int errorNumber)
{
  if (errorNumber != ENOSPC && errorNumber != EDQUOT) {
    return "";
  }
  return std::string(" The disk is full (") + std::strerror(errorNumber) +
         "): free space there, or write elsewhere with --output DIR; --restart DIR continues from the last checkpoint.";
}

bool overwriteInPlace(const std::string& path, const std::string& text) noexcept
{
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0 || static_cast<std::size_t>(status.st_size) < text.size()) {
    return false;
  }
  const int fd = ::open(path.c_str(), O_WRONLY);
  if (fd < 0) {
    return false;
  }
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::pwrite(fd, text.data() + done, text.size() - done, static_cast<off_t>(done));
    if (n < 0 && errno == EINTR) {
      continue;
    }
    if (n <= 0) {
      break;
    }
    done += static_cast<std::size_t>(n);
  }
  const bool ok = done == text.size() && ::ftruncate(fd, static_cast<off_t>(text.size())) == 0 && ::fsync(fd) == 0;
  ::close(fd);
  return ok;
}

std::vector<std::string> removeStaleTemporaryFiles(const std::string& directory)
{
  std::vector<std::string> removed;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(directory, ec)) {
    const std::string name = entry.path().filename().string();
    const auto mark = name.rfind(".tmp.");
    if (mark == std::string::npos || mark == 0 || mark + 5 == name.size() ||
        name.find_first_not_of("0123456789", mark + 5) != std::string::npos) {
      continue;
    }
    const std::string digits = name.substr(mark + 5);
    if (digits.size() > 9) {
      continue;
    }
    const auto pid = static_cast<pid_t>(std::stol(digits));
    // kill(pid, 0) sends nothing: it fails with ESRCH only if no such process exists.
    if (pid == ::getpid() || ::kill(pid, 0) == 0 || errno != ESRCH) {
      continue;
    }
    std::error_code removeError;
    if (entry.is_regular_file(removeError) && fs::remove(entry.path(), removeError)) {
      removed.push_back(name);
    }
  }
  return removed;
}

void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write)
{
  const std::string tmp = temporaryPathFor(path);
  {
    std::ofstream out(tmp, std::ios::trunc);
    if (!out) {
      const int error = errno;
      throw IoError("Cannot write '" + path + "': " + std::strerror(error) + "." + diskFullAdvice(error));
    }
    out.precision(17);
    errno = 0; // the stream writes (and may fail) whenever its buffer fills, not only at the flush
    write(out);
    out.flush();
    if (!out) {
      const int error = errno;
      std::remove(tmp.c_str());
      const std::string advice = diskFullAdvice(error);
      throw IoError("Writing '" + path + "' failed" +
                    (advice.empty() && error != 0 ? std::string(": ") + std::strerror(error) + "." : "." + advice));
    }
  }
  replaceFileAtomically(tmp, path);
}

void replaceFileAtomically(const std::string& temporaryPath, const std::string& path)
{
  if (std::rename(temporaryPath.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(temporaryPath.c_str());
    throw IoError("Cannot move '" + temporaryPath + "' to '" + path + "': " + why + ".");
  }
}

} // namespace capsula::core
