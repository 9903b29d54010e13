#pragma once
// A fresh, empty directory under the system temporary directory, removed afterwards.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

namespace capsula::io::testing {

class TemporaryDirectory {
public:
  explicit TemporaryDirectory(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / ("capsula_io_" + name + "_" + std::to_string(::getpid())))
  {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TemporaryDirectory() { std::filesystem::remove_all(path_); }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  /// Number of entries in the directory (to spot stray temporary files).
  std::size_t entryCount() const
  {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(path_)) {
      ++n;
    }
    return n;
  }

private:
  std::filesystem::path path_;
};

inline std::string readText(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline bool contains(const std::string& text, const std::string& piece)
{
  return text.find(piece) != std::string::npos;
}

} // namespace capsula::io::testing
