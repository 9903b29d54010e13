// check_metrics: compares metrics.csv tables in the regression tests.
//
//   check_metrics expect FILE CELL COLUMN=VALUE:TOLERANCE...
//       The last row of cell CELL (column "cell") must have |COLUMN - VALUE| <= TOLERANCE.
//       CELL "-": the table of several cells (one row per time, columns NAME_c), last row.
//   check_metrics same FILE_A FILE_B RELATIVE_TOLERANCE
//       Same columns and rows; every number within RELATIVE_TOLERANCE * max(1, |a|, |b|).
//   check_metrics agree FILE_A FILE_B RELATIVE_TOLERANCE COLUMN...
//       At every time both tables hold (two runs with different output intervals), each
//       COLUMN within RELATIVE_TOLERANCE * max(|a|, |b|). Prints the largest difference.
//   check_metrics shifted FILE_A FILE_B COLUMN=OFFSET:TOLERANCE...
//       At every time both tables hold, |COLUMN_a - COLUMN_b - OFFSET| <= TOLERANCE: the same
//       run moved by OFFSET (tests/regression/periodic.cmake). Prints the largest deviation.
//       COLUMN may be NAME_A/NAME_B, a column of each table (in shifted and mirrored): one
//       wall's map against the other wall's, wall_stress_min/wall_stress_min_upper.
//   check_metrics mirrored FILE_A FILE_B COLUMN=SUM:TOLERANCE...
//       At every time both tables hold, |COLUMN_a + COLUMN_b - SUM| <= TOLERANCE: the run
//       reflected about a plane (tests/regression/channel.cmake). Prints the largest deviation.
//   check_metrics within FILE COLUMN=LOW:HIGH...
//       Every row must have LOW <= COLUMN <= HIGH, so also be finite (NaN fails); for the
//       bounds a run must keep all along (tests/regression/stability.cmake). Prints the
//       extremes found.
//
// Prints every comparison; exits 0 if all pass, 1 otherwise, 2 on a usage error.
#include <capsula/core/Error.hpp>
#include <capsula/io/MetricsCsv.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace {

namespace io = capsula::io;

std::size_t columnIndex(const io::CsvTable& table, const std::string& name, const std::string& file)
{
  const auto it = std::find(table.columns.begin(), table.columns.end(), name);
  if (it == table.columns.end()) {
    throw capsula::core::InputError("no column '" + name + "' in " + file);
  }
  return static_cast<std::size_t>(it - table.columns.begin());
}

int expect(int argc, char** argv)
{
  const std::string file = argv[2];
  const bool wholeRows = std::string(argv[3]) == "-";
  const double cell = std::atof(argv[3]);
  const io::CsvTable table = io::readCsvTable(file);
  const std::size_t cellColumn = wholeRows ? 0 : columnIndex(table, "cell", file);
  const std::vector<double>* last = nullptr;
  for (const auto& row : table.rows) {
    if (wholeRows || row[cellColumn] == cell) {
      last = &row;
    }
  }
  if (!last) {
    std::cerr << "no row of cell " << cell << " in " << file << "\n";
    return 1;
  }
  bool ok = true;
  for (int k = 4; k < argc; ++k) {
    const std::string spec = argv[k];
    const auto equals = spec.find('='), colon = spec.find(':');
    if (equals == std::string::npos || colon == std::string::npos || colon < equals) {
      std::cerr << "bad expectation '" << spec << "' (COLUMN=VALUE:TOLERANCE)\n";
      return 2;
    }
    const std::string name = spec.substr(0, equals);
    const double value = std::atof(spec.substr(equals + 1, colon - equals - 1).c_str());
    const double tolerance = std::atof(spec.substr(colon + 1).c_str());
    const double actual = (*last)[columnIndex(table, name, file)];
    const bool pass = std::abs(actual - value) <= tolerance;
    ok = ok && pass;
    std::cout << (pass ? "ok    " : "FAIL  ") << name << " = " << actual << ", expected " << value << " +- "
              << tolerance << "\n";
  }
  return ok ? 0 : 1;
}

