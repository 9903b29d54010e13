#include "capsula/io/MetricsCsv.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/core/Files.hpp"
#include "capsula/io/NumberFormat.hpp"

#include <fstream>
#include <sstream>
#include <utility>

namespace capsula::io {

namespace {

std::vector<std::string> splitCommas(const std::string& line)
{
  std::vector<std::string> pieces;
  std::string piece;
  std::istringstream in(line);
  while (std::getline(in, piece, ',')) {
    pieces.push_back(piece);
  }
  if (!line.empty() && line.back() == ',') {
    pieces.emplace_back();
  }
  return pieces;
}

std::string joinColumns(const std::vector<std::string>& columns)
{
  std::string line;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    line += (i > 0 ? "," : "") + columns[i];
  }
  return line;
}

void checkColumns(const std::vector<std::string>& columns, const std::string& path)
{
  core::require(!columns.empty(), "internal: the table '", path, "' needs at least one column");
  for (const auto& c : columns) {
    core::require(!c.empty() && c.find_first_of(",\"\r\n") == std::string::npos, "internal: column name '", c, "' of '",
                  path, "' is empty or contains ',', '\"' or a line break");
  }
}

} // namespace

MetricsCsv::MetricsCsv(std::string path, std::vector<std::string> columns)
    : MetricsCsv(std::move(path), std::move(columns), Unwritten{})
{
  rewrite();
}

MetricsCsv::MetricsCsv(std::string path, std::vector<std::string> columns, Unwritten)
    : path_(std::move(path)), columns_(std::move(columns))
{
  checkColumns(columns_, path_);
}

MetricsCsv MetricsCsv::resume(std::string path, std::vector<std::string> columns, double checkpointTime)
{
  MetricsCsv table(std::move(path), std::move(columns), Unwritten{});
  const CsvTable existing = readCsvTable(table.path_);
  core::require<core::IoError>(existing.columns == table.columns_, "Cannot continue '", table.path_,
                               "' after the restart: its columns (", joinColumns(existing.columns),
                               ") differ from this run's (", joinColumns(table.columns_),
                               "). Restart into a fresh output directory.");
  for (const auto& row : existing.rows) {
    if (row[0] <= checkpointTime) {
      std::string line;
      for (std::size_t i = 0; i < row.size(); ++i) {
        line += (i > 0 ? "," : "") + shortestDecimal(row[i]);
      }
      table.rows_.push_back(std::move(line));
    }
  }
  table.rewrite();
  return table;
}

void MetricsCsv::appendRow(const std::vector<double>& values)
{
  core::require(values.size() == columns_.size(), "internal: a row of ", values.size(), " values for the ",
                columns_.size(), " columns of '", path_, "'");
  std::string line;
  for (std::size_t i = 0; i < values.size(); ++i) {
    line += (i > 0 ? "," : "") + shortestDecimal(values[i]);
  }
  rows_.push_back(std::move(line));
  try {
    rewrite();
  } catch (...) {
    rows_.pop_back(); // the file still holds the previous rows; keep memory in step
    throw;
  }
}

void MetricsCsv::rewrite() const
{
  core::writeFileAtomically(path_, [&](std::ostream& out) {
    out << joinColumns(columns_) << '\n';
    for (const auto& row : rows_) {
      out << row << '\n';
    }
  });
}

CsvTable readCsvTable(const std::string& path)
{
  std::ifstream in(path);
  core::require<core::IoError>(static_cast<bool>(in), "Cannot read the table '", path,
                               "': it does not exist or is not readable.");
  CsvTable table;
  std::string line;
  core::require<core::IoError>(static_cast<bool>(std::getline(in, line)), "The table '", path,
                               "' is empty: it has no header row.");
  table.columns = splitCommas(line);
  for (std::size_t lineNumber = 2; std::getline(in, line); ++lineNumber) {
    const auto pieces = splitCommas(line);
    core::require<core::IoError>(pieces.size() == table.columns.size(), "The table '", path, "' is malformed: line ",
                                 lineNumber, " has ", pieces.size(), " values for ", table.columns.size(), " columns.");
    std::vector<double> row(pieces.size());
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      core::require<core::IoError>(parseDecimal(pieces[i], row[i]), "The table '", path, "' is malformed: line ",
                                   lineNumber, " column '", table.columns[i], "' is not a number ('", pieces[i], "').");
    }
    table.rows.push_back(std::move(row));
  }
  return table;
}

} // namespace capsula::io
