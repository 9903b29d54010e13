// The command line shared by every app.
#include "capsula/core/CommandLine.hpp"
#include "capsula/core/DeckValidators.hpp"
#include "capsula/core/Error.hpp"

#include <gtest/gtest.h>

namespace core = capsula::core;

namespace {
core::CommandLineOptions parse(std::vector<const char*> args)
{
  args.insert(args.begin(), "app");
  return core::parseCommandLine(static_cast<int>(args.size()), args.data());
}

std::string commandLineErrorOf(std::vector<const char*> args)
{
  try {
    parse(std::move(args));
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "no error";
}
} // namespace

TEST(CommandLine, ParsesEveryOption)
{
  const auto o = parse({"deck.xml", "--set", "Flow/Capillary number=0.3", "--set=Wall/Enabled=false", "--output", "out",
                        "--restart=old"});
  EXPECT_EQ(o.deckPath, "deck.xml");
  ASSERT_EQ(o.overrides.size(), 2u);
  EXPECT_EQ(o.overrides[0], "Flow/Capillary number=0.3");
  EXPECT_EQ(o.overrides[1], "Wall/Enabled=false");
  EXPECT_EQ(o.outputDirectory.value(), "out");
  EXPECT_EQ(o.restartDirectory.value(), "old");
  EXPECT_FALSE(o.help);
  EXPECT_TRUE(parse({"--help"}).help);
  EXPECT_TRUE(parse({"--version"}).version);
  EXPECT_TRUE(parse({"--print-defaults"}).printDefaults);
}

TEST(CommandLine, BadUsageIsExplained)
{
  EXPECT_NE(commandLineErrorOf({"deck.xml", "--frobnicate"}).find("Unknown option '--frobnicate'"), std::string::npos);
  EXPECT_NE(commandLineErrorOf({"deck.xml", "--output"}).find("Option --output needs a value"), std::string::npos);
  EXPECT_NE(commandLineErrorOf({"a.xml", "b.xml"}).find("Two decks given ('a.xml' and 'b.xml')"), std::string::npos);
}

TEST(CommandLine, UsageListsOptionsAndExamples)
{
  core::AppDescription app{"cell3d", "one cell near a wall", {"cell3d input/demo.xml"}, true};
  const std::string text = core::usage(app);
  for (const char* piece : {"--set", "--output", "--restart", "--print-defaults", "--version", "cell3d input/demo.xml",
                            "mpiexec -n 2 cell3d"}) {
    EXPECT_NE(text.find(piece), std::string::npos) << piece;
  }
}

// The apps and the benches answer --help before MPI and Kokkos start (Kokkos answers it with
// its own option list): the check finds --help or -h anywhere, and nothing else.
TEST(CommandLine, AsksForHelpFindsHelpAnywhere)
{
  const auto asks = [](std::vector<const char*> args) {
    args.insert(args.begin(), "app");
    return core::asksForHelp(static_cast<int>(args.size()), args.data());
  };
  EXPECT_TRUE(asks({"--help"}));
  EXPECT_TRUE(asks({"deck.xml", "--set", "Flow/Capillary number=0.3", "-h"}));
  EXPECT_TRUE(asks({"--level=2", "--help", "--kernel=Wall"}));
  EXPECT_FALSE(asks({}));
  EXPECT_FALSE(asks({"deck.xml", "--helpful", "--kokkos-help=false", "-hh"}));
}

TEST(CommandLine, ClosestMatchFindsTyposOnly)
{
  EXPECT_EQ(core::editDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(core::closestMatch("Skalack", {"NeoHookean", "Skalak"}).value(), "Skalak");
  EXPECT_FALSE(core::closestMatch("Mooney", {"NeoHookean", "Skalak"}).has_value());
}
