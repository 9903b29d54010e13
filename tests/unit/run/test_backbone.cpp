// The run backbone shared by every app: checkpoint sections, RunOutputs and RunSummary.
#include <capsula/core/Error.hpp>
#include <capsula/io/CheckpointSection.hpp>
#include <capsula/io/Json.hpp>
#include <capsula/io/MetricsCsv.hpp>
#include <capsula/core/Deck.hpp>
#include <capsula/core/Interruption.hpp>
#include <capsula/run/IntegrationStateSection.hpp>
#include <capsula/run/RestartDeck.hpp>
#include <capsula/run/RunBackbone.hpp>
#include <capsula/run/RunOutputs.hpp>
#include <capsula/run/RunSummary.hpp>

#include <Teuchos_DefaultSerialComm.hpp>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace core = capsula::core;
namespace io = capsula::io;
namespace run = capsula::run;
namespace ti = capsula::timeint;
namespace fs = std::filesystem;

Teuchos::RCP<const Teuchos::Comm<int>> serial()
{
  return Teuchos::rcp(new Teuchos::SerialComm<int>);
}

fs::path scratch(const std::string& name)
{
  const fs::path path = fs::temp_directory_path() / ("capsula-backbone-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(path);
  return path;
}

std::vector<std::string> keys(const io::JsonValue& object)
{
  std::vector<std::string> names;
  for (const auto& [name, value] : object.members()) {
    names.push_back(name);
  }
  return names;
}

} // namespace

TEST(CheckpointSections, TheIntegrationStateGoesUnderItsPrefixAndComesBackBitForBit)
{
  ti::IntegrationState state;
  state.time = 0.1 + 0.2;
  state.y = {1.0 / 3.0, -2.5};
  state.statistics.acceptedSteps = 7;
  run::IntegrationStateSection section(state, "timeint.");
  io::Checkpoint checkpoint;
  io::saveSections(checkpoint, {&section});
  EXPECT_EQ(checkpoint.arrays.at("timeint.state"), state.y);
  EXPECT_EQ(checkpoint.integers.at("timeint.accepted steps"), 7);

  ti::IntegrationState restored;
  run::IntegrationStateSection into(restored, "timeint.");
  io::loadSections(checkpoint, "test", {&into});
  EXPECT_EQ(restored.time, state.time);
  EXPECT_EQ(restored.y, state.y);
  EXPECT_EQ(restored.statistics.acceptedSteps, 7);

  // Another prefix finds nothing and says which entry it missed, and where.
  ti::IntegrationState other;
  run::IntegrationStateSection unprefixed(other, "");
  try {
    unprefixed.load(checkpoint, "run/checkpoint.h5");
    FAIL() << "loaded a state from entries under another prefix";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("run/checkpoint.h5"), std::string::npos) << e.what();
  }
}

TEST(CheckpointSections, AMissingEntryIsNamed)
{
  io::Checkpoint checkpoint;
  checkpoint.reals["present"] = 1.5;
  EXPECT_EQ(io::requiredReal(checkpoint, "present", "c.h5"), 1.5);
  EXPECT_EQ(io::optionalArray(checkpoint, "absent"), nullptr);
  try {
    io::requiredInteger(checkpoint, "run stage", "c.h5");
    FAIL() << "a missing entry was accepted";
  } catch (const core::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'run stage'"), std::string::npos) << what;
    EXPECT_NE(what.find("c.h5"), std::string::npos) << what;
  }
}