int same(char** argv)
{
  const io::CsvTable a = io::readCsvTable(argv[2]);
  const io::CsvTable b = io::readCsvTable(argv[3]);
  const double tolerance = std::atof(argv[4]);
  if (a.columns != b.columns || a.rows.size() != b.rows.size()) {
    std::cout << "FAIL  the tables differ in shape: " << a.rows.size() << " and " << b.rows.size() << " rows\n";
    return 1;
  }
  double worst = 0.0;
  std::string where = "nowhere";
  for (std::size_t r = 0; r < a.rows.size(); ++r) {
    for (std::size_t c = 0; c < a.columns.size(); ++c) {
      const double x = a.rows[r][c], y = b.rows[r][c];
      const double difference = std::abs(x - y) / std::max({1.0, std::abs(x), std::abs(y)});
      if (difference > worst || (std::isnan(x) != std::isnan(y))) {
        worst = std::isnan(x) != std::isnan(y) ? HUGE_VAL : difference;
        where = "row " + std::to_string(r + 1) + " column " + a.columns[c];
      }
    }
  }
  const bool pass = worst <= tolerance;
  std::cout << (pass ? "ok    " : "FAIL  ") << a.rows.size() << " rows, largest relative difference " << worst << " at "
            << where << " (allowed " << tolerance << ")\n";
  return pass ? 0 : 1;
}

int agree(int argc, char** argv)
{
  const io::CsvTable a = io::readCsvTable(argv[2]);
  const io::CsvTable b = io::readCsvTable(argv[3]);
  const double tolerance = std::atof(argv[4]);
  const std::size_t timeA = columnIndex(a, "time", argv[2]), timeB = columnIndex(b, "time", argv[3]);
  bool ok = true;
  for (int k = 5; k < argc; ++k) {
    const std::size_t ca = columnIndex(a, argv[k], argv[2]), cb = columnIndex(b, argv[k], argv[3]);
    double worst = 0.0, worstTime = 0.0;
    int common = 0;
    for (const auto& ra : a.rows) {
      for (const auto& rb : b.rows) {
        if (ra[timeA] != rb[timeB]) {
          continue;
        }
        ++common;
        const double x = ra[ca], y = rb[cb];
        const double difference = x == y ? 0.0 : std::abs(x - y) / std::max(std::abs(x), std::abs(y));
        if (!(difference <= worst)) { // NaN counts as the worst
          worst = difference;
          worstTime = ra[timeA];
        }
      }
    }
    const bool pass = common > 1 && worst <= tolerance;
    ok = ok && pass;
    std::cout << (pass ? "ok    " : "FAIL  ") << argv[k] << " at " << common
              << " common times: largest relative difference " << worst << " at t = " << worstTime << " (allowed "
              << tolerance << ")\n";
  }
  return ok ? 0 : 1;
}

// shifted (sign -1: a - b) and mirrored (sign +1: a + b) against OFFSET.
int combined(int argc, char** argv, double sign)
{
  const io::CsvTable a = io::readCsvTable(argv[2]);
  const io::CsvTable b = io::readCsvTable(argv[3]);
  const std::size_t timeA = columnIndex(a, "time", argv[2]), timeB = columnIndex(b, "time", argv[3]);
  bool ok = true;
  for (int k = 4; k < argc; ++k) {
    const std::string spec = argv[k];
    const auto equals = spec.find('='), colon = spec.rfind(':');
    if (equals == std::string::npos || colon == std::string::npos || colon < equals) {
      std::cerr << "bad expectation '" << spec << "' (COLUMN=OFFSET:TOLERANCE)\n";
      return 2;
    }
    const std::string name = spec.substr(0, equals);
    const double offset = std::atof(spec.substr(equals + 1, colon - equals - 1).c_str());
    const double tolerance = std::atof(spec.substr(colon + 1).c_str());
    const auto slash = name.find('/');
    const std::string nameA = name.substr(0, slash);
    const std::string nameB = slash == std::string::npos ? name : name.substr(slash + 1);
    const std::size_t ca = columnIndex(a, nameA, argv[2]), cb = columnIndex(b, nameB, argv[3]);
    double worst = 0.0, worstTime = 0.0;
    int common = 0;
    for (const auto& ra : a.rows) {
      for (const auto& rb : b.rows) {
        if (ra[timeA] != rb[timeB]) {
          continue;
        }
        ++common;
        const double deviation = std::abs(ra[ca] + sign * rb[cb] - offset);
        if (!(deviation <= worst)) { // NaN counts as the worst
          worst = deviation;
          worstTime = ra[timeA];
        }
      }
    }
    const bool pass = common > 1 && worst <= tolerance;
    ok = ok && pass;
    std::cout << (pass ? "ok    " : "FAIL  ") << name << " at " << common << " common times: largest |a "
              << (sign < 0 ? "-" : "+") << " b - " << offset << "| " << worst << " at t = " << worstTime << " (allowed "
              << tolerance << ")\n";
  }
  return ok ? 0 : 1;
}

