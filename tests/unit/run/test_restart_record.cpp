#include <capsula/core/Error.hpp>
#include <capsula/core/Deck.hpp>
#include <capsula/io/Checkpoint.hpp>
#include <capsula/run/MethodSwitchRecord.hpp>
#include <capsula/run/RestartDeck.hpp>
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

namespace {

// A deck of the shape every app has: a physical key, the end time and the output directory.
Teuchos::ParameterList restartDeck(double capillaryNumber, double endTime, const std::string& directory)
{
  Teuchos::ParameterList deck("app");
  deck.sublist("Flow").set("Capillary number", capillaryNumber);
  deck.sublist("Flow").set("Viscosity ratio", 1.0);
  deck.sublist("Time integration").set("End time", endTime);
  deck.sublist("Output").set("Directory", directory);
  return deck;
}

} // namespace

// The restart check every app runs (tether2d once went on with a changed Capillary number):
// a changed key is refused with its full path and both values; End time and Output/Directory
// may change; a key only one deck has is a change too.
TEST(RestartDeck, AChangedKeyIsRefusedNamingItAndBothValues)
{
  const std::string then = capsula::core::deckToXml(restartDeck(0.25, 0.2, "out/a"), false);
  EXPECT_EQ(restartRefusal([&] { run::requireSameRun(restartDeck(0.25, 0.4, "out/b"), then, "c.h5"); }), "");
  const std::string changed =
      restartRefusal([&] { run::requireSameRun(restartDeck(0.05, 0.4, "out/a"), then, "c.h5"); });
  EXPECT_NE(changed.find("Cannot restart from 'c.h5': the deck differs from the one the run was started with at "
                         "'Flow/Capillary number': the run was written with Flow/Capillary number = 0.25 but the "
                         "deck has 0.05. Only 'Time integration/End time' and 'Output/Directory' may change"),
            std::string::npos)
      << changed;
  Teuchos::ParameterList extra = restartDeck(0.25, 0.2, "out/a");
  extra.sublist("Flow").set("Shear rate", 2.0);
  const std::string added = restartRefusal([&] { run::requireSameRun(extra, then, "c.h5"); });
  EXPECT_NE(added.find("at 'Flow/Shear rate': the run was written with Flow/Shear rate = (absent) but the deck has 2"),
            std::string::npos)
      << added;
}

// A checkpoint of another application is refused naming both; the key check runs on what
// readRestartCheckpoint reads, before any caller writes.
TEST(RestartDeck, ReadRestartCheckpointChecksTheApplicationAndTheDeck)
{
  const fs::path dir = fs::temp_directory_path() / ("capsula_restart_deck_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  io::Checkpoint checkpoint;
  checkpoint.application = "tether2d";
  checkpoint.deckXml = capsula::core::deckToXml(restartDeck(0.25, 0.2, ""), false);
  checkpoint.reals["x"] = 1.0;
  io::writeCheckpoint(run::checkpointPath(dir.string()), checkpoint);
  const auto read = [&](const std::string& application, double capillaryNumber) {
    return restartRefusal(
        [&] { run::readRestartCheckpoint(dir.string(), application, restartDeck(capillaryNumber, 0.5, "")); });
  };
  EXPECT_EQ(read("tether2d", 0.25), "");
  EXPECT_NE(read("cell3d", 0.25).find("it is a checkpoint of tether2d, not of cell3d"), std::string::npos);
  EXPECT_NE(read("tether2d", 0.05).find("at 'Flow/Capillary number'"), std::string::npos);
  fs::remove_all(dir);
  EXPECT_NE(read("tether2d", 0.25).find("--restart " + dir.string() + ": "), std::string::npos);
}
