#pragma once
// The command line shared by every Capsula app:
//
//   APP DECK.xml [--set "List/Sub/Key=value"]... [--output DIR] [--restart DIR]
//       [--print-defaults] [--help] [--version]
#include <optional>
#include <string>
#include <vector>

namespace capsula::core {

struct CommandLineOptions {
  std::string deckPath;               ///< empty if none was given
  std::vector<std::string> overrides; ///< each "List/Sub/Key=value", in order
  std::optional<std::string> outputDirectory;
  std::optional<std::string> restartDirectory;
  bool printDefaults = false;
  bool help = false;
  bool version = false;
};

/// Whether argv asks for --help (or -h). Programs answer it before MPI and Kokkos start:
/// Kokkos takes --help too and would print its own option list instead.
bool asksForHelp(int argc, const char* const* argv);

/// Parses argv (argv[0] is the program). Throws InputError naming the bad option.
CommandLineOptions parseCommandLine(int argc, const char* const* argv);

/// What an app says about itself in --help.
struct AppDescription {
  std::string name;                  ///< e.g. "cell3d"
  std::string summary;               ///< one line
  std::vector<std::string> examples; ///< full command lines
  bool supportsRestart = false;      ///< --restart; also: SIGTERM/SIGINT stop it cleanly
};

/// The --help text.
std::string usage(const AppDescription& app);

} // namespace capsula::core
