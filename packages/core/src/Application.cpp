#include "capsula/core/Application.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/core/MpiSessionDirectory.hpp"
#include "capsula/core/Interruption.hpp"
#include "capsula/core/RunInfo.hpp"
#include "capsula/core/Timers.hpp"

#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_oblackholestream.hpp>
#include <Tpetra_Core.hpp>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <thread>
#include <mpi.h>

namespace capsula::core {

namespace {

namespace fs = std::filesystem;

// How long the ranks that failed wait for the others to fail too. A failure every rank
// meets (a bad deck, an error broadcast from rank 0, a non-finite state, which every rank
// holds alike) reaches all of them within one step's local work; a rank still missing
// after this long waits in a collective the failed rank will never join.
constexpr std::chrono::seconds kAgreementWait{10};

Teuchos::RCP<Teuchos::ParameterList> loadDeck(const CommandLineOptions& options,
                                              const ValidParameterBuilder& validParameters, std::string& deckName)
{
  require<InputError>(!options.deckPath.empty(), "No deck given. Usage: APP DECK.xml [options]; ",
                      "run with --help for examples or --print-defaults for every key.");
  deckName = options.deckPath;
  std::error_code ec;
  require<InputError>(fs::exists(options.deckPath, ec), "The deck '", options.deckPath,
                      "' does not exist. Give the path of a deck file (an XML parameter list), e.g. "
                      "input/cell3d/demo.xml, or write one with --print-defaults > my_deck.xml.");
  require<InputError>(!fs::is_directory(options.deckPath, ec), "The deck '", options.deckPath,
                      "' is a directory, not a deck file. Give the XML file itself (to continue a run in that "
                      "directory: APP DECK.xml --restart ",
                      options.deckPath, ").");
  Teuchos::RCP<Teuchos::ParameterList> deck;
  try {
    deck = readDeck(options.deckPath);
  } catch (const IoError& e) {
    throw InputError(e.what());
  }
  // Overrides are typed by the valid list of the deck as read, then the whole
  // deck (overrides included) is validated against the list rebuilt from it.
  for (const auto& assignment : options.overrides) {
    applyOverride(*deck, *validParameters(*deck), assignment);
  }
  const auto valid = validParameters(*deck);
  validateDeck(*deck, *valid, deckName);
  return deck;
}

/// The one exit of a failed or interrupted run. The ranks that got here wait (on a
/// communicator of their own, so a rank blocked in another collective is no partner) for
/// all the others: if all come, the failure is collective and rank 0 reports it once and
/// every rank returns rank 0's code. If some never come, the failure is this rank's alone
/// and the others wait for it in a collective: it reports with its rank and MPI_Abort ends
/// them all.
int reportFailure(MPI_Comm agreement, const std::string& app, int code, const std::string& what)
{
  int size = 1;
  int rank = 0;
  MPI_Comm_size(agreement, &size);
  MPI_Comm_rank(agreement, &rank);
  bool everyone = size == 1;
  if (!everyone) {
    MPI_Request request = MPI_REQUEST_NULL;
    MPI_Ibarrier(agreement, &request);
    const auto deadline = std::chrono::steady_clock::now() + kAgreementWait;
    int done = 0;
    while (!done && std::chrono::steady_clock::now() < deadline) {
      MPI_Test(&request, &done, MPI_STATUS_IGNORE);
      if (!done) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
    }
    everyone = done != 0;
  }
  if (everyone) {
    if (size > 1) {
      MPI_Bcast(&code, 1, MPI_INT, 0, agreement);
    }
    if (rank == 0) {
      std::cerr << app << (code > 128 ? ": " : ": error: ") << what << "\n" << std::flush;
    }
    return code;
  }
  std::cerr << app << ": error on rank " << rank << " (the other ranks did not fail with it): " << what << "\n"
            << std::flush;
  MPI_Abort(agreement, code);
  return code;
}

MPI_Comm agreementCommunicator(const Teuchos::Comm<int>& comm)
{
  MPI_Comm raw = MPI_COMM_SELF;
  if (const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm)) {
    raw = *mpi->getRawMpiComm();
  }
  MPI_Comm agreement = MPI_COMM_NULL;
  MPI_Comm_dup(raw, &agreement);
  return agreement;
}

} // namespace

int runApplication(int argc, char** argv, const AppDescription& app, const ValidParameterBuilder& validParameters,
                   const std::function<void(RunContext&)>& run)
{
  // --help is answered before Kokkos starts: Kokkos also takes --help and would print its
  // own forty lines of options above ours.
  if (asksForHelp(argc, argv)) {
    std::cout << usage(app);
    return 0;
  }
  // An app that continues from checkpoints stops cleanly on SIGTERM/SIGINT (its time loop
  // asks for them, run::InterruptionWatch); the others keep the default: killed at once.
  // Before MPI and Kokkos start: a signal during the set-up stops the run after its first step.
  if (app.supportsRestart) {
    installInterruptionHandlers();
  }
  MpiSessionDirectory sessionDirectory; // outlives MPI (declared before the scope guard)
  Tpetra::ScopeGuard tpetraScope(&argc, &argv);
  const auto comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  Teuchos::oblackholestream blackHole;
  std::ostream& out = root ? std::cout : blackHole;
  MPI_Comm agreement = agreementCommunicator(*comm);

  RunContext context;
  context.comm = comm;
  context.out = &out;
  int code = 0;
  std::string what;
  try {
    context.options = parseCommandLine(argc, argv);
    if (context.options.help) {
      out << usage(app);
    } else if (context.options.version) {
      out << app.name << ": " << versionLine() << "\n";
    } else if (context.options.printDefaults) {
      Teuchos::ParameterList empty("Capsula");
      auto valid = Teuchos::rcp(new Teuchos::ParameterList(*validParameters(empty)));
      valid->setName(app.name);
      out << deckToXml(*valid, true);
    } else {
      context.deck = loadDeck(context.options, validParameters, context.deckName);
      out << app.name << ": " << versionLine() << ", " << comm->getSize() << " rank(s)\n";
      run(context);
      printTimerSummary(*comm, out);
    }
  } catch (const Interrupted& e) {
    code = 128 + e.signal();
    what = e.what();
  } catch (const InputError& e) {
    code = 2;
    what = e.what();
  } catch (const std::exception& e) {
    code = 1;
    what = e.what();
  }
  if (code != 0) {
    code = reportFailure(agreement, app.name, code, what);
  }
  MPI_Comm_free(&agreement);
  if (code != 0) {
    // Leave without finalising MPI: every rank has agreed and written what it had to, and
    // the finalisation can hang or crash after a failure. When mpiexec itself was signalled
    // it tears the job down and no longer answers MPI_Finalize; after a full disk HDF5
    // closes at MPI_Finalize the files whose close failed and dies on them. (mpiexec
    // reports a non-zero exit the same way with or without it.)
    std::cout << std::flush;
    std::cerr << std::flush;
    sessionDirectory.remove();
    std::_Exit(code);
  }
  return code;
}

} // namespace capsula::core
