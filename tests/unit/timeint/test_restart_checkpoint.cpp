// Restart through an HDF5 checkpoint file (io::Checkpoint) reproduces the uninterrupted
// run bit for bit: the glue an app needs between timeint::toRecord and io::Checkpoint.
#include "capsula/io/Checkpoint.hpp"
#include "capsula/timeint/TimeIntegrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

#include <unistd.h>

namespace ti = capsula::timeint;
namespace io = capsula::io;

TEST(RestartThroughCheckpointFile, ReproducesTheUninterruptedRunBitForBit)
{
  const auto dir = std::filesystem::temp_directory_path() / ("capsula_timeint_restart_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "checkpoint.h5").string();

  // Three "cells" of two coupled oscillators each: a state vector of 12 coordinates.
  const ti::RightHandSide rhs = [](double t, const std::vector<double>& y, std::vector<double>& f) {
    for (std::size_t i = 0; i < y.size(); i += 2) {
      f[i] = y[i + 1];
      f[i + 1] = (1.0 - y[i] * y[i]) * y[i + 1] - y[i] + 0.1 * std::sin(t + static_cast<double>(i));
    }
  };
  ti::TimeIntegrationSettings settings;
  settings.method = "DormandPrince45";
  settings.tolerance = 1e-9;
  settings.endTime = 8.0;
  const ti::OutputSchedule schedule{0.5, true};
  const std::vector<double> y0 = {2, 0, 1, 1, -1, 0.5, 0.3, 0, 1.5, -1, 0, 2};

  ti::TimeIntegrator uninterrupted(settings, rhs);
  auto full = uninterrupted.start(0.0, y0);
  uninterrupted.integrate(full, schedule, {[&](const ti::IntegrationState& state, ti::OutputReason) {
                            if (state.time == 3.0) { // the app's checkpoint observer
                              const auto record = ti::toRecord(state);
                              io::Checkpoint c;
                              c.time = state.time;
                              c.step = state.statistics.acceptedSteps;
                              c.stepSize = state.proposedStep;
                              c.deckXml = "<ParameterList name=\"Capsula\"/>";
                              c.reals = record.reals;
                              c.integers = record.integers;
                              c.arrays = record.arrays;
                              io::writeCheckpoint(path, c);
                            }
                          }});

  const io::Checkpoint c = io::readCheckpoint(path);
  auto resumed = ti::fromRecord({c.reals, c.integers, c.arrays}, path);
  EXPECT_EQ(resumed.time, 3.0);
  ti::TimeIntegrator restarted(settings, rhs);
  restarted.integrate(resumed, schedule, {});

  ASSERT_EQ(resumed.y.size(), full.y.size());
  EXPECT_EQ(std::memcmp(resumed.y.data(), full.y.data(), full.y.size() * sizeof(double)), 0);
  EXPECT_EQ(resumed.time, full.time);
  EXPECT_EQ(resumed.statistics.acceptedSteps, full.statistics.acceptedSteps);
  EXPECT_EQ(resumed.statistics.rejectedSteps, full.statistics.rejectedSteps);
  EXPECT_EQ(resumed.statistics.rhsEvaluations, full.statistics.rhsEvaluations);
  std::filesystem::remove_all(dir);
}
