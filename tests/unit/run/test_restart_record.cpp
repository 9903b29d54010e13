#include <capsula/core/Error.hpp>
#include <capsula/io/Checkpoint.hpp>
#include <capsula/run/MethodSwitchRecord.hpp>
#include <capsula/run/RestartRecord.hpp>

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace core = capsula::core;
namespace io = capsula::io;
namespace run = capsula::run;
namespace fs = std::filesystem;

// The message of the InputError `f` throws, or "" if it throws none.
template <typename F>
std::string restartRefusal(F&& f)
{
  try {
    f();
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "";
}

} // namespace

// Auto's switches go into the checkpoint and come back with their times and reasons, text
// and all (a reason holds digits, ';' and '='), in order; a run without switches adds
// nothing, and its checkpoint restores none.
TEST(MethodSwitchRecord, SwitchesComeBackFromTheCheckpoint)
{
  run::MethodSwitchRecord record;
  record.add(0.0035, "switched to ROS34PW2: the stability limit held RKF45 at dt = 0.000703 for 5 steps");
  record.add(0.25, "back to RKF45; it advances 2.1 x further per application");
  io::Checkpoint checkpoint;
  record.save(checkpoint);
  run::MethodSwitchRecord restored;
  restored.add(9.0, "a switch of another run, replaced on load");
  restored.load(checkpoint, "test.h5");
  EXPECT_EQ(restored.switches(), record.switches());

  io::Checkpoint none;
  run::MethodSwitchRecord().save(none);
  EXPECT_TRUE(none.arrays.empty());
  restored.load(none, "test.h5");
  EXPECT_TRUE(restored.switches().empty());
}

// A restart directory whose metrics.csv is missing, or holds another number of rows up to
// the checkpoint than the run wrote, is refused naming the file; rows after the checkpoint
// (written before a kill) are not counted.
TEST(RestartRecord, AMissingOrDamagedTableIsRefused)
{
  const fs::path dir = fs::temp_directory_path() / ("capsula_restart_record_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const auto table = [&](const std::string& rows) { std::ofstream(dir / "metrics.csv") << "time,D12\n" << rows; };
  const auto check = [&](std::int64_t written) {
    return restartRefusal([&] { run::requireTableUpToCheckpoint(dir.string(), "metrics.csv", 0.5, written); });
  };
  table("0,0\n0.25,0.1\n0.5,0.2\n0.75,0.3\n");
  EXPECT_EQ(check(3), "");
  const std::string gap = check(4);
  EXPECT_NE(gap.find("metrics.csv' holds 3 rows up to the checkpoint at t = 0.5, where the run wrote 4"),
            std::string::npos)
      << gap;
  fs::remove(dir / "metrics.csv");
  const std::string missing = check(3);
  EXPECT_NE(missing.find("metrics.csv' is missing; the checkpoint at t = 0.5 continues its 3 rows"), std::string::npos)
      << missing;
  fs::remove_all(dir);
}
