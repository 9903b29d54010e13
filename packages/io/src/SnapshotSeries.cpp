#include "capsula/io/SnapshotSeries.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/core/Files.hpp"
#include "capsula/io/SnapshotFile.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <utility>

namespace capsula::io {

namespace fs = std::filesystem;

namespace {

constexpr int indexDigits = 6;

std::string indexedName(const std::string& base, std::size_t index)
{
  char digits[32];
  std::snprintf(digits, sizeof(digits), "%0*zu", indexDigits, index);
  return base + "_" + digits + ".h5";
}

/// The index of "<base>_<digits>.h5", or -1 for any other name.
long long indexOf(const std::string& fileName, const std::string& base)
{
  const std::string prefix = base + "_", suffix = ".h5";
  if (fileName.size() <= prefix.size() + suffix.size() || fileName.compare(0, prefix.size(), prefix) != 0 ||
      fileName.compare(fileName.size() - suffix.size(), suffix.size(), suffix) != 0) {
    return -1;
  }
  const std::string digits = fileName.substr(prefix.size(), fileName.size() - prefix.size() - suffix.size());
  if (digits.size() < static_cast<std::size_t>(indexDigits) ||
      !std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c) != 0; })) {
    return -1;
  }
  return std::stoll(digits);
}

void removeFile(const std::string& path)
{
  std::error_code ec;
  fs::remove(path, ec);
  if (ec) {
    throw core::IoError("Cannot remove the stale snapshot '" + path + "': " + ec.message() + ".");
  }
}

} // namespace

SnapshotSeries::SnapshotSeries(std::string directory, std::string baseName)
  : directory_(std::move(directory)), baseName_(std::move(baseName))
{
  if (!isValidOutputName(baseName_)) {
    throw core::InputError("Snapshot base name '" + baseName_ +
                           "' must be letters, digits, '_', '-' or '.'.");
  }
  core::ensureWritableDirectory(directory_);
  for (const auto& file : existingFiles()) {
    removeFile(file.path);
  }
}

SnapshotSeries SnapshotSeries::resume(std::string directory, std::string baseName, double checkpointTime)
{
  SnapshotSeries series;
  series.directory_ = std::move(directory);
  series.baseName_ = std::move(baseName);
  core::ensureWritableDirectory(series.directory_);
  bool keeping = true;
  std::size_t expected = 0;
  for (const auto& file : series.existingFiles()) {
    if (keeping) {
      const Snapshot snapshot = readSnapshotFile(file.path);
      // Keep a gap-free prefix of the series up to the checkpoint.
      keeping = file.index == expected && snapshot.time <= checkpointTime;
      if (keeping) {
        series.layouts_.push_back(layoutOf(snapshot, fs::path(file.path).filename().string()));
        ++expected;
        continue;
      }
    }
    removeFile(file.path);
  }
  series.writeXdmf();
  return series;
}

std::vector<SnapshotSeries::ExistingFile> SnapshotSeries::existingFiles() const
{
  std::vector<ExistingFile> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(directory_, ec)) {
    const long long index = indexOf(entry.path().filename().string(), baseName_);
    if (index >= 0 && entry.is_regular_file()) {
      files.push_back({static_cast<std::size_t>(index), entry.path().string()});
    }
  }
  if (ec) {
    throw core::IoError("Cannot list the output directory '" + directory_ + "': " + ec.message() + ".");
  }
  std::sort(files.begin(), files.end(),
            [](const ExistingFile& a, const ExistingFile& b) { return a.index < b.index; });
  return files;
}

std::string SnapshotSeries::snapshotPath(std::size_t index) const
{
  return (fs::path(directory_) / indexedName(baseName_, index)).string();
}

std::string SnapshotSeries::xdmfPath() const
{
  return (fs::path(directory_) / (baseName_ + ".xdmf")).string();
}

std::string SnapshotSeries::write(const Snapshot& snapshot)
{
  const std::size_t index = layouts_.size();
  const std::string path = snapshotPath(index);
  writeSnapshotFile(path, snapshot);
  layouts_.push_back(layoutOf(snapshot, indexedName(baseName_, index)));
  try {
    writeXdmf();
  } catch (...) {
    layouts_.pop_back();
    throw;
  }
  return path;
}

void SnapshotSeries::writeXdmf() const
{
  const std::string text = xdmfTimeSeries(layouts_);
  core::writeFileAtomically(xdmfPath(), [&](std::ostream& out) { out << text; });
}

} // namespace capsula::io
