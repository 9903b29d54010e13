#include "capsula/run/SceneRun.hpp"

#include "capsula/run/Collective.hpp"
#include "capsula/run/IntegrationStateSection.hpp"
#include "capsula/run/PairMetrics.hpp"
#include "capsula/run/RestartRecord.hpp"
#include "capsula/run/RunBackbone.hpp"
#include "capsula/run/RunScene.hpp"
#include "capsula/run/SceneOutputSettings.hpp"
#include "capsula/run/SceneOutputs.hpp"
#include "capsula/run/TetherRecord.hpp"
#include "capsula/run/WallClock.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/Timers.hpp>
#include <capsula/operators/ShearRate.hpp>
#include <capsula/scene/NodesAboveWall.hpp>
#include <capsula/scene/SceneBounds.hpp>
#include <capsula/scene/UnfoldedMembranes.hpp>
#include <capsula/scene/SceneDescription.hpp>
#include <capsula/scene/VelocityJacobian.hpp>
#include <capsula/timeint/TimeIntegrationParameters.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

#include <Teuchos_oblackholestream.hpp>

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <memory>
#include <ostream>
#include <sstream>

namespace capsula::run {

namespace core = capsula::core;

namespace {

std::string outputDirectory(const SceneRunOptions& options, const SceneOutputSettings& settings)
{
  const std::string directory = options.outputDirectory    ? *options.outputDirectory
                                : options.restartDirectory ? *options.restartDirectory
                                                           : settings.directory;
  core::require<core::InputError>(!directory.empty(),
                                  "No output directory: set 'Output/Directory' or give --output DIR.");
  return directory;
}

// The settings of the integrator: the deck's, but steady state is judged on the shape at
// output times (SceneOutputs.hpp), not on the raw node positions, which keep moving as the
// membrane tank-treads.
// With a periodic shear rate, a step (the first one too) is at most a twentieth of its period.
timeint::TimeIntegrationSettings integrationSettings(const Teuchos::ParameterList& deck,
                                                     const scene::SceneDescription& description,
                                                     const timeint::MethodRegistry& methods)
{
  auto settings = timeint::timeIntegrationSettings(deck.sublist("Time integration"), methods);
  // Auto judges stiffness by the stability limit: the deck's false (the 3D apps' default is
  // true) would be overridden.
  core::require<core::InputError>(settings.stabilityLimit || !methods.info(settings.method).traits.stabilityLimit,
                                  "'Time integration/Stability limit' = false cannot hold with 'Time "
                                  "integration/Method' = ",
                                  settings.method,
                                  ", which judges stiffness by that limit: set it to true, "
                                  "or choose RKF45 (explicit without the limit) or ROS34PW2 (stiff throughout).");
  settings.steadyCriterion = timeint::SteadyStateCriterion::Off;
  operators::requireNoSteadyStop(description.shearRate, "Flow/Shear rate", settings.steadyTolerance);
  settings.maximumStep = operators::limitStepToPeriod(settings.maximumStep, description.shearRate);
  settings.initialStep = std::min(settings.initialStep, settings.maximumStep);
  return settings;
}

// The output settings; with a periodic shear rate, the interval must divide its period.
SceneOutputSettings outputSettings(const Teuchos::ParameterList& deck, const scene::SceneDescription& description)
{
  SceneOutputSettings settings = readSceneOutputSettings(deck, description);
  operators::requireOutputsCommensurate(description.shearRate, "Flow/Shear rate", settings.interval, "Output/Interval");
  return settings;
}

/// The run of a scene, the model the run backbone (RunBackbone.hpp) drives: builds the
/// parts, restores them from a checkpoint, runs the time loop with them as observers, and
/// watches the gap between the cells and the progress.
class SceneRunner final : public timeint::IntegrationObserver, public RunModel {
public:
  SceneRunner(const Teuchos::ParameterList& deck, const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
              const SceneRunOptions& options, const operators::KernelRegistry& kernels,
              const elasticity::MembraneLawRegistry& laws, const timeint::MethodRegistry& methods);

  SceneRunResult execute();

  timeint::ObserverVerdict afterStep(timeint::IntegrationState& state, const timeint::StepReport& report,
                                     bool atOutputTime) override;
  timeint::ObserverVerdict atOutput(const timeint::IntegrationState& state, timeint::OutputReason reason) override;

