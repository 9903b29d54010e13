#include "capsula/run/TetherRun2D.hpp"

#include "capsula/run/IntegrationStateSection.hpp"
#include "capsula/run/RestartDeck.hpp"
#include "capsula/run/InterruptionWatch.hpp"
#include "capsula/run/RunOutputs.hpp"
#include "capsula/run/RunSummary.hpp"
#include "capsula/run/TetherStages2D.hpp"

#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/core/Interruption.hpp>
#include <capsula/io/Checkpoint.hpp>
#include <capsula/operators/ContourDiscretisation2D.hpp>
#include <capsula/operators/ShearRate.hpp>
#include <capsula/scene2d/NodesInFluid2D.hpp>
#include <capsula/scene2d/VelocityJacobian2D.hpp>
#include <capsula/timeint/TimeIntegrationParameters.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <iomanip>
#include <memory>
#include <ostream>
#include <sstream>
#include <vector>

namespace capsula::run {

namespace {

/// The summary.json results of a tether2d run, after the common part (RunSummary.hpp).
void addResults(io::JsonValue& summary, const TetherRunResult2D& result)
{
  summary["tethered"] = result.tethered;
  summary["preparation time"] = result.preparationTime;
  summary["final"]["time"] = result.finalTime;
  const auto names = scene2d::metricColumns();
  const auto values = scene2d::metricValues(result.final);
  for (std::size_t i = 0; i < names.size(); ++i) {
    summary["final"][names[i]] = values[i];
  }
  summary["max"]["tether_force"] = result.maxTetherForce;
  summary["max"]["time_of_max_tether_force"] = result.timeOfMaxTetherForce;
  summary["max"]["tether_force_after_transient"] = result.maxTetherForceAfterTransient;
  summary["max"]["time_of_max_tether_force_after_transient"] = result.timeOfMaxTetherForceAfterTransient;
  summary["max"]["contour_length_ratio"] = result.maxContourLengthRatio;
  summary["max"]["cell_length"] = result.maxCellLength;
  summary["max"]["abs_area_drift"] = result.maxAbsAreaDrift;
}

} // namespace

TetherRun2D::TetherRun2D(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const Teuchos::ParameterList& deck,
                         std::ostream* log, std::string deckSource)
    : comm_(comm),
      deck_(deck),
      log_(log),
      deckSource_(std::move(deckSource)),
      tether_(scene2d::readTetherSettings2D(deck.sublist("Tether"))),
      output_(readOutputSettings2D(deck.sublist("Output"))),
      model_(comm, scene2d::readCellSettings2D(deck.sublist("Cell")),
             scene2d::readFlowSettings2D(deck.sublist("Flow"), deck.sublist("Wall"), deck.sublist("Operator")),
             operators::readContourDiscretisation2D(deck.sublist("Discretisation")),
             operators::readSolverParameters(deck.sublist("Solver")))
{
  core::require<core::InputError>(!tether_.enabled || model_.flow().wall,
                                  "Tether/Enabled needs the wall (Wall/Enabled = true): the tether point is "
                                  "held above it.");
}

namespace {

// Method Auto's switches: a log line each and summary.json's "time integration" (those of
// this process, with the stage and its tau).
class MethodSwitchLog2D final : public timeint::IntegrationObserver {
public:
  MethodSwitchLog2D(const TetherStages2D& stages, std::ostream* log) : stages_(stages), log_(log) {}

