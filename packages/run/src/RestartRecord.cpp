#include "capsula/run/RestartRecord.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/io/MetricsCsv.hpp>

#include <filesystem>

namespace capsula::run {

void requireTableUpToCheckpoint(const std::string& directory, const std::string& file, double checkpointTime,
                                std::int64_t rowsWritten)
{
  const std::string path = (std::filesystem::path(directory) / file).string();
  const std::string restart = core::message("--restart ", directory, ": '", path, "'");
  core::require<core::InputError>(std::filesystem::is_regular_file(path), restart,
                                  " is missing; the checkpoint at t = ", checkpointTime, " continues its ", rowsWritten,
                                  " rows. Restore the file, or start the run afresh in another output directory.");
  io::CsvTable table;
  try {
    table = io::readCsvTable(path);
  } catch (const core::IoError& e) {
    throw core::InputError(core::message(restart, " cannot be continued: ", e.what()));
  }
  std::int64_t rows = 0;
  for (const auto& row : table.rows) {
    rows += !row.empty() && row[0] <= checkpointTime ? 1 : 0;
  }
  core::require<core::InputError>(rows == rowsWritten, restart, " holds ", rows,
                                  " rows up to the checkpoint at t = ", checkpointTime, ", where the run wrote ",
                                  rowsWritten,
                                  ": the record is damaged (a row lost or added). Restore the file, or start the run "
                                  "afresh in another output directory.");
}

} // namespace capsula::run