  std::vector<io::CheckpointSection*> checkpointSections() override
  {
    return {&stateSection_, &outputs_, &live_, &tether_};
  }
  void addResults(io::JsonValue& json) const override;
  double lastOutputTime() const override { return outputs_.lastTime(); }

private:
  std::ostream& log() { return *log_; }
  void restore();
  void attachJacobian();
  bool cellsTooClose(const timeint::IntegrationState& state);
  void progress(const timeint::IntegrationState& state);
  void report(const std::string& status);

  const Teuchos::ParameterList& deck_;
  SceneRunOptions options_;
  const operators::KernelRegistry& kernels_;
  Teuchos::oblackholestream quiet_;
  std::ostream* log_;
  scene::SceneDescription description_;
  SceneOutputSettings settings_;
  timeint::TimeIntegrator integrator_;
  timeint::IntegrationState state_;
  RunBackbone backbone_;
  RunOutputs& files_;
  RunScene live_;
  SceneOutputs outputs_;
  TetherRecord tether_;
  IntegrationStateSection stateSection_;
  // The stiff methods' Jacobian, built for the scene it belongs to (again after an adaption).
  std::shared_ptr<scene::VelocityJacobian> jacobian_;
  const scene::Scene* jacobianScene_ = nullptr;
  bool restarted_ = false;
  bool tooClose_ = false;
  std::string stopReason_;
  std::vector<std::string> terms_;
  std::chrono::steady_clock::time_point wallStart_;
  double simulatedStart_ = 0.0;
};

SceneRunner::SceneRunner(const Teuchos::ParameterList& deck, const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                         const SceneRunOptions& options, const operators::KernelRegistry& kernels,
                         const elasticity::MembraneLawRegistry& laws, const timeint::MethodRegistry& methods)
    : deck_(deck),
      options_(options),
      kernels_(kernels),
      log_(options.log && comm->getRank() == 0 ? options.log : &quiet_),
      description_(scene::describeScene(deck, laws)),
      settings_(outputSettings(deck, description_)),
      // The scene is looked up at every call: a mesh adaption replaces it during the run.
      integrator_(
          integrationSettings(deck, description_, methods),
          [this](double t, const std::vector<double>& y, std::vector<double>& dydt) {
            live_.scene().velocity(t, y, dydt);
          },
          methods),
      backbone_(
          {options.application, options.deckSource, outputDirectory(options, settings_), options.restartDirectory},
          deck, comm, *this, integrator_, state_, log_),
      files_(backbone_.files()),
      live_(description_, deck, comm, kernels, state_, *log_),
      outputs_(live_, description_, settings_, files_, integrator_.settings().steadyTolerance),
      tether_(live_, description_.capillaryNumber),
      stateSection_(state_, "timeint.")
{
  // Loaded in this order: the scene's meshes take their positions from the state.
  if (options_.restartDirectory) {
    restore();
  }
  live_.build();
  if (integrator_.settings().adaptive) { // the cells as the deck builds them (a restart's too)
    std::vector<mesh::SurfaceMesh> cells;
    for (int c = 0; c < live_.scene().numCells(); ++c) {
      cells.push_back(live_.scene().cell(c));
    }
    scene::requireToleranceBelowCellSize(integrator_.settings().tolerance, "Time integration/Tolerance", description_,
                                         scene::smallestSemiAxes(cells));
  }
  outputs_.setCheckpointWriter([this] { backbone_.writeCheckpoint(); });
  // A stage state or step result with a node through the wall or a folded membrane rejects
  // the attempt (NodesAboveWall.hpp, UnfoldedMembranes.hpp).
  integrator_.setDomainCheck([this](const std::vector<double>& y) {
    scene::requireNodesAboveWall(live_.scene(), y);
    scene::requireUnfoldedMembranes(live_.scene(), y);
  });
  if (live_.scene().hasConstraints()) {
    integrator_.setStageConstraint(
        [this](double, const std::vector<double>& y, std::vector<double>& dydt) { live_.scene().constrain(y, dydt); });
  }
  std::vector<std::string> terms = live_.scene().terms();
  for (auto& term : outputs_.terms()) {
    terms.push_back(std::move(term));
  }
  terms.push_back(integrator_.describe());
  attachJacobian();
  if (jacobian_) {
    terms.push_back(jacobian_->describe());
  }
  terms_ = std::move(terms);
}

// The stiff methods' Jacobian of the scene as it is now (a mesh adaption replaces the scene).
void SceneRunner::attachJacobian()
{
  if (!integrator_.needsLinearisedSystem() || jacobianScene_ == &live_.scene()) {
    return;
  }
  jacobian_ = std::make_shared<scene::VelocityJacobian>(live_.scene(), deck_, kernels_);
  jacobianScene_ = &live_.scene();
  integrator_.setLinearisedSystem(jacobian_);
}

void SceneRunner::restore()
{
  // Every rank reads the (small) checkpoint itself (RunBackbone): no broadcast of its contents needed.
  backbone_.restore();
  // The record the run continues, checked before anything is written.
  requireTableUpToCheckpoint(*options_.restartDirectory, "metrics.csv", state_.time, outputs_.outputsWritten());
  core::require<core::InputError>(!state_.steady, "--restart ", *options_.restartDirectory,
                                  ": the run reached a steady state at t = ", state_.time,
                                  " ('Time integration/Steady tolerance'); a restart has nothing to do.");
  backbone_.requireTimeLeft(state_.time, integrator_.settings().endTime);
  restarted_ = true;
}

// After every step: if two cell surfaces are closer than 'Cells/Minimum gap', records the
// state as an output (metrics row, snapshot, checkpoint) and the reason. Every rank holds
// the same state, so every rank takes the same decision.
bool SceneRunner::cellsTooClose(const timeint::IntegrationState& state)
{
  if (live_.scene().numCells() < 2) {
    return false;
  }
  ClosestPair closest;
  {
    Teuchos::TimeMonitor guard(*core::timer("Cell gap"));
    closest = closestPair(live_.scene(), state.y);
  }
  if (closest.gap >= description_.minimumGap) {
    return false;
  }
  std::ostringstream reason;
  reason << std::setprecision(6) << "Stopped at t = " << state.time << ": the surfaces of '"
         << description_.cells[static_cast<std::size_t>(closest.first)].path << "' and '"
         << description_.cells[static_cast<std::size_t>(closest.second)].path << "' are " << closest.gap
         << " apart, less than 'Cells/Minimum gap' = " << description_.minimumGap
         << ". The outputs and the checkpoint at this time are in " << files_.directory() << ".";
  stopReason_ = reason.str();
  outputs_.observe(state);
  progress(state);
  backbone_.writeSummary("too close", stopReason_, outputs_.lastTime());
  log() << stopReason_ << "\n";
  return true;
}

timeint::ObserverVerdict SceneRunner::afterStep(timeint::IntegrationState& state, const timeint::StepReport&,
                                                bool atOutputTime)
{
  attachJacobian(); // RunScene, observed before, may have rebuilt the scene
  tooClose_ = cellsTooClose(state);
  if (tooClose_) {
    return timeint::ObserverVerdict::Stop;
  }
  if (state.statistics.acceptedSteps % settings_.progressSteps == 0 && !atOutputTime) {
    progress(state);
  }
  return timeint::ObserverVerdict::Continue;
}

// After the outputs (SceneOutputs observes first): summary.json and a progress line.
timeint::ObserverVerdict SceneRunner::atOutput(const timeint::IntegrationState& state, timeint::OutputReason)
{
  backbone_.writeSummary(outputs_.steady() ? "steady" : "running", "", outputs_.lastTime());
  progress(state);
  return timeint::ObserverVerdict::Continue;
}

void SceneRunner::progress(const timeint::IntegrationState& state)
{
  const double end = integrator_.settings().endTime;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart_).count();
  std::ostringstream line;
  line << std::setprecision(4) << "t = " << state.time << " / " << end << " (" << std::setprecision(3)
       << 100.0 * state.time / end << "%)  step " << state.statistics.acceptedSteps << "  dt " << std::scientific
       << std::setprecision(2) << state.statistics.lastStep << std::defaultfloat << std::setprecision(4);
  if (const std::optional<double> d12 = outputs_.d12At(state.time)) { // measured at outputs only
    line << "  D12 " << *d12;
  }
  line << "  ETA " << wallClock(timeLeft(elapsed, simulatedStart_, state.time, end));
  if (jacobian_) { // the stiff methods: which one runs, and the Krylov work so far
    const auto& stats = state.statistics;
    line << "  [" << integrator_.activeMethodName(state) << std::setprecision(3) << ", "
         << (stats.linearSolves > 0
                 ? static_cast<double>(stats.linearIterations) / static_cast<double>(stats.linearSolves)
                 : 0.0)
         << " GMRES it/solve]";
  }
  log() << line.str() << std::endl;
}

// The scene's entries of summary.json: the outputs' results, the tether's.
void SceneRunner::addResults(io::JsonValue& json) const
{
  outputs_.addResults(json);
  tether_.addResults(json, outputs_.steady());
}

SceneRunResult SceneRunner::execute()
{
  wallStart_ = std::chrono::steady_clock::now();
  backbone_.open();
  outputs_.open(restarted_ ? std::optional<double>(state_.time) : std::nullopt);
  backbone_.begin(terms_);

  timeint::OutputSchedule schedule;
  schedule.interval = settings_.interval;
  backbone_.recordingFailure([&] {
    if (!restarted_) {
      state_ = integrator_.start(0.0, live_.scene().initialPositions());
    } else {
      log() << "Restarted from " << *options_.restartDirectory << " at t = " << state_.time << ", step "
            << state_.statistics.acceptedSteps << "\n";
    }
    // The start is observed (never steady: the test needs t > 0); the ETA counts from after it.
    simulatedStart_ = state_.time;
    try {
      integrator_.integrate(state_, schedule, {&backbone_, &live_, &tether_, &outputs_, this, &backbone_.watch()});
    } catch (const core::NumericalError& e) {
      // With what the last output says of a softened membrane law (a fold or step collapse
      // that follows has that cause).
      throw core::NumericalError(e.what() + outputs_.softeningNote());
    }
  });
  if (backbone_.signal() != 0 && !tooClose_ && !outputs_.steady()) {
    backbone_.stopInterrupted();
  }
  const std::string status = tooClose_ ? "too close" : outputs_.steady() ? "steady" : "finished";
  backbone_.writeSummary(status, stopReason_, outputs_.lastTime());
  report(status);
  SceneRunResult result;
  result.status = status;
  result.time = state_.time;
  result.acceptedSteps = state_.statistics.acceptedSteps;
  result.outputDirectory = files_.directory();
  result.terms = backbone_.summary().terms();
  return result;
}

// The key results of the last output, and how to look at the files.
void SceneRunner::report(const std::string& status)
{
  if (outputs_.steady()) {
    log() << "Steady state at t = " << state_.time << ": the shape changes slower than "
          << integrator_.settings().steadyTolerance << "\n";
  }
  log() << "Done: " << status << " at t = " << state_.time << " after " << state_.statistics.acceptedSteps << " steps ("
        << state_.statistics.rejectedSteps << " rejected); outputs in " << files_.directory() << "\n";
  const auto& samples = outputs_.lastSamples();
  for (std::size_t c = 0; c < samples.size(); ++c) {
    const CellSample& sample = samples[c];
    log() << "  " << description_.cells[c].path << ": D12 " << sample.shape.deformation.D12 << ", centroid ("
          << sample.shape.centroid[0] << ", " << sample.shape.centroid[1] << ", " << sample.shape.centroid[2]
          << "), u_slip " << sample.slipVelocity() << ", u_migr " << sample.migrationVelocity() << ", volume change "
          << sample.volumeChange << ", mean shear stress " << sample.stress.mean << "\n";
    if (sample.tether) {
      const double ca = description_.capillaryNumber, force = sample.tether->state.force.norm();
      log() << "  tether: peak force " << tether_.peakForce() << " G a (" << tether_.peakForce() / ca
            << " mu k a^2) at t = " << tether_.peakTime() << ", final " << force << " G a (" << force / ca
            << " mu k a^2), angle to the wall " << sample.tether->state.inclinationDegrees << ", pivot angle "
            << sample.tether->pivotAngleDegrees << " degrees\n";
    }
  }
  log() << "  metrics.csv (one row per output), summary.json (final and steady values)";
  if (settings_.snapshots) {
    log() << "; ParaView: open " << files_.directory() << "/snapshots.xdmf";
  }
  log() << "\n";
}

} // namespace

SceneRunResult runScene(const Teuchos::ParameterList& validatedDeck, const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                        const SceneRunOptions& options, const operators::KernelRegistry& kernels,
                        const elasticity::MembraneLawRegistry& laws, const timeint::MethodRegistry& methods)
{
  SceneRunner run(validatedDeck, comm, options, kernels, laws, methods);
  return run.execute();
}

} // namespace capsula::run