TEST(RunSummary, OneLayoutForEveryApp)
{
  Teuchos::ParameterList deck("app");
  deck.sublist("Flow").set("Capillary number", 0.3);
  run::RunSummary summary("app", deck, 1);
  ti::IntegrationStatistics statistics;
  statistics.acceptedSteps = 12;
  statistics.rejectedSteps = 3;
  statistics.rhsEvaluations = 80;
  summary.begin(statistics, true);
  summary.setTerms({"a term"});
  statistics.rhsEvaluations = 100;
  const io::JsonValue json =
      summary.json("failed", "it broke", 2.5, statistics, [](io::JsonValue& j) { j["result"] = 1.0; });
  EXPECT_EQ(keys(json), (std::vector<std::string>{"application", "status", "failure", "time", "version", "ranks",
                                                  "restarted", "terms", "steps", "result", "timings", "deck"}));
  io::JsonValue copy = json;
  EXPECT_EQ(keys(copy["version"]), (std::vector<std::string>{"capsula", "git sha", "trilinos"}));
  EXPECT_EQ(copy["steps"]["accepted"].asInteger(), 12);
  EXPECT_EQ(copy["steps"]["rejected"].asInteger(), 3);
  EXPECT_EQ(copy["steps"]["rhs evaluations"].asInteger(), 100);
  EXPECT_EQ(copy["failure"].asString(), "it broke");
  EXPECT_TRUE(copy["restarted"].asBoolean());
  // The rate per right-hand side counts this process's 20 evaluations only.
  EXPECT_NEAR(copy["timings"]["seconds per rhs evaluation (this process)"].asNumber(),
              copy["timings"]["wall seconds (this process)"].asNumber() / 20.0, 1e-3);
  // A run that stopped early gives its reason under another key.
  io::JsonValue early = summary.json("too close", "they met", 1.0, statistics, {});
  EXPECT_EQ(early["stop reason"].asString(), "they met");
}

TEST(RunSummary, PeakMemoryOnceRecordedHasOnePositiveEntryPerRank)
{
  Teuchos::ParameterList deck("app");
  const Teuchos::SerialComm<int> comm;
  run::RunSummary summary("app", deck, comm.getSize());
  ti::IntegrationStatistics statistics;
  summary.begin(statistics, false);
  summary.recordPeakMemory(comm);
  io::JsonValue json = summary.json("running", "", 0.0, statistics, {});
  const std::vector<std::string> names = keys(json);
  ASSERT_GE(names.size(), 2u);
  EXPECT_EQ(names[names.size() - 2], "peak memory (MiB) per rank"); // just before the deck
  const auto& perRank = json["peak memory (MiB) per rank"].items();
  ASSERT_EQ(perRank.size(), static_cast<std::size_t>(comm.getSize()));
  EXPECT_GT(perRank[0].asNumber(), 0.0);
}

TEST(RunOutputs, WithoutADirectoryNothingIsWritten)
{
  const fs::path cwd = fs::current_path();
  run::RunOutputs outputs(serial(), "", std::nullopt);
  EXPECT_FALSE(outputs.writing());
  outputs.openTable("metrics.csv", {"time", "x"});
  outputs.appendRow("metrics.csv", {0.0, 1.0});
  outputs.writeSummary([] { return io::JsonValue::object(); });
  EXPECT_FALSE(fs::exists(cwd / "metrics.csv"));
  EXPECT_FALSE(fs::exists(cwd / "summary.json"));
}

TEST(RunOutputs, ARestartIntoAnotherDirectoryCarriesTheTablesOver)
{
  const fs::path first = scratch("first"), second = scratch("second");
  Teuchos::ParameterList deck("app");
  {
    run::RunOutputs outputs(serial(), first.string(), std::nullopt);
    outputs.open(deck, {"app", "", 1});
    outputs.openTable("metrics.csv", {"time", "x"});
    for (double t : {0.0, 0.5, 1.0}) {
      outputs.appendRow("metrics.csv", {t, 2.0 * t});
    }
  }
  // Continued from a checkpoint at t = 0.5: the row the stopped run wrote after it goes.
  run::RunOutputs outputs(serial(), second.string(), first.string());
  outputs.open(deck, {"app", "", 1});
  outputs.openTable("metrics.csv", {"time", "x"}, 0.5);
  outputs.appendRow("metrics.csv", {0.75, 1.5});
  const io::CsvTable table = io::readCsvTable((second / "metrics.csv").string());
  ASSERT_EQ(table.rows.size(), 3u);
  EXPECT_EQ(table.rows[2], (std::vector<double>{0.75, 1.5}));
  EXPECT_EQ(io::readCsvTable((first / "metrics.csv").string()).rows.size(), 3u); // untouched
  fs::remove_all(first);
  fs::remove_all(second);
}

