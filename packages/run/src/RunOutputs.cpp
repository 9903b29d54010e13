#include "capsula/run/RunOutputs.hpp"

#include "capsula/run/Collective.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/Files.hpp>

#include <filesystem>

namespace capsula::run {

namespace fs = std::filesystem;

RunOutputs::RunOutputs(Teuchos::RCP<const Teuchos::Comm<int>> comm, std::string directory,
                       std::optional<std::string> restartDirectory)
    : comm_(std::move(comm)), directory_(std::move(directory)), restartDirectory_(std::move(restartDirectory))
{}

std::string RunOutputs::path(const std::string& file) const
{
  return (fs::path(directory_) / file).string();
}

void RunOutputs::onRoot(const std::function<void()>& action) const
{
  if (writing()) {
    run::onRoot(*comm_, action);
  }
}

void RunOutputs::open(const Teuchos::ParameterList& validatedDeck, const io::RunMetadata& metadata)
{
  application_ = metadata.application;
  onRoot([&] {
    try {
      output_.emplace(directory_);
    } catch (const core::IoError& e) {
      throw core::InputError(core::message("The output directory '", directory_, "' cannot be used (", e.what(),
                                           "). Choose another with --output DIR or 'Output/Directory'."));
    }
    staleFiles_ = core::removeStaleTemporaryFiles(directory_);
    output_->writeRunMetadata(validatedDeck, metadata);
  });
}

void RunOutputs::carryOver(const std::string& file) const
{
  if (!restartDirectory_ || fs::path(*restartDirectory_) == fs::path(directory_)) {
    return;
  }
  const fs::path from = fs::path(*restartDirectory_) / file;
  if (fs::exists(from)) {
    fs::copy_file(from, path(file), fs::copy_options::overwrite_existing);
  }
}

void RunOutputs::openTable(const std::string& file, const std::vector<std::string>& columns,
                           std::optional<double> resumeAfter)
{
  onRoot([&] {
    tables_.erase(file);
    if (resumeAfter) {
      carryOver(file);
      tables_.emplace(file, io::MetricsCsv::resume(path(file), columns, *resumeAfter));
    } else {
      tables_.emplace(file, io::MetricsCsv(path(file), columns));
    }
  });
}

void RunOutputs::appendRow(const std::string& file, const std::vector<double>& row)
{
  onRoot([&] { tables_.at(file).appendRow(row); });
}

void RunOutputs::openSnapshots(const std::string& base, std::optional<double> resumeAfter)
{
  onRoot([&] {
    series_.erase(base);
    if (resumeAfter) {
      series_.emplace(base, io::SnapshotSeries::resume(directory_, base, *resumeAfter,
                                                       restartDirectory_ ? *restartDirectory_ : ""));
    } else {
      series_.emplace(base, io::SnapshotSeries(directory_, base));
    }
  });
}

void RunOutputs::writeSnapshot(const std::string& base, const std::function<io::Snapshot()>& snapshot)
{
  onRoot([&] { series_.at(base).write(snapshot()); });
}

void RunOutputs::writeCheckpoint(const std::function<io::Checkpoint()>& checkpoint)
{
  onRoot([&] {
    io::Checkpoint content = checkpoint();
    content.application = application_;
    io::writeCheckpoint(path("checkpoint.h5"), content);
  });
}

void RunOutputs::writeSummary(const std::function<io::JsonValue()>& summary)
{
  onRoot([&] { io::writeJsonFile(path("summary.json"), summary()); });
}

void RunOutputs::writeSummaryAfterFailure(const std::function<io::JsonValue()>& summary) noexcept
{
  if (!writing() || comm_->getRank() != 0 || !output_) {
    return;
  }
  io::JsonValue json;
  try {
    json = summary();
    io::writeJsonFile(path("summary.json"), json);
    return;
  } catch (...) {
    // The original error is the one to report.
  }
  // On a full disk no new file can be written, but the "running" summary.json already
  // has its space: the failed one takes it if it fits.
  try {
    io::JsonValue brief = io::JsonValue::object(); // what fits when the whole does not
    for (const auto& [key, value] : json.members()) {
      if (key == "application" || key == "status" || key == "failure" || key == "time") {
        brief[key] = value;
      }
    }
    for (const std::string& text : {io::toJson(json), io::toJson(json, 0), io::toJson(brief)}) {
      if (core::overwriteInPlace(path("summary.json"), text + "\n")) {
        return;
      }
    }
  } catch (...) {
  }
}

} // namespace capsula::run
