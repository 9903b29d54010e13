#include "capsula/scene2d/TetherRun2D.hpp"

#include "capsula/scene2d/ContourDiscretisation2D.hpp"
#include "capsula/scene2d/NodesInFluid2D.hpp"
#include "capsula/scene2d/TetherStages2D.hpp"
#include "capsula/scene2d/VelocityJacobian2D.hpp"

#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/operators/ShearRate.hpp>
#include <capsula/run/IntegrationStateSection.hpp>
#include <capsula/run/RunBackbone.hpp>
#include <capsula/timeint/TimeIntegrationParameters.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

#include <algorithm>
#include <memory>
#include <ostream>
#include <vector>

namespace capsula::scene2d {

namespace {

/// The summary.json results of a tether2d run, after the common part (RunSummary.hpp).
void addTetherResults(io::JsonValue& summary, const TetherRunResult2D& result)
{
  summary["tethered"] = result.tethered;
  summary["preparation time"] = result.preparationTime;
  summary["final"]["time"] = result.finalTime;
  const auto names = metricColumns();
  const auto values = metricValues(result.final);
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
      tether_(readTetherSettings2D(deck.sublist("Tether"))),
      output_(readOutputSettings2D(deck.sublist("Output"))),
      model_(comm, readCellSettings2D(deck.sublist("Cell")),
             readFlowSettings2D(deck.sublist("Flow"), deck.sublist("Wall"), deck.sublist("Operator")),
             readContourDiscretisation2D(deck.sublist("Discretisation")),
             operators::readSolverParameters(deck.sublist("Solver")))
{
  core::require<core::InputError>(!tether_.enabled || model_.flow().domain.hasLowerWall(),
                                  "Tether/Enabled needs the wall (Wall/Enabled = true): the tether point is "
                                  "held above it.");
}

namespace {

// The time integration of the deck, with a periodic shear rate: steps of at most a
// twentieth of its period, outputs at a whole number per period (Output/Interval is in
// tau = k t / lambda), no steady-state stop.
timeint::TimeIntegrationSettings integrationSettings2D(const Teuchos::ParameterList& deck, const CapsuleModel2D& model,
                                                       const OutputSettings2D& output)
{
  timeint::TimeIntegrationSettings settings = timeint::timeIntegrationSettings(deck.sublist("Time integration"));
  settings.maximumStep = operators::limitStepToPeriod(settings.maximumStep, model.flow().shearRate);
  settings.initialStep = std::min(settings.initialStep, settings.maximumStep);
  operators::requireOutputsCommensurate(model.flow().shearRate, "Flow/Shear rate", output.interval, "Output/Interval",
                                        model.flow().conditions.viscosityRatio);
  operators::requireNoSteadyStop(model.flow().shearRate, "Flow/Shear rate", settings.steadyTolerance);
  return settings;
}

/// A run of the 2D tethered cell, the model the run backbone (RunBackbone.hpp) drives: the
/// preparation and tethered stages (or the free stage alone), each a time loop with the
/// stages, the outputs, Auto's switches and the backbone's interruption watch as observers.
class TetherRunner2D final : public run::RunModel {
public:
  TetherRunner2D(CapsuleModel2D& model, const TetherSettings2D& tether, const OutputSettings2D& output,
                 const Teuchos::ParameterList& deck, const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                 run::RunInvocation invocation, std::ostream* log);

  TetherRunResult2D execute();

  std::vector<io::CheckpointSection*> checkpointSections() override
  {
    // Loaded in this order: the stages rebuild the model's markers and tether, which drops
    // the warm start the model then restores.
    return {&stateSection_, &stages_, &model_, &outputs_};
  }
  void addResults(io::JsonValue& json) const override;
  double reportedTime(double t) const override { return stages_.tau(t); }
  const char* timeName() const override { return "tau"; }
  std::string stage() const override
  {
    return stages_.preparing() ? "preparation" : stages_.tethered() ? "tethered" : "free";
  }
  double lastOutputTime() const override { return outputs_.result().finalTime; }

private:
  /// The duration of the tethered (or free) stage in tau.
  double endTau() const { return integrator_.settings().endTime; }
  void restore();
  std::vector<std::string> terms() const;
  void integrateStages();
  void stopIfInterrupted(bool runOver);
  /// The outputs' values with the stages' and the integrator's.
  TetherRunResult2D result() const;

  CapsuleModel2D& model_;
  const TetherSettings2D& tether_;
  const OutputSettings2D& output_;
  std::ostream* log_;
  timeint::TimeIntegrator integrator_;
  std::shared_ptr<VelocityJacobian2D> jacobian_;
  timeint::IntegrationState state_;
  run::RunBackbone backbone_;
  TetherStages2D stages_;
  TetherOutputs2D outputs_;
  run::IntegrationStateSection stateSection_;
};

TetherRunner2D::TetherRunner2D(CapsuleModel2D& model, const TetherSettings2D& tether, const OutputSettings2D& output,
                               const Teuchos::ParameterList& deck, const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                               run::RunInvocation invocation, std::ostream* log)
    : model_(model),
      tether_(tether),
      output_(output),
      log_(log),
      integrator_(integrationSettings2D(deck, model, output),
                  [this](double t, const std::vector<double>& y, std::vector<double>& dydt) {
                    model_.rightHandSide(t, y, dydt);
                  }),
      backbone_(std::move(invocation), deck, comm, *this, integrator_, state_, log),
      stages_(model, tether, integrator_, state_, log),
      outputs_(model, stages_, output, integrator_.settings(), tether.forceTransient, backbone_.files(), state_, log),
      stateSection_(state_, "")
{
  // With the wall, a stage state or a step with a node on or below it is a rejected
  // attempt (NodesInFluid2D.hpp), not a failure of the run.
  if (model_.flow().domain.hasWalls()) {
    integrator_.setDomainCheck(
        [domain = model_.flow().domain](const std::vector<double>& y) { requireNodesInFluid(domain, y); });
  }
  // The stiff methods' Jacobian (VelocityJacobian2D.hpp) reads the model at every
  // linearisation, so it follows the tethering and the regrids as it is.
  if (integrator_.needsLinearisedSystem()) {
    jacobian_ = std::make_shared<VelocityJacobian2D>(model_, comm, deck);
    integrator_.setLinearisedSystem(jacobian_);
  }
  outputs_.setCheckpointWriter([this] { backbone_.writeCheckpoint(); });
}

void TetherRunner2D::restore()
{
  backbone_.restore();
  state_.steady = false; // a restart goes on from where the stopped run was
  if (!stages_.preparing()) {
    backbone_.requireTimeLeft(stages_.tau(state_.time), endTau());
  }
}

std::vector<std::string> TetherRunner2D::terms() const
{
  std::vector<std::string> terms = model_.terms();
  if (tether_.enabled) {
    terms.emplace_back("tether constraint after a free preparation stage");
  }
  terms.push_back(integrator_.describe());
  if (jacobian_) {
    terms.push_back(jacobian_->describe());
  }
  return terms;
}

TetherRunResult2D TetherRunner2D::result() const
{
  TetherRunResult2D result = outputs_.result();
  result.tethered = stages_.tethered();
  result.steady = state_.steady;
  result.preparationTime = stages_.preparationTime();
  result.steps = static_cast<long long>(state_.statistics.acceptedSteps);
  return result;
}

void TetherRunner2D::addResults(io::JsonValue& json) const
{
  addTetherResults(json, result());
}

// `runOver`: the stage ended at equilibrium, where a signal is not acted on.
void TetherRunner2D::stopIfInterrupted(bool runOver)
{
  if (backbone_.signal() != 0 && !runOver) {
    backbone_.stopInterrupted();
  }
}

void TetherRunner2D::integrateStages()
{
  if (stages_.preparing()) {
    integrator_.integrate(state_, stages_.schedule(output_.interval, endTau()),
                          {&backbone_, &stages_, &outputs_, &backbone_.watch()});
    stopIfInterrupted(false);
    // The preparation is over: its last state is an output, then the cell is tethered.
    if (stages_.stoppedAtOutputTime()) {
      ++state_.nextOutput;
    }
    outputs_.observe(stages_.lastStepSize(), stages_.preparationRate(), true);
    stages_.tether();
    outputs_.beginStage();
  }
  integrator_.integrate(state_, stages_.schedule(output_.interval, endTau()),
                        {&backbone_, &stages_, &outputs_, &backbone_.watch()});
  stopIfInterrupted(state_.steady);
  backbone_.writeCheckpoint();
}

TetherRunResult2D TetherRunner2D::execute()
{
  // The checkpoint was read and checked before the output directory is touched; it is
  // opened once the checkpoint is known to continue.
  if (backbone_.restarting()) {
    restore();
  }
  backbone_.open();
  if (backbone_.restarting()) {
    const io::Checkpoint& checkpoint = backbone_.restartCheckpoint();
    outputs_.beginStage(checkpoint.time);
    if (log_ != nullptr) {
      *log_ << "Restarting from " << backbone_.restartPath() << " at tau = " << checkpoint.time << " (step "
            << checkpoint.step << ")\n";
    }
  } else {
    state_ = integrator_.start(0.0, model_.initialState());
    stages_.begin(tether_.enabled ? TetherStage::Preparation : TetherStage::Free);
    outputs_.beginStage();
  }
  backbone_.begin(terms());
  backbone_.recordingFailure([this] { integrateStages(); });
  const TetherRunResult2D finished = result();
  backbone_.writeSummary(finished.steady ? "steady" : "finished", "", finished.finalTime);
  return finished;
}

} // namespace

TetherRunResult2D TetherRun2D::run(const std::string& outputDirectory,
                                   const std::optional<std::string>& restartDirectory)
{
  TetherRunner2D runner(model_, tether_, output_, deck_, comm_,
                        {"tether2d", deckSource_, outputDirectory, restartDirectory}, log_);
  return runner.execute();
}

} // namespace capsula::scene2d
