// Metrics CSV: exact round trip, always-complete file, restart without duplicate rows.
#include "TemporaryDirectory.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/io/MetricsCsv.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace io = capsula::io;
namespace core = capsula::core;
using io::testing::TemporaryDirectory;

namespace {
bool sameBits(double a, double b)
{
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}
} // namespace

TEST(MetricsCsv, NumbersRoundTripBitForBit)
{
  TemporaryDirectory dir("csv_roundtrip");
  const std::string path = dir.file("metrics.csv");
  const std::vector<double> values = {0.1,
                                      1.0 / 3.0,
                                      -2.5e10,
                                      1e-300,
                                      std::numeric_limits<double>::denorm_min(),
                                      std::numeric_limits<double>::max(),
                                      -0.0,
                                      std::numeric_limits<double>::infinity(),
                                      -std::numeric_limits<double>::infinity(),
                                      std::nextafter(1.0, 2.0)};
  std::vector<std::string> columns = {"time"};
  for (std::size_t i = 1; i < values.size(); ++i) {
    columns.push_back("m" + std::to_string(i));
  }
  io::MetricsCsv csv(path, columns);
  csv.appendRow(values);
  std::vector<double> withNan(values.size(), 2.0);
  withNan[3] = std::numeric_limits<double>::quiet_NaN();
  csv.appendRow(withNan);

  const auto table = io::readCsvTable(path);
  EXPECT_EQ(table.columns, columns);
  ASSERT_EQ(table.rows.size(), 2u);
  for (std::size_t i = 0; i < values.size(); ++i) {
    EXPECT_TRUE(sameBits(table.rows[0][i], values[i])) << "column " << i << ": " << values[i];
  }
  EXPECT_TRUE(std::isnan(table.rows[1][3]));
  // The shortest round-trip form is also the readable one.
  EXPECT_TRUE(io::testing::contains(io::testing::readText(path), "\n0.1,0.3333333333333333,-2.5e+10,1e-300,"));
}

TEST(MetricsCsv, FileIsCompleteAfterEveryRowAndNoTemporaryIsLeft)
{
  TemporaryDirectory dir("csv_complete");
  const std::string path = dir.file("metrics.csv");
  io::MetricsCsv csv(path, {"time", "D12"});
  EXPECT_EQ(io::readCsvTable(path).rows.size(), 0u); // header written at once
  for (int k = 0; k < 5; ++k) {
    csv.appendRow({0.5 * k, 0.01 * k});
    const auto table = io::readCsvTable(path);
    ASSERT_EQ(table.rows.size(), static_cast<std::size_t>(k + 1));
    EXPECT_EQ(table.rows.back()[0], 0.5 * k);
    EXPECT_EQ(dir.entryCount(), 1u);
  }
}

TEST(MetricsCsv, RestartContinuesTheFileWithoutDuplicateRows)
{
  TemporaryDirectory dir("csv_restart");
  const std::vector<std::string> columns = {"time", "x", "steps"};
  const auto row = [](int k) { return std::vector<double>{0.25 * k, std::sin(0.25 * k), 7.0 * k}; };

  // The uninterrupted run: outputs k = 0..12.
  const std::string reference = dir.file("reference.csv");
  {
    io::MetricsCsv csv(reference, columns);
    for (int k = 0; k <= 12; ++k) {
      csv.appendRow(row(k));
    }
  }
  // A run that checkpointed at output 6 (t = 1.5), wrote outputs 7..9, and died.
  const std::string path = dir.file("metrics.csv");
  {
    io::MetricsCsv csv(path, columns);
    for (int k = 0; k <= 9; ++k) {
      csv.appendRow(row(k));
    }
  }
  // The restarted run continues from the checkpoint and recomputes outputs 7..12.
  auto csv = io::MetricsCsv::resume(path, columns, 1.5);
  EXPECT_EQ(csv.rowCount(), 7u);
  for (int k = 7; k <= 12; ++k) {
    csv.appendRow(row(k));
  }
  EXPECT_EQ(io::testing::readText(path), io::testing::readText(reference));
  const auto table = io::readCsvTable(path);
  for (std::size_t i = 1; i < table.rows.size(); ++i) {
    EXPECT_GT(table.rows[i][0], table.rows[i - 1][0]) << "row " << i;
  }
}

TEST(MetricsCsv, RestartRefusesAMissingFileOrOtherColumns)
{
  TemporaryDirectory dir("csv_refuse");
  const std::string path = dir.file("metrics.csv");
  try {
    io::MetricsCsv::resume(path, {"time"}, 1.0);
    FAIL() << "a missing table was accepted";
  } catch (const core::IoError& e) {
    EXPECT_TRUE(io::testing::contains(e.what(), path)) << e.what();
  }
  {
    io::MetricsCsv csv(path, {"time", "D12"});
  }
  try {
    io::MetricsCsv::resume(path, {"time", "D13"}, 1.0);
    FAIL() << "a table with other columns was accepted";
  } catch (const core::IoError& e) {
    EXPECT_TRUE(io::testing::contains(e.what(), path)) << e.what();
    EXPECT_TRUE(io::testing::contains(e.what(), "time,D12")) << e.what();
  }
}

TEST(MetricsCsv, MalformedTableNamesFileAndLine)
{
  TemporaryDirectory dir("csv_malformed");
  const std::string path = dir.file("metrics.csv");
  std::ofstream(path) << "time,D12\n0,0.1\n0.5,zero\n";
  try {
    io::readCsvTable(path);
    FAIL() << "a malformed table was accepted";
  } catch (const core::IoError& e) {
    EXPECT_TRUE(io::testing::contains(e.what(), path)) << e.what();
    EXPECT_TRUE(io::testing::contains(e.what(), "line 3")) << e.what();
    EXPECT_TRUE(io::testing::contains(e.what(), "'D12'")) << e.what();
  }
}

TEST(MetricsCsv, UnwritableDirectoryIsNamed)
{
  TemporaryDirectory dir("csv_unwritable");
  std::ofstream(dir.file("a-file")) << "x";
  const std::string path = dir.file("a-file") + "/metrics.csv";
  try {
    io::MetricsCsv csv(path, {"time"});
    FAIL() << "a table below a regular file was created";
  } catch (const core::IoError& e) {
    EXPECT_TRUE(io::testing::contains(e.what(), path)) << e.what();
  }
}