int within(int argc, char** argv)
{
  const std::string file = argv[2];
  const io::CsvTable table = io::readCsvTable(file);
  if (table.rows.empty()) {
    std::cerr << "no rows in " << file << "\n";
    return 1;
  }
  bool ok = true;
  for (int k = 3; k < argc; ++k) {
    const std::string spec = argv[k];
    const auto equals = spec.find('='), colon = spec.rfind(':');
    if (equals == std::string::npos || colon == std::string::npos || colon < equals) {
      std::cerr << "bad bound '" << spec << "' (COLUMN=LOW:HIGH)\n";
      return 2;
    }
    const std::string name = spec.substr(0, equals);
    const double low = std::atof(spec.substr(equals + 1, colon - equals - 1).c_str());
    const double high = std::atof(spec.substr(colon + 1).c_str());
    const std::size_t column = columnIndex(table, name, file);
    double smallest = HUGE_VAL, largest = -HUGE_VAL;
    std::size_t bad = 0;
    for (const auto& row : table.rows) {
      const double x = row[column];
      smallest = std::min(smallest, x);
      largest = std::max(largest, x);
      bad += (x >= low && x <= high) ? 0 : 1; // NaN fails both comparisons
    }
    ok = ok && bad == 0;
    std::cout << (bad == 0 ? "ok    " : "FAIL  ") << name << " in [" << smallest << ", " << largest << "] over "
              << table.rows.size() << " rows, allowed [" << low << ", " << high << "]";
    if (bad > 0) {
      std::cout << ", " << bad << " rows outside (or not finite)";
    }
    std::cout << "\n";
  }
  return ok ? 0 : 1;
}

} // namespace

int main(int argc, char** argv)
{
  try {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "expect" && argc >= 5) {
      return expect(argc, argv);
    }
    if (mode == "same" && argc == 5) {
      return same(argv);
    }
    if (mode == "agree" && argc >= 6) {
      return agree(argc, argv);
    }
    if (mode == "shifted" && argc >= 5) {
      return combined(argc, argv, -1.0);
    }
    if (mode == "mirrored" && argc >= 5) {
      return combined(argc, argv, 1.0);
    }
    if (mode == "within" && argc >= 4) {
      return within(argc, argv);
    }
    std::cerr << "usage: check_metrics expect FILE CELL COLUMN=VALUE:TOLERANCE...\n"
                 "       check_metrics same FILE_A FILE_B RELATIVE_TOLERANCE\n"
                 "       check_metrics agree FILE_A FILE_B RELATIVE_TOLERANCE COLUMN...\n"
                 "       check_metrics shifted FILE_A FILE_B COLUMN=OFFSET:TOLERANCE...\n"
                 "       check_metrics mirrored FILE_A FILE_B COLUMN=SUM:TOLERANCE...\n"
                 "       check_metrics within FILE COLUMN=LOW:HIGH...\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "check_metrics: " << e.what() << "\n";
    return 1;
  }
}
