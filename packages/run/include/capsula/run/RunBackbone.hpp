#pragma once
// The run backbone: what every app's run does around its model, written once. The 3D
// scenes (cell3d, twocell3d: SceneRun.cpp) and the 2D tethered cell (tether2d:
// scene2d/TetherRun2D.cpp) plug their model in through RunModel; the backbone owns
//
//   restart        the checkpoint of --restart DIR, read and checked against the
//                  application and the deck (RestartDeck.hpp: every key but 'Time
//                  integration/End time' and 'Output/Directory' must match, a changed
//                  one is refused naming it) before the output directory is touched,
//                  then the model's checkpoint sections loaded from it in their order
//   checkpoint     checkpoint.h5 from those same sections and the backbone's, stamped
//                  with the reported time, the step, the step size the integrator
//                  proposes next and the validated deck; the model's outputs call
//                  writeCheckpoint() at their cadence
//   the directory  RunOutputs opened once the restart is known to continue: deck.xml,
//                  run.json, temporaries of a killed writer removed (and logged)
//   summary.json   RunSummary: "running" from the start (the terms built in the log
//                  too), the final status, "failed" after a failure (then rethrown),
//                  "interrupted" after a signal; the time integration's method and the
//                  one in use, then the model's results
//   Auto's switches  the backbone is the first observer of every time loop: it logs each
//                  switch of method Auto and keeps them (MethodSwitchRecord, a checkpoint
//                  section of its own, so a restarted run's summary lists those before the
//                  checkpoint too)
//   interruption   InterruptionWatch, the loop's last observer; a signal the ranks
//                  agreed on ends the run with the checkpoint and summary.json at the
//                  step reached, and core::Interrupted
//
// The model keeps its time loop (the observers it integrates with, the stages of
// tether2d), its outputs and their cadence, and its log of progress.
#include <capsula/io/Checkpoint.hpp>
#include <capsula/io/CheckpointSection.hpp>
#include <capsula/io/Json.hpp>
#include <capsula/run/InterruptionWatch.hpp>
#include <capsula/run/MethodSwitchRecord.hpp>
#include <capsula/run/RunOutputs.hpp>
#include <capsula/run/RunSummary.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace capsula::run {

/// What a model plugs into the backbone.
class RunModel {
public:
  virtual ~RunModel() = default;
  /// The sections that restore the model, in the order a restart loads them (a later
  /// one may rely on an earlier one). Every checkpoint holds them all.
  virtual std::vector<io::CheckpointSection*> checkpointSections() = 0;
  /// The model's entries of summary.json, after "steps" and the time integration's
  /// method and the one in use (its final values, extremes, Auto's switches).
  virtual void addResults(io::JsonValue& summary) const = 0;
  /// The time the model reports for the integrator's time `t`: t itself, or tether2d's
  /// tau = k (t - t0) / lambda of its stage; named timeName() in the log.
  virtual double reportedTime(double t) const { return t; }
  virtual const char* timeName() const { return "t"; }
  /// The stage the run is in, named with Auto's switches ("" for a run of one stage).
  virtual std::string stage() const { return ""; }
  /// The reported time of the last output: summary.json's "time" while the run goes on
  /// and after a failure.
  virtual double lastOutputTime() const = 0;
};

/// Where a run comes from and goes to, as the command line gave it.
struct RunInvocation {
  std::string application;                     ///< named in run.json, summary.json, checkpoint.h5
  std::string deckSource;                      ///< the deck file, for run.json
  std::string outputDirectory;                 ///< "": nothing is written
  std::optional<std::string> restartDirectory; ///< continue from its checkpoint.h5
};

class RunBackbone final : public timeint::IntegrationObserver {
public:
  /// Reads and checks the restart checkpoint (throws core::InputError before anything is
  /// written). `integrator` and `state` are the model's; `log` may be null. Collective.
  RunBackbone(RunInvocation invocation, const Teuchos::ParameterList& validatedDeck,
              const Teuchos::RCP<const Teuchos::Comm<int>>& comm, RunModel& model,
              const timeint::TimeIntegrator& integrator, timeint::IntegrationState& state, std::ostream* log);

  bool restarting() const { return restart_.has_value(); }
  /// The checkpoint a restart continues and its path (restarting() only).
  const io::Checkpoint& restartCheckpoint() const { return *restart_; }
  const std::string& restartPath() const { return restartPath_; }
  /// Loads the model's checkpoint sections from the restart checkpoint.
  void restore();
  /// Throws core::InputError naming the restart directory if the checkpoint's reported
  /// `time` is at or past `endTime` (to a relative 1e-12): nothing to do.
  void requireTimeLeft(double time, double endTime) const;

  RunOutputs& files() { return files_; }
  const RunSummary& summary() const { return summary_; }
  /// Records Auto's switches: the first observer of the model's time loops.
  timeint::ObserverVerdict afterStep(timeint::IntegrationState& state, const timeint::StepReport& report,
                                     bool atOutputTime) override;
  /// The observer the model's time loops end with.
  InterruptionWatch& watch() { return watch_; }
  /// The signal the ranks agreed on, 0 while none.
  int signal() const { return watch_.signal(); }

  /// Opens the output directory and logs where it is (and any temporaries removed).
  void open();
  /// The run starts: the terms built go to summary.json and the log, and summary.json
  /// says "running" from here on. Collective.
  void begin(std::vector<std::string> terms);
  /// checkpoint.h5 now (between outputs too: a run stopped by a signal). Collective.
  void writeCheckpoint();
  /// summary.json with `status`, `note` (why the run failed or stopped early, "" for
  /// none) and the reported `time`, with every rank's peak memory. Collective.
  void writeSummary(const std::string& status, const std::string& note, double time);
  io::JsonValue summaryJson(const std::string& status, const std::string& note, double time) const;

  /// Runs `loop`; a failure (any exception but core::Interrupted) is recorded in
  /// summary.json ("failed", the message, the last output's time) and rethrown.
  void recordingFailure(const std::function<void()>& loop);
  /// A signal stopped the loop after a step every rank agreed on: checkpoint.h5 and
  /// summary.json there ("interrupted"), then core::Interrupted with the line the app
  /// prints.
  [[noreturn]] void stopInterrupted();

private:
  /// The model's sections and the record of Auto's switches, as a checkpoint saves them.
  std::vector<const io::CheckpointSection*> checkpointSections() const;
  void log(const std::string& line) const;

  RunInvocation invocation_;
  const Teuchos::ParameterList& deck_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  RunModel& model_;
  const timeint::TimeIntegrator& integrator_;
  timeint::IntegrationState& state_;
  std::ostream* log_;
  std::optional<io::Checkpoint> restart_;
  std::string restartPath_;
  RunOutputs files_;
  RunSummary summary_;
  InterruptionWatch watch_;
  MethodSwitchRecord switches_; // since the start of the run
};

} // namespace capsula::run