  timeint::ObserverVerdict afterStep(timeint::IntegrationState& state, const timeint::StepReport& report, bool) override
  {
    if (!report.switchReason.empty()) {
      const double tau = stages_.tau(state.time);
      io::JsonValue change = io::JsonValue::object();
      change["stage"] = stages_.preparing() ? "preparation" : stages_.tethered() ? "tethered" : "free";
      change["tau"] = tau;
      change["reason"] = report.switchReason;
      switches_.push_back(change);
      if (log_ != nullptr) {
        *log_ << "tau = " << tau << ": " << report.switchReason << "\n";
      }
    }
    return timeint::ObserverVerdict::Continue;
  }
  const std::vector<io::JsonValue>& switches() const { return switches_; }

private:
  const TetherStages2D& stages_;
  std::ostream* log_;
  std::vector<io::JsonValue> switches_;
};

// A signal stopped the loop after the step every rank agreed on: the checkpoint and
// summary.json there, then the line the app prints.
[[noreturn]] void stopInterrupted(int signal, double tau, std::int64_t step, RunOutputs& files,
                                  TetherOutputs2D& outputs,
                                  const std::function<io::JsonValue(const std::string&)>& json)
{
  std::ostringstream line;
  line << std::setprecision(6) << "interrupted by " << core::signalName(signal) << " at tau = " << tau << " (step "
       << step << ")";
  if (files.writing()) {
    outputs.writeCheckpoint();
    files.writeSummary([&] { return json(line.str()); });
    line << "; the checkpoint and summary.json are in " << files.directory() << ": continue with --restart "
         << files.directory();
  }
  throw core::Interrupted(signal, line.str());
}

} // namespace

TetherRunResult2D TetherRun2D::run(const std::string& outputDirectory,
                                   const std::optional<std::string>& restartDirectory)
{
  timeint::TimeIntegrationSettings settings = timeint::timeIntegrationSettings(deck_.sublist("Time integration"));
  // With a periodic shear rate: steps of at most a twentieth of its period, outputs at a
  // whole number per period (Output/Interval is in tau = k t / lambda), no steady-state stop.
  settings.maximumStep = operators::limitStepToPeriod(settings.maximumStep, model_.flow().shearRate);
  settings.initialStep = std::min(settings.initialStep, settings.maximumStep);
  operators::requireOutputsCommensurate(model_.flow().shearRate, "Flow/Shear rate", output_.interval, "Output/Interval",
                                        model_.flow().conditions.viscosityRatio);
  operators::requireNoSteadyStop(model_.flow().shearRate, "Flow/Shear rate", settings.steadyTolerance);
  const double endTau = settings.endTime; // the tethered (or free) stage's duration in tau
  timeint::TimeIntegrator integrator(settings, [this](double t, const std::vector<double>& y,
                                                      std::vector<double>& dydt) { model_.rightHandSide(t, y, dydt); });
  // With the wall, a stage state or a step with a node on or below it is a rejected
  // attempt (NodesInFluid2D.hpp), not a failure of the run.
  if (model_.flow().wall) {
    integrator.setDomainCheck(scene2d::requireNodesInFluid);
  }
  // The stiff methods' Jacobian (VelocityJacobian2D.hpp) reads the model at every
  // linearisation, so it follows the tethering and the regrids as it is.
  std::shared_ptr<scene2d::VelocityJacobian2D> jacobian;
  if (integrator.needsLinearisedSystem()) {
    jacobian = std::make_shared<scene2d::VelocityJacobian2D>(model_, comm_, deck_);
    integrator.setLinearisedSystem(jacobian);
  }

  // The checkpoint is read and checked before the output directory is touched: a wrong
  // --restart must leave the directory it names as it was.
  std::optional<io::Checkpoint> checkpoint;
  const std::string checkpointPath = restartDirectory ? *restartDirectory + "/checkpoint.h5" : "";
  if (restartDirectory) {
    try {
      checkpoint = io::readCheckpoint(checkpointPath);
    } catch (const core::IoError& e) {
      throw core::InputError(core::message("--restart ", *restartDirectory, ": ", e.what()));
    }
    requireSameApplication(*checkpoint, "tether2d", checkpointPath);
  }
  RunOutputs files(comm_, outputDirectory, restartDirectory);
  RunSummary summary("tether2d", deck_, comm_->getSize());
  timeint::IntegrationState state;
  TetherStages2D stages(model_, tether_, integrator, state, log_);
  TetherOutputs2D outputs(model_, stages, output_, integrator.settings(), tether_.forceTransient, files, state,
                          core::deckToXml(deck_, false), log_);
  IntegrationStateSection stateSection(state, "");
  // Loaded in this order: the stages rebuild the model's markers and tether, which drops
  // the warm start the model then restores.
  outputs.setCheckpointSections({&stateSection, &stages, &model_, &outputs});

  if (checkpoint) {
    io::loadSections(*checkpoint, checkpointPath, {&stateSection, &stages, &model_, &outputs});
    state.steady = false; // a restart goes on from where the stopped run was
    // Same margin as the end-of-run test of TetherOutputs2D.
    core::require<core::InputError>(
        stages.preparing() || stages.tau(state.time) < endTau * (1.0 - 1e-12), "--restart ", *restartDirectory,
        ": the checkpoint is at tau = ", stages.tau(state.time), ", at or past 'Time integration/End time' = ", endTau,
        "; nothing to do. Give a later end, e.g. --set \"Time integration/End time=", 2.0 * stages.tau(state.time),
        "\".");
  }
  // Opened once the checkpoint is known to continue: a refused restart leaves the
  // directory as it was.
  files.open(deck_, {"tether2d", deckSource_, comm_->getSize()});
  for (const auto& name : files.removedStaleFiles()) {
    if (log_ != nullptr) {
      *log_ << "Removed " << name << ", left by a writer that was killed\n";
    }
  }
  if (checkpoint) {
    outputs.beginStage(checkpoint->time);
    if (log_ != nullptr) {
      *log_ << "Restarting from " << checkpointPath << " at tau = " << checkpoint->time << " (step " << checkpoint->step
            << ")\n";
    }
  } else {
    state = integrator.start(0.0, model_.initialState());
    stages.begin(tether_.enabled ? TetherStage::Preparation : TetherStage::Free);
    outputs.beginStage();
  }
  std::vector<std::string> terms = model_.terms();
  if (tether_.enabled) {
    terms.emplace_back("tether constraint after a free preparation stage");
  }
  terms.push_back(integrator.describe());
  if (jacobian) {
    terms.push_back(jacobian->describe());
  }
  summary.setTerms(terms);
  summary.begin(state.statistics, restartDirectory.has_value());
  if (log_ != nullptr) {
    summary.printTerms(*log_);
  }

  TetherRunResult2D result;
  MethodSwitchLog2D switches(stages, log_);
  InterruptionWatch watch(*comm_);
  const auto summaryJson = [&](const std::string& status, const std::string& note) {
    const double time = status == "interrupted" ? stages.tau(state.time) : result.finalTime;
    return summary.json(status, note, time, state.statistics, [&](io::JsonValue& json) {
      json["time integration"]["method"] = integrator.settings().method;
      json["time integration"]["in use"] = integrator.activeMethodName(state);
      for (const io::JsonValue& change : switches.switches()) {
        json["time integration"]["switches"].append(change);
      }
      addResults(json, result);
    });
  };
  // From the start: the status is never missing, and the file holds the space a failure on
  // a full disk rewrites it in (RunOutputs::writeSummaryAfterFailure).
  files.writeSummary([&] { return summaryJson("running", ""); });
  try {
    if (stages.preparing()) {
      integrator.integrate(state, stages.schedule(output_.interval, endTau), {&stages, &outputs, &switches, &watch});
      if (watch.signal() != 0) {
        stopInterrupted(watch.signal(), stages.tau(state.time), state.statistics.acceptedSteps, files, outputs,
                        [&](const std::string& note) { return summaryJson("interrupted", note); });
      }
      // The preparation is over: its last state is an output, then the cell is tethered.
      if (stages.stoppedAtOutputTime()) {
        ++state.nextOutput;
      }
      outputs.observe(stages.lastStepSize(), stages.preparationRate(), true);
      stages.tether();
      outputs.beginStage();
    }
    integrator.integrate(state, stages.schedule(output_.interval, endTau), {&stages, &outputs, &switches, &watch});
    if (watch.signal() != 0 && !state.steady) {
      stopInterrupted(watch.signal(), stages.tau(state.time), state.statistics.acceptedSteps, files, outputs,
                      [&](const std::string& note) { return summaryJson("interrupted", note); });
    }
    outputs.writeCheckpoint();
  } catch (const core::Interrupted&) {
    throw;
  } catch (const std::exception& e) {
    result = outputs.result();
    files.writeSummaryAfterFailure([&] { return summaryJson("failed", e.what()); });
    throw;
  }

  result = outputs.result();
  result.tethered = stages.tethered();
  result.steady = state.steady;
  result.preparationTime = stages.preparationTime();
  result.steps = static_cast<long long>(state.statistics.acceptedSteps);
  files.writeSummary([&] { return summaryJson(result.steady ? "steady" : "finished", ""); });
  return result;
}

} // namespace capsula::run