namespace {

// A model of one state section whose last output was at t = 0.75 and whose result is 42.
class ModelOfOneSection final : public run::RunModel {
public:
  explicit ModelOfOneSection(ti::IntegrationState& state) : section_(state, "timeint.") {}
  std::vector<io::CheckpointSection*> checkpointSections() override { return {&section_}; }
  void addResults(io::JsonValue& json) const override { json["result"] = 42.0; }
  double lastOutputTime() const override { return 0.75; }

private:
  run::IntegrationStateSection section_;
};

std::string fileText(const fs::path& path)
{
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

} // namespace

// What the backbone writes for every app: "running" from begin(), then a failure recorded
// with its message, the model's last output time and results, and rethrown; an interruption
// passes through without a "failed" summary (the backbone's stopInterrupted writes its own).
TEST(RunBackbone, AFailureIsRecordedWithTheModelsResultsAndRethrown)
{
  const fs::path directory = scratch("failure");
  Teuchos::ParameterList deck("app");
  deck.sublist("Flow").set("Capillary number", 0.3);
  ti::IntegrationState state;
  ti::TimeIntegrator integrator(ti::TimeIntegrationSettings{},
                                [](double, const std::vector<double>& y, std::vector<double>& dydt) { dydt = y; });
  ModelOfOneSection model(state);
  run::RunBackbone backbone({"app", "", directory.string(), std::nullopt}, deck, serial(), model, integrator, state,
                            nullptr);
  EXPECT_FALSE(backbone.restarting());
  backbone.open();
  backbone.begin({"a term"});
  EXPECT_NE(fileText(directory / "summary.json").find("\"status\": \"running\""), std::string::npos);
  EXPECT_THROW(backbone.recordingFailure([] { throw core::Interrupted(15, "stopped"); }), core::Interrupted);
  EXPECT_NE(fileText(directory / "summary.json").find("\"status\": \"running\""), std::string::npos);
  EXPECT_THROW(backbone.recordingFailure([] { throw core::NumericalError("it broke"); }), core::NumericalError);
  const std::string summary = fileText(directory / "summary.json");
  for (const char* entry : {"\"status\": \"failed\"", "\"failure\": \"it broke\"", "\"time\": 0.75", "\"result\": 42",
                            "\"in use\"", "a term"}) {
    EXPECT_NE(summary.find(entry), std::string::npos) << entry << " in\n" << summary;
  }
  fs::remove_all(directory);
}

// A restart: the model's sections come back from the checkpoint; one at the end time has
// nothing to do, and says so in the model's time.
TEST(RunBackbone, ARestartLoadsTheModelsSectionsAndNeedsTimeLeft)
{
  const fs::path directory = scratch("restart");
  fs::create_directories(directory);
  Teuchos::ParameterList deck("app");
  deck.sublist("Time integration").set("End time", 0.5);
  ti::IntegrationState saved;
  saved.time = 0.5;
  saved.y = {1.0 / 3.0};
  run::IntegrationStateSection section(saved, "timeint.");
  io::Checkpoint checkpoint;
  checkpoint.application = "app";
  checkpoint.deckXml = core::deckToXml(deck, false);
  io::saveSections(checkpoint, {&section});
  io::writeCheckpoint(run::checkpointPath(directory.string()), checkpoint);

  ti::IntegrationState state;
  ti::TimeIntegrator integrator(ti::TimeIntegrationSettings{},
                                [](double, const std::vector<double>& y, std::vector<double>& dydt) { dydt = y; });
  ModelOfOneSection model(state);
  run::RunBackbone backbone({"app", "", directory.string(), directory.string()}, deck, serial(), model, integrator,
                            state, nullptr);
  ASSERT_TRUE(backbone.restarting());
  backbone.restore();
  EXPECT_EQ(state.y, saved.y);
  EXPECT_EQ(state.time, 0.5);
  backbone.requireTimeLeft(0.25, 0.5);
  try {
    backbone.requireTimeLeft(state.time, 0.5);
    FAIL() << "a restart at the end time was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the checkpoint is at t = 0.5, at or past 'Time integration/End time' = 0.5"),
              std::string::npos)
        << e.what();
  }
  fs::remove_all(directory);
}
