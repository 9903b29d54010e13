#pragma once
// The files every run leaves in its output directory, written on rank 0:
//
//   deck.xml, run.json     the validated deck and the run record (io/OutputDirectory.hpp)
//   <table>.csv            tables of one row per output (io/MetricsCsv.hpp)
//   <base>.h5 + .xdmf      snapshot series (io/SnapshotSeries.hpp)
//   checkpoint.h5          the state to continue from (io/Checkpoint.hpp)
//   summary.json           the run's status and results (RunSummary.hpp)
//
// Every member is collective: each rank calls it, rank 0 does the work, and a failure
// there is thrown on every rank (Collective.hpp). Content that costs something to build
// (a snapshot, a checkpoint, the summary) is passed as a function that rank 0 calls.
//
// Restart: tables and snapshot series are continued after the checkpoint's time (what the
// stopped run wrote later is dropped), and copied over first when the restarted run writes
// into another directory, so the new directory holds the whole run.
//
// Without a directory the run writes nothing (tests that only need the numbers).
#include <capsula/io/Checkpoint.hpp>
#include <capsula/io/Json.hpp>
#include <capsula/io/MetricsCsv.hpp>
#include <capsula/io/OutputDirectory.hpp>
#include <capsula/io/Snapshot.hpp>
#include <capsula/io/SnapshotSeries.hpp>

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace capsula::run {

class RunOutputs {
public:
  /// `directory` empty: nothing is written. `restartDirectory`: where the checkpoint the
  /// run continues from lies.
  RunOutputs(Teuchos::RCP<const Teuchos::Comm<int>> comm, std::string directory,
             std::optional<std::string> restartDirectory);

  bool writing() const { return !directory_.empty(); }
  const std::string& directory() const { return directory_; }
  /// `file` in the output directory.
  std::string path(const std::string& file) const;

  /// Creates the directory, removes the temporary files a killed writer left there
  /// (core::removeStaleTemporaryFiles) and writes deck.xml and run.json. Throws
  /// core::InputError if the directory cannot be used.
  void open(const Teuchos::ParameterList& validatedDeck, const io::RunMetadata& metadata);
  /// What open() removed (rank 0), for the log.
  const std::vector<std::string>& removedStaleFiles() const { return staleFiles_; }

  /// Starts the table `file` with `columns`; with `resumeAfter` (a restart from a
  /// checkpoint at that time in the table's first column) continues the stopped run's.
  void openTable(const std::string& file, const std::vector<std::string>& columns,
                 std::optional<double> resumeAfter = std::nullopt);
  void appendRow(const std::string& file, const std::vector<double>& row);

  /// Starts the snapshot series `base` (<base>.h5, <base>.xdmf), or continues it after
  /// `resumeAfter`.
  void openSnapshots(const std::string& base, std::optional<double> resumeAfter = std::nullopt);
  void writeSnapshot(const std::string& base, const std::function<io::Snapshot()>& snapshot);

  /// checkpoint.h5, replaced atomically, stamped with the application open() was given.
  void writeCheckpoint(const std::function<io::Checkpoint()>& checkpoint);
  /// summary.json, replaced atomically.
  void writeSummary(const std::function<io::JsonValue()>& summary);
  /// summary.json after a failure, which the caller rethrows: rank 0 only, not collective
  /// (the ranks may have failed at different places), and a failure to write is ignored
  /// (the original error is the one to report). On a full disk the previous summary.json
  /// is overwritten in place (core::overwriteInPlace), shortened to its first entries if
  /// the whole does not fit.
  void writeSummaryAfterFailure(const std::function<io::JsonValue()>& summary) noexcept;

private:
  void onRoot(const std::function<void()>& action) const;
  /// Copies `file` from the restart directory if the run writes elsewhere.
  void carryOver(const std::string& file) const;

  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::string directory_;
  std::optional<std::string> restartDirectory_;
  std::string application_;
  std::vector<std::string> staleFiles_;              // rank 0
  std::optional<io::OutputDirectory> output_;        // rank 0
  std::map<std::string, io::MetricsCsv> tables_;     // rank 0
  std::map<std::string, io::SnapshotSeries> series_; // rank 0
};

} // namespace capsula::run
