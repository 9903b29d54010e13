#include "capsula/core/Application.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/core/MpiSessionDirectory.hpp"
#include "capsula/core/RunInfo.hpp"
#include "capsula/core/Timers.hpp"

#include <Teuchos_oblackholestream.hpp>
#include <Tpetra_Core.hpp>

#include <iostream>
#include <string>
#include <mpi.h>

namespace capsula::core {

namespace {

Teuchos::RCP<Teuchos::ParameterList> loadDeck(const CommandLineOptions& options,
                                              const ValidParameterBuilder& validParameters, std::string& deckName)
{
  require<InputError>(!options.deckPath.empty(), "No deck given. Usage: APP DECK.xml [options]; ",
                      "run with --help for examples or --print-defaults for every key.");
  deckName = options.deckPath;
  auto deck = readDeck(options.deckPath);
  // Overrides are typed by the valid list of the deck as read, then the whole
  // deck (overrides included) is validated against the list rebuilt from it.
  for (const auto& assignment : options.overrides) {
    applyOverride(*deck, *validParameters(*deck), assignment);
  }
  const auto valid = validParameters(*deck);
  validateDeck(*deck, *valid, deckName);
  return deck;
}

} // namespace

int runApplication(int argc, char** argv, const AppDescription& app, const ValidParameterBuilder& validParameters,
                   const std::function<void(RunContext&)>& run)
{
  // --help is answered before Kokkos starts: Kokkos also takes --help and would print its
  // own forty lines of options above ours.
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
      std::cout << usage(app);
      return 0;
    }
  }
  const MpiSessionDirectory sessionDirectory; // outlives MPI (declared before the scope guard)
  Tpetra::ScopeGuard tpetraScope(&argc, &argv);
  const auto comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  Teuchos::oblackholestream blackHole;
  std::ostream& out = root ? std::cout : blackHole;

  RunContext context;
  context.comm = comm;
  context.out = &out;
  try {
    context.options = parseCommandLine(argc, argv);
    if (context.options.help) {
      out << usage(app);
      return 0;
    }
    if (context.options.version) {
      out << app.name << ": " << versionLine() << "\n";
      return 0;
    }
    if (context.options.printDefaults) {
      Teuchos::ParameterList empty("Capsula");
      auto valid = Teuchos::rcp(new Teuchos::ParameterList(*validParameters(empty)));
      valid->setName(app.name);
      out << deckToXml(*valid, true);
      return 0;
    }
    context.deck = loadDeck(context.options, validParameters, context.deckName);
    out << app.name << ": " << versionLine() << ", " << comm->getSize() << " rank(s)\n";
    run(context);
    printTimerSummary(*comm, out);
    return 0;
  } catch (const InputError& e) {
    // Input is read and checked identically on every rank: all ranks fail here
    // together, so one message from rank 0 is enough and no rank is left waiting.
    if (root) {
      std::cerr << app.name << ": error: " << e.what() << "\n";
    }
    return 2;
  } catch (const std::exception& e) {
    std::cerr << app.name << ": error";
    if (comm->getSize() > 1) {
      std::cerr << " on rank " << comm->getRank();
    }
    std::cerr << ": " << e.what() << "\n" << std::flush;
    if (comm->getSize() > 1) {
      // Another rank may be waiting in a collective: stop them all.
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
    return 1;
  }
}

} // namespace capsula::core
