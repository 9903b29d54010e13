#pragma once
// The skeleton every Capsula app shares, so that apps stay thin:
// parse the command line, answer --help/--version/--print-defaults, read the
// deck, apply --set overrides, validate (validateParametersAndSetDefaults) and
// hand a ready RunContext to the app's run function; report errors uniformly
// and print the timer summary at the end.
#include "capsula/core/CommandLine.hpp"
#include "capsula/core/Deck.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <iosfwd>
#include <string>

namespace capsula::core {

struct RunContext {
  Teuchos::RCP<const Teuchos::Comm<int>> comm;
  Teuchos::RCP<Teuchos::ParameterList> deck; ///< validated, defaults filled in
  std::string deckName;                      ///< the file it came from
  CommandLineOptions options;
  std::ostream* out = nullptr; ///< rank 0: stdout; other ranks: a black hole
};

/// Runs an app. Must be called from main() before MPI is initialised (it owns
/// MPI and Kokkos through Tpetra::ScopeGuard). Returns the process exit code:
/// 0 on success, 1 on an error (the message is printed on stderr), 2 on a usage error.
int runApplication(int argc, char** argv, const AppDescription& app, const ValidParameterBuilder& validParameters,
                   const std::function<void(RunContext&)>& run);

} // namespace capsula::core
