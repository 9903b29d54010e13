// The output directory and the run record (validated deck, versions, git SHA).
#include "TemporaryDirectory.hpp"

#include "capsula/core/Deck.hpp"
#include "capsula/core/Error.hpp"
#include "capsula/core/ParameterDeclaration.hpp"
#include "capsula/core/RunInfo.hpp"
#include "capsula/io/OutputDirectory.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace io = capsula::io;
namespace core = capsula::core;
using io::testing::TemporaryDirectory;

TEST(OutputDirectory, CreatesTheDirectoryAndRecordsTheRun)
{
  TemporaryDirectory dir("outdir_record");
  const std::string path = (dir.path() / "runs" / "case 1").string();
  const io::OutputDirectory out(path);
  EXPECT_TRUE(std::filesystem::is_directory(path));
  EXPECT_EQ(out.file("metrics.csv"), path + "/metrics.csv");

  auto valid = Teuchos::rcp(new Teuchos::ParameterList("Capsula"));
  auto& flow = core::declareSublist(*valid, "Flow", "Ambient flow");
  core::declareReal(flow, "Capillary number", 0.3, "Ca", core::greaterThan(0.0));
  auto deck = core::readDeckFromString(
      R"(<ParameterList name="Capsula"><ParameterList name="Flow"><Parameter name="Capillary number" type="double" value="0.9"/></ParameterList></ParameterList>)",
      "case1.xml");
  core::validateDeck(*deck, *valid, "case1.xml");
  out.writeRunMetadata(*deck, {"cell3d", "decks/case1.xml", 4});

  const auto reread = core::readDeck(out.file("deck.xml"));
  EXPECT_EQ(reread->sublist("Flow").get<double>("Capillary number"), 0.9);
  const std::string run = io::testing::readText(out.file("run.json"));
  EXPECT_TRUE(io::testing::contains(run, "\"git sha\": \"" + core::gitSha() + "\"")) << run;
  EXPECT_TRUE(io::testing::contains(run, "\"trilinos version\": \"" + core::trilinosVersion() + "\"")) << run;
  EXPECT_TRUE(io::testing::contains(run, "\"application\": \"cell3d\"")) << run;
  EXPECT_TRUE(io::testing::contains(run, "\"deck\": \"decks/case1.xml\"")) << run;
  EXPECT_TRUE(io::testing::contains(run, "\"ranks\": 4")) << run;
}

TEST(OutputDirectory, UnwritableDirectoryIsNamed)
{
  TemporaryDirectory dir("outdir_unwritable");
  std::ofstream(dir.file("a-file")) << "x";
  const std::string target = dir.file("a-file") + "/out";
  try {
    io::OutputDirectory out(target);
    FAIL() << "a directory below a regular file was accepted";
  } catch (const core::IoError& e) {
    EXPECT_TRUE(io::testing::contains(e.what(), "'" + target + "'")) << e.what();
  }
}
