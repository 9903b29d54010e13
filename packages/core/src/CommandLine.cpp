#include "capsula/core/CommandLine.hpp"

#include "capsula/core/Error.hpp"

#include <sstream>

namespace capsula::core {

bool asksForHelp(int argc, const char* const* argv)
{
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (option == "--help" || option == "-h") {
      return true;
    }
  }
  return false;
}

CommandLineOptions parseCommandLine(int argc, const char* const* argv)
{
  CommandLineOptions options;
  const auto valueOf = [&](int& i, const std::string& option) -> std::string {
    require<InputError>(i + 1 < argc, "Option ", option, " needs a value (see --help).");
    // An option in the value's place means the value was forgotten ("--set --output DIR"):
    // taking it as the value would report the wrong mistake (DIR as a second deck).
    const std::string next = argv[i + 1];
    require<InputError>(next.rfind("--", 0) != 0, "Option ", option,
                        " needs a value, but the next argument is the option '", next, "': give ", option,
                        option == "--set" ? " \"List/Sub/Key=value\"" : " DIR", " before it (see --help).");
    return argv[++i];
  };
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    // Accept both "--opt value" and "--opt=value".
    std::string option = arg;
    std::optional<std::string> inlineValue;
    if (arg.rfind("--", 0) == 0) {
      const auto eq = arg.find('=');
      if (eq != std::string::npos) {
        option = arg.substr(0, eq);
        inlineValue = arg.substr(eq + 1);
      }
    }
    const auto take = [&]() { return inlineValue ? *inlineValue : valueOf(i, option); };
    if (option == "--help" || option == "-h") {
      options.help = true;
    } else if (option == "--version") {
      options.version = true;
    } else if (option == "--print-defaults") {
      options.printDefaults = true;
    } else if (option == "--set") {
      options.overrides.push_back(take());
    } else if (option == "--output") {
      options.outputDirectory = take();
    } else if (option == "--restart") {
      options.restartDirectory = take();
    } else if (arg.rfind("-", 0) == 0) {
      throw InputError("Unknown option '" + arg + "'. Run with --help to see the options.");
    } else {
      require<InputError>(options.deckPath.empty(), "Two decks given ('", options.deckPath, "' and '", arg,
                          "'): give one deck; use --set to change single values.");
      options.deckPath = arg;
    }
  }
  return options;
}

std::string usage(const AppDescription& app)
{
  std::ostringstream out;
  out << app.name << ": " << app.summary << "\n\n"
      << "Usage: " << app.name << " DECK.xml [options]\n"
      << "       mpiexec -n 2 " << app.name << " DECK.xml [options]\n\n"
      << "Options:\n"
      << "  --set \"List/Sub/Key=value\"  override one deck value (repeatable; same checks as the deck)\n"
      << "  --output DIR                write results to DIR (overrides Output/Directory)\n";
  if (app.supportsRestart) {
    out << "  --restart DIR               continue the run whose checkpoint is in DIR\n";
  }
  out << "  --print-defaults            print every deck key with its default and meaning, as XML\n"
      << "  --version                   print the version, git SHA and Trilinos version\n"
      << "  --help                      this text\n";
  if (!app.examples.empty()) {
    out << "\nExamples:\n";
    for (const auto& e : app.examples) {
      out << "  " << e << "\n";
    }
  }
  return out.str();
}

} // namespace capsula::core
