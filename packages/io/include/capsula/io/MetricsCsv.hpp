#pragma once
// The metrics table of a run (metrics.csv): a header row of column names, then one row
// of numbers per output time; the first column is the time.
//
// Crash safety: the rows are kept in memory and the whole file is rewritten atomically
// (temporary + rename) at every output, so the file on disk is always a complete table;
// a crash can lose the last row, never truncate one. Rewriting costs O(rows) per output:
// ~1 MB for 10^4 rows of 20 columns, negligible next to one boundary-integral step.
// Numbers are written in the shortest form that reads back as the same double.
//
// Restart: resume() reads the table, keeps the rows whose time is <= the checkpoint's,
// and continues the same file, so rows written after the checkpoint by the run that
// stopped are not duplicated. Serial: call from one rank.
#include <string>
#include <vector>

namespace capsula::io {

class MetricsCsv {
public:
  /// A new table at `path`, written at once with its header row (replacing any existing
  /// file). Column names must be non-empty and free of ',', '"' and line breaks. Throws
  /// core::IoError naming the file if it cannot be written.
  MetricsCsv(std::string path, std::vector<std::string> columns);

  /// Continues the table at `path` after a restart from a checkpoint at `checkpointTime`.
  /// Throws core::IoError naming the file if it is missing or unreadable, or if its header
  /// differs from `columns`.
  static MetricsCsv resume(std::string path, std::vector<std::string> columns, double checkpointTime);

  /// Appends a row (one value per column) and rewrites the file atomically.
  void appendRow(const std::vector<double>& values);

  const std::string& path() const { return path_; }
  const std::vector<std::string>& columns() const { return columns_; }
  std::size_t rowCount() const { return rows_.size(); }

private:
  struct Unwritten {};
  MetricsCsv(std::string path, std::vector<std::string> columns, Unwritten);
  void rewrite() const;

  std::string path_;
  std::vector<std::string> columns_;
  std::vector<std::string> rows_; // formatted lines, without the line break
};

/// A CSV table of numbers as written by MetricsCsv.
struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

/// Reads a numeric CSV table with a header row. Throws core::IoError naming the file and
/// the line if it is missing or malformed.
CsvTable readCsvTable(const std::string& path);

} // namespace capsula::io
