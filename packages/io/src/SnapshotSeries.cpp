#include "capsula/io/SnapshotSeries.hpp"

#include "Hdf5Support.hpp"
#include "UndoJournal.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/core/Files.hpp"
#include "capsula/io/SnapshotFile.hpp"

#include <cstdio>
#include <filesystem>
#include <utility>

namespace capsula::io {

namespace fs = std::filesystem;

namespace {

/// Copies `from` to `to` atomically (temporary copy, fsync, rename).
void copyAtomically(const std::string& from, const std::string& to)
{
  const std::string temporary = core::temporaryPathFor(to);
  try {
    std::error_code ec;
    fs::copy_file(from, temporary, fs::copy_options::overwrite_existing, ec);
    if (ec) {
      throw core::IoError("Cannot copy the snapshot file '" + from + "' to '" + to + "': " + ec.message() + ".");
    }
    hdf5::syncToDisk(temporary);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  hdf5::discardUndoJournal(to); // it belongs to the file being replaced
  core::replaceFileAtomically(temporary, to);
}

} // namespace

SnapshotSeries::SnapshotSeries(std::string directory, std::string baseName)
    : SnapshotSeries(std::move(directory), std::move(baseName), true)
{}

SnapshotSeries::SnapshotSeries(std::string directory, std::string baseName, bool create)
    : directory_(std::move(directory)), baseName_(std::move(baseName))
{
  if (!isValidOutputName(baseName_)) {
    throw core::InputError("Snapshot base name '" + baseName_ + "' must be letters, digits, '_', '-' or '.'.");
  }
  core::ensureWritableDirectory(directory_);
  if (create) {
    createSnapshotFile(filePath());
    writeXdmf();
  }
}

SnapshotSeries SnapshotSeries::resume(std::string directory, std::string baseName, double checkpointTime,
                                      const std::string& sourceDirectory)
{
  SnapshotSeries series(std::move(directory), std::move(baseName), false);
  if (!sourceDirectory.empty() && fs::path(sourceDirectory) != fs::path(series.directory_)) {
    const std::string source = (fs::path(sourceDirectory) / (series.baseName_ + ".h5")).string();
    if (fs::exists(source)) {
      undoInterruptedAppend(source);
      copyAtomically(source, series.filePath());
    } else if (fs::exists(series.filePath())) {
      createSnapshotFile(series.filePath()); // not this run's: the source had none
    }
  }
  if (!fs::exists(series.filePath())) {
    createSnapshotFile(series.filePath());
  }
  undoInterruptedAppend(series.filePath());
  std::vector<SnapshotLayout> layouts;
  try {
    layouts = readSnapshotLayouts(series.filePath());
  } catch (const core::IoError& e) {
    throw core::IoError(
        core::message(e.what(), " The run cannot continue its snapshots there; move '", series.filePath(),
                      "' away to restart with a new snapshot series (the checkpoint and the tables are unaffected)."));
  }
  // Keep the prefix up to the checkpoint (snapshot times increase along the series).
  std::size_t keep = 0;
  while (keep < layouts.size() && layouts[keep].time <= checkpointTime) {
    ++keep;
  }
  if (keep < layouts.size()) {
    truncateSnapshots(series.filePath(), keep);
    layouts.resize(keep);
  }
  series.layouts_ = std::move(layouts);
  series.writeXdmf();
  return series;
}

std::string SnapshotSeries::filePath() const
{
  return (fs::path(directory_) / (baseName_ + ".h5")).string();
}

std::string SnapshotSeries::xdmfPath() const
{
  return (fs::path(directory_) / (baseName_ + ".xdmf")).string();
}

std::size_t SnapshotSeries::write(const Snapshot& snapshot)
{
  layouts_.push_back(appendSnapshot(filePath(), snapshot));
  writeXdmf();
  return layouts_.size() - 1;
}

void SnapshotSeries::writeXdmf() const
{
  const std::string text = xdmfTimeSeries(baseName_ + ".h5", layouts_);
  core::writeFileAtomically(xdmfPath(), [&](std::ostream& out) { out << text; });
}

} // namespace capsula::io
