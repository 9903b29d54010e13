#include "capsula/run/RunBackbone.hpp"

#include "capsula/run/RestartDeck.hpp"

#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/core/Interruption.hpp>

#include <iomanip>
#include <ostream>
#include <sstream>

namespace capsula::run {

RunBackbone::RunBackbone(RunInvocation invocation, const Teuchos::ParameterList& validatedDeck,
                         const Teuchos::RCP<const Teuchos::Comm<int>>& comm, RunModel& model,
                         const timeint::TimeIntegrator& integrator, timeint::IntegrationState& state, std::ostream* log)
    : invocation_(std::move(invocation)),
      deck_(validatedDeck),
      comm_(comm),
      model_(model),
      integrator_(integrator),
      state_(state),
      log_(log),
      // Read and checked before RunOutputs exists: a refused restart leaves the directory
      // it names byte for byte.
      restart_(invocation_.restartDirectory ? std::optional<io::Checkpoint>(readRestartCheckpoint(
                                                  *invocation_.restartDirectory, invocation_.application, deck_))
                                            : std::nullopt),
      restartPath_(invocation_.restartDirectory ? checkpointPath(*invocation_.restartDirectory) : ""),
      files_(comm, invocation_.outputDirectory, invocation_.restartDirectory),
      summary_(invocation_.application, validatedDeck, comm->getSize()),
      watch_(*comm)
{}

void RunBackbone::restore()
{
  std::vector<io::CheckpointSection*> sections = model_.checkpointSections();
  sections.push_back(&switches_);
  io::loadSections(*restart_, restartPath_, sections);
}

void RunBackbone::requireTimeLeft(double time, double endTime) const
{
  core::require<core::InputError>(
      time < endTime * (1.0 - 1e-12), "--restart ", *invocation_.restartDirectory, ": the checkpoint is at ",
      model_.timeName(), " = ", time, ", at or past 'Time integration/End time' = ", endTime,
      "; nothing to do. Give a later end, e.g. --set \"Time integration/End time=", 2.0 * time, "\".");
}

std::vector<const io::CheckpointSection*> RunBackbone::checkpointSections() const
{
  const std::vector<io::CheckpointSection*> sections = model_.checkpointSections();
  std::vector<const io::CheckpointSection*> saved(sections.begin(), sections.end());
  saved.push_back(&switches_);
  return saved;
}

void RunBackbone::writeCheckpoint()
{
  files_.writeCheckpoint([&] {
    io::Checkpoint checkpoint;
    checkpoint.time = model_.reportedTime(state_.time);
    checkpoint.step = state_.statistics.acceptedSteps;
    checkpoint.stepSize = state_.proposedStep;
    checkpoint.deckXml = core::deckToXml(deck_, false);
    io::saveSections(checkpoint, checkpointSections());
    return checkpoint;
  });
}

timeint::ObserverVerdict RunBackbone::afterStep(timeint::IntegrationState& state, const timeint::StepReport& report,
                                                bool)
{
  if (!report.switchReason.empty()) {
    const std::string stage = model_.stage();
    const double time = model_.reportedTime(state.time);
    switches_.add(time, stage.empty() ? report.switchReason : stage + " stage: " + report.switchReason);
    std::ostringstream line;
    line << std::setprecision(6) << model_.timeName() << " = " << time << ": " << switches_.switches().back().second;
    log(line.str());
  }
  return timeint::ObserverVerdict::Continue;
}

void RunBackbone::log(const std::string& line) const
{
  if (log_ != nullptr) {
    *log_ << line << "\n";
  }
}

void RunBackbone::open()
{
  files_.open(deck_, {invocation_.application, invocation_.deckSource, comm_->getSize()});
  if (files_.writing()) {
    log("Output directory: " + files_.directory());
  }
  for (const auto& name : files_.removedStaleFiles()) {
    log("Removed " + name + ", left by a writer that was killed");
  }
}

void RunBackbone::begin(std::vector<std::string> terms)
{
  summary_.setTerms(std::move(terms));
  summary_.begin(state_.statistics, restarting());
  if (log_ != nullptr) {
    summary_.printTerms(*log_);
  }
  // From the start: the status is never missing, and the file holds the space a failure on
  // a full disk rewrites it in (RunOutputs::writeSummaryAfterFailure).
  writeSummary("running", "", model_.reportedTime(state_.time));
}

io::JsonValue RunBackbone::summaryJson(const std::string& status, const std::string& note, double time) const
{
  return summary_.json(status, note, time, state_.statistics, [this](io::JsonValue& json) {
    json["time integration"]["method"] = integrator_.settings().method;
    json["time integration"]["in use"] = integrator_.activeMethodName(state_);
    for (const auto& [switchTime, reason] : switches_.switches()) {
      io::JsonValue change = io::JsonValue::object();
      change["time"] = switchTime;
      change["reason"] = reason;
      json["time integration"]["switches"].append(change);
    }
    model_.addResults(json);
  });
}

void RunBackbone::writeSummary(const std::string& status, const std::string& note, double time)
{
  summary_.recordPeakMemory(*comm_);
  files_.writeSummary([&] { return summaryJson(status, note, time); });
}

void RunBackbone::recordingFailure(const std::function<void()>& loop)
{
  try {
    loop();
  } catch (const core::Interrupted&) {
    throw;
  } catch (const std::exception& e) {
    // Recorded next to the last good outputs; the app reports it.
    files_.writeSummaryAfterFailure([&] { return summaryJson("failed", e.what(), model_.lastOutputTime()); });
    throw;
  }
}

void RunBackbone::stopInterrupted()
{
  const double time = model_.reportedTime(state_.time);
  std::ostringstream line;
  line << std::setprecision(6) << "interrupted by " << core::signalName(watch_.signal()) << " at " << model_.timeName()
       << " = " << time << " (step " << state_.statistics.acceptedSteps << ")";
  if (files_.writing()) {
    writeCheckpoint();
    files_.writeSummary([&] { return summaryJson("interrupted", line.str(), time); });
    line << "; the checkpoint and summary.json are in " << files_.directory() << ": continue with --restart "
         << files_.directory();
  }
  throw core::Interrupted(watch_.signal(), line.str());
}

} // namespace capsula::run
