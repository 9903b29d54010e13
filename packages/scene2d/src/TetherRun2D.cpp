#include "capsula/scene2d/TetherRun2D.hpp"

#include "capsula/scene2d/NodesInFluid2D.hpp"
#include "capsula/scene2d/VelocityJacobian2D.hpp"

#include <capsula/contour/ContourMetrics.hpp>
#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/core/RunInfo.hpp>
#include <capsula/io/Checkpoint.hpp>
#include <capsula/io/Json.hpp>
#include <capsula/io/MetricsCsv.hpp>
#include <capsula/io/OutputDirectory.hpp>
#include <capsula/io/SnapshotSeries.hpp>
#include <capsula/operators/ContourDiscretisation2D.hpp>
#include <capsula/timeint/TimeIntegrationParameters.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <memory>
#include <optional>
#include <ostream>
#include <utility>

namespace capsula::scene2d {

void declareOutputParameters2D(Teuchos::ParameterList& output)
{
  namespace core = capsula::core;
  const OutputSettings2D defaults;
  core::declareString(output, "Directory", defaults.directory,
                      "Where the run writes (empty: nowhere). --output overrides it.");
  core::declareReal(output, "Interval", defaults.interval,
                    "tau = k t / lambda between rows of the metrics tables.", core::greaterThan(0.0));
  core::declareInt(output, "Snapshot every", defaults.snapshotEvery,
                   "Outputs between contour snapshots (HDF5 + XDMF); 0: none but the first and last.", 0,
                   1000000);
  core::declareInt(output, "Checkpoint every", defaults.checkpointEvery,
                   "Outputs between checkpoints (checkpoint.h5, overwritten); 0: at the end only.", 0, 1000000);
}

OutputSettings2D readOutputSettings2D(const Teuchos::ParameterList& output)
{
  OutputSettings2D s;
  s.directory = output.get<std::string>("Directory");
  s.interval = output.get<double>("Interval");
  s.snapshotEvery = output.get<int>("Snapshot every");
  s.checkpointEvery = output.get<int>("Checkpoint every");
  return s;
}

namespace {

enum class Stage : int { Preparation = 0, Tethered = 1, Free = 2 };

/// What the run carries besides the integration state (all of it goes into checkpoints).
struct Progress {
  Stage stage = Stage::Free;
  double origin = 0.0;          // t0, the start of the current stage in k t
  long long outputIndex = 0;    // outputs written in the current stage
  long long steps = 0;          // accepted steps, both stages
  long long evaluations = 0;    // right-hand sides of finished stages
  double previousD12 = 0.0;     // preparation: D12 at the last check (a multiple of the window)
  double preparationRate = 0.0; // preparation: d D12 / d tau over the last window
  double preparationEnd = -1.0; // preparation: predicted tau of its end (< 0: none yet)
  bool placing = false;         // preparation: shape settled, waiting for a node at the bottom
  int placeNode = -1;           // placing: the lowest node after the last step
  double placeSlope = 0.0;      // placing: its tangent's y-component then
  double placeTime = 0.0;       // placing: k t of that sample
  double placeTarget = -1.0;    // placing: predicted k t of the crossing (< 0: none)
  double nextRegrid = 0.0;      // preparation: tau of the next regrid of the free cell
  long long lastSnapshot = -1;  // output index of the last snapshot in this stage
  bool steady = false;
};

std::vector<std::string> tableColumns()
{
  std::vector<std::string> columns{"time", "step", "dt"};
  for (const auto& name : metricColumns()) {
    columns.push_back(name);
  }
  for (const char* name : {"raw_time", "gmres_iterations", "steady_measure"}) {
    columns.emplace_back(name);
  }
  return columns;
}

const char* baseName(Stage stage)
{
  return stage == Stage::Preparation ? "preparation" : "contour";
}

io::Snapshot snapshotOf(const contour::Contour& contour, const elasticity::MembraneState2D& membrane,
                        const std::vector<double>& velocities, double tau, long long step)
{
  const int n = contour.numberOfNodes();
  io::SnapshotBlock block;
  block.name = "cell";
  block.topology = io::Topology::Polylines;
  block.dimension = 2;
  block.nodesPerPolyline = n + 1;
  block.positions.assign(contour.nodes().data(), contour.nodes().data() + 2 * n);
  for (int i = 0; i <= n; ++i) {
    block.connectivity.push_back(i % n);
  }
  io::Field tension{"tension", 1, {}}, stretch{"stretch", 1, {}}, load{"load", 2, {}}, velocity{"velocity", 2, {}},
    parameter{"s_over_smax", 1, {}};
  const std::vector<double>& s = contour.parameters();
  for (int i = 0; i < n; ++i) {
    tension.values.push_back(membrane.tension()(i));
    stretch.values.push_back(membrane.stretch()(i));
    load.values.push_back(membrane.load()(0, i));
    load.values.push_back(membrane.load()(1, i));
    velocity.values.push_back(velocities[2 * i]);
    velocity.values.push_back(velocities[2 * i + 1]);
    parameter.values.push_back(s[static_cast<std::size_t>(i)] / s.back());
  }
  block.nodeFields = {tension, stretch, load, velocity, parameter};
  io::Snapshot snapshot;
  snapshot.time = tau;
  snapshot.step = step;
  snapshot.blocks.push_back(std::move(block));
  return snapshot;
}

// Stiff time integration: what a fresh integration state at new markers (a regrid, the
// tethering) keeps of the old one, the stiff methods' counters and Auto's choice of method
// (the counters belong to the run; the method suits the membrane, which is the same).
void keepStiffProgress(const timeint::IntegrationState& from, timeint::IntegrationState& to)
{
  const timeint::IntegrationStatistics& a = from.statistics;
  timeint::IntegrationStatistics& b = to.statistics;
  b.stiffSteps = a.stiffSteps;
  b.stiffRhsEvaluations = a.stiffRhsEvaluations;
  b.linearisations = a.linearisations;
  b.linearSolves = a.linearSolves;
  b.linearIterations = a.linearIterations;
  b.largestLinearIterations = a.largestLinearIterations;
  b.failedLinearSolves = a.failedLinearSolves;
  b.methodSwitches = a.methodSwitches;
  to.stiffActive = from.stiffActive;
  to.stiffAdvanceRate = from.stiffAdvanceRate;
}

// Stiff time integration: the integrator's counters in summary.json ("timings"), where a
// stiff step was taken or the method switched.
void writeStiffStatistics(const timeint::IntegrationStatistics& s, long long jacobianApplications,
                          io::JsonValue& timings)
{
  if (s.stiffSteps == 0 && s.methodSwitches == 0) {
    return;
  }
  timings["stiff_steps"] = static_cast<long long>(s.stiffSteps);
  timings["rhs_evaluations_in_stiff_steps"] = static_cast<long long>(s.stiffRhsEvaluations);
  timings["linearisations"] = static_cast<long long>(s.linearisations);
  timings["linear_solves"] = static_cast<long long>(s.linearSolves);
  timings["linear_iterations"] = static_cast<long long>(s.linearIterations);
  timings["linear_iterations_per_stiff_step"] =
    s.stiffSteps > 0 ? static_cast<double>(s.linearIterations) / static_cast<double>(s.stiffSteps) : 0.0;
  timings["largest_linear_iterations"] = static_cast<long long>(s.largestLinearIterations);
  timings["failed_linear_solves"] = static_cast<long long>(s.failedLinearSolves);
  timings["method_switches"] = static_cast<long long>(s.methodSwitches);
  timings["jacobian_applications_this_process"] = jacobianApplications;
}

} // namespace

TetherRun2D::TetherRun2D(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const Teuchos::ParameterList& deck,
                         std::ostream* log)
  : comm_(comm),
    deck_(deck),
    log_(log),
    tether_(readTetherSettings2D(deck.sublist("Tether"))),
    output_(readOutputSettings2D(deck.sublist("Output"))),
    model_(comm, readCellSettings2D(deck.sublist("Cell")),
           readFlowSettings2D(deck.sublist("Flow"), deck.sublist("Wall")),
           operators::readContourDiscretisation2D(deck.sublist("Discretisation")),
           operators::readSolverParameters(deck.sublist("Solver")))
{
  core::require<core::InputError>(!tether_.enabled || model_.flow().wall,
                                  "Tether/Enabled needs the wall (Wall/Enabled = true): the tether point is "
                                  "held above it.");
}

TetherRunResult2D TetherRun2D::run(const std::string& outputDirectory,
                                   const std::optional<std::string>& restartDirectory)
{
  const auto wallStart = std::chrono::steady_clock::now();
  const bool root = comm_->getRank() == 0;
  const bool writing = !outputDirectory.empty() && root;
  const double lambda = model_.flow().conditions.viscosityRatio;

  timeint::TimeIntegrationSettings settings = timeint::timeIntegrationSettings(deck_.sublist("Time integration"));
  const double endTau = settings.endTime; // the tethered (or free) stage's duration in tau
  timeint::TimeIntegrator integrator(settings, [this](double, const std::vector<double>& y, std::vector<double>& dydt) {
    model_.rightHandSide(y, dydt);
  });
  // With the wall, a stage state or a step with a node on or below it is a rejected
  // attempt (NodesInFluid2D.hpp), not a failure of the run.
  if (model_.flow().wall) {
    integrator.setDomainCheck(requireNodesInFluid);
  }
  // Stiff time integration: the Jacobian (VelocityJacobian2D.hpp) reads the model at every
  // linearisation, so it follows the tethering and the regrids as it is.
  std::shared_ptr<VelocityJacobian2D> jacobian;
  if (timeint::needsLinearisedSystem(settings.method)) {
    jacobian = std::make_shared<VelocityJacobian2D>(model_, comm_, deck_);
    integrator.setLinearisedSystem(jacobian);
  }
  std::vector<std::string> timeIntegrationTerms{timeint::describeTimeIntegration(integrator.settings())};
  if (jacobian) {
    timeIntegrationTerms.push_back(jacobian->describe());
  }
  if (log_ != nullptr) {
    for (const std::string& term : timeIntegrationTerms) {
      *log_ << term << "\n";
    }
  }
  struct MethodSwitch {
    std::string stage;
    double tau;
    std::string reason;
  };
  std::vector<MethodSwitch> methodSwitches;   // Auto, this process

  const std::vector<std::string> columns = tableColumns();
  std::optional<io::OutputDirectory> directory;
  std::optional<io::MetricsCsv> table;
  std::optional<io::SnapshotSeries> series;
  if (writing) {
    directory.emplace(outputDirectory);
    directory->writeRunMetadata(deck_, {"tether2d", "", comm_->getSize()});
  }

  TetherRunResult2D result;
  Progress progress;
  auto stageWallStart = wallStart; // for the ETA of the tethered (or free) stage:
  double stageTauStart = 0.0;      // wall time and tau since the stage (or the restart) began
  timeint::IntegrationState state;
  const auto tauOf = [&](double t) { return (t - progress.origin) / lambda; };

  // Output of the current state: a row, maybe a snapshot (collective: needs the velocity).
  const auto observe = [&](double stepSize, double steadyMeasure, bool forceSnapshot) {
    const contour::Contour current = model_.contour(state.y);
    const elasticity::MembraneState2D membrane = model_.membrane(current);
    const std::vector<double> velocities = model_.velocities(current, membrane).velocities;
    const CellMetrics2D metrics = cellMetrics2D(model_, current, membrane, velocities);
    const double tau = tauOf(state.time);
    result.final = metrics;
    result.finalTime = tau;
    result.maxAbsAreaDrift = std::max(result.maxAbsAreaDrift, std::abs(metrics.areaDrift));
    const bool snapshot = forceSnapshot ||
                          (output_.snapshotEvery > 0 && progress.outputIndex % output_.snapshotEvery == 0);
    if (writing) {
      std::vector<double> row{tau, static_cast<double>(progress.steps), stepSize};
      for (const double v : metricValues(metrics)) {
        row.push_back(v);
      }
      row.push_back(state.time);
      row.push_back(model_.lastIterations());
      row.push_back(steadyMeasure);
      table->appendRow(row);
      if (snapshot && progress.lastSnapshot != progress.outputIndex) {
        series->write(snapshotOf(current, membrane, velocities, tau, progress.steps));
      }
    }
    if (snapshot) {
      progress.lastSnapshot = progress.outputIndex;
      if (log_ != nullptr) {
        *log_ << (progress.stage == Stage::Preparation ? "preparation" : "tau") << " = " << tau
              << ": A/A0 = " << metrics.contourLengthRatio << ", L_cell = " << metrics.cellLength
              << ", F = " << metrics.tetherForce << ", D12 = " << metrics.D12
              << ", area drift = " << metrics.areaDrift;
        if (jacobian) {   // stiff time integration: the method in use, the Krylov work so far
          const timeint::IntegrationStatistics& stats = state.statistics;
          *log_ << " [" << integrator.activeMethodName(state) << ", " << std::setprecision(3)
                << (stats.linearSolves > 0
                      ? static_cast<double>(stats.linearIterations) / static_cast<double>(stats.linearSolves)
                      : 0.0)
                << " GMRES it/solve]" << std::setprecision(6);
        }
        // ETA of the stage from its wall time per unit tau so far (the preparation's end
        // depends on the shape, so it has none).
        if (progress.stage != Stage::Preparation && tau > stageTauStart && tau < endTau) {
          const double spent =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - stageWallStart).count();
          const long long left = std::llround(spent / (tau - stageTauStart) * (endTau - tau));
          *log_ << " (" << std::llround(100.0 * tau / endTau) << "% of tau = " << endTau << ", ETA "
                << left / 3600 << ":" << (left / 600) % 6 << (left / 60) % 10 << ":" << (left % 60) / 10
                << left % 10 << ")";
        }
        *log_ << "\n";
      }
    }
  };

  // The extremes of the tethered (or free) stage, after every accepted step: they need
  // the membrane only (no velocity solve), and output times would sample them coarsely.
  const auto trackExtremes = [&]() {
    const contour::Contour current = model_.contour(state.y);
    const double force = model_.membrane(current).netForce(model_.discretisation().gaussLegendrePoints).norm();
    const double tau = tauOf(state.time);
    if (force > result.maxTetherForce) {
      result.maxTetherForce = force;
      result.timeOfMaxTetherForce = tau;
    }
    // tau counts from tethering in the tethered stage (from 0 in a free run).
    if (tau >= tether_.forceTransient && force > result.maxTetherForceAfterTransient) {
      result.maxTetherForceAfterTransient = force;
      result.timeOfMaxTetherForceAfterTransient = tau;
    }
    result.maxContourLengthRatio = std::max(result.maxContourLengthRatio, current.length() / model_.referenceLength());
    result.maxCellLength = std::max(result.maxCellLength, contour::cellLength(current));
  };

  const auto startStage = [&](Stage stage) {
    progress.stage = stage;
    progress.origin = state.time;
    stageWallStart = std::chrono::steady_clock::now();
    stageTauStart = 0.0;
    progress.outputIndex = 0;
    progress.lastSnapshot = -1;
    if (writing) {
      table.emplace(directory->file(stage == Stage::Preparation ? "preparation.csv" : "metrics.csv"), columns);
      series.emplace(outputDirectory, baseName(stage));
    }
  };

  const auto writeCheckpoint = [&]() {
    if (!writing) {
      return;
    }
    io::Checkpoint checkpoint;
    checkpoint.time = tauOf(state.time);
    checkpoint.step = progress.steps;
    checkpoint.stepSize = state.proposedStep;
    checkpoint.deckXml = core::deckToXml(deck_, false);
    const timeint::StateRecord record = timeint::toRecord(state);
    checkpoint.arrays = record.arrays;
    checkpoint.reals = record.reals;
    checkpoint.integers = record.integers;
    checkpoint.integers["run stage"] = static_cast<std::int64_t>(progress.stage);
    checkpoint.integers["run output index"] = progress.outputIndex;
    checkpoint.integers["run steps"] = progress.steps;
    checkpoint.integers["run evaluations"] = progress.evaluations;
    checkpoint.integers["run last snapshot"] = progress.lastSnapshot;
    checkpoint.integers["run tether offset"] = model_.tetherOffset();
    checkpoint.reals["run next regrid"] = progress.nextRegrid;
    // The membrane's reference is rebuilt from the deck on restart, so the deck must have
    // the same prestress (checked there).
    checkpoint.reals["run cell prestress"] = model_.cell().prestress;
    if (model_.freeCellRegridded()) {
      const Eigen::Matrix2Xd& free = model_.freeReferenceNodes();
      checkpoint.arrays["run free reference nodes"] = std::vector<double>(free.data(), free.data() + free.size());
    }
    if (const Eigen::Matrix2Xd& regridded = model_.regriddedReference(); regridded.size() > 0) {
      checkpoint.arrays["run regridded reference nodes"] =
          std::vector<double>(regridded.data(), regridded.data() + regridded.size());
    }
    checkpoint.reals["run origin"] = progress.origin;
    checkpoint.reals["run previous D12"] = progress.previousD12;
    checkpoint.reals["run preparation rate"] = progress.preparationRate;
    checkpoint.reals["run preparation end"] = progress.preparationEnd;
    checkpoint.integers["run placing"] = progress.placing ? 1 : 0;
    checkpoint.integers["run place node"] = progress.placeNode;
    checkpoint.reals["run place slope"] = progress.placeSlope;
    checkpoint.reals["run place time"] = progress.placeTime;
    checkpoint.reals["run place target"] = progress.placeTarget;
    checkpoint.reals["run preparation time"] = result.preparationTime;
    checkpoint.reals["run max tether force"] = result.maxTetherForce;
    checkpoint.reals["run time of max tether force"] = result.timeOfMaxTetherForce;
    checkpoint.reals["run max tether force after transient"] = result.maxTetherForceAfterTransient;
    checkpoint.reals["run time of max tether force after transient"] = result.timeOfMaxTetherForceAfterTransient;
    checkpoint.reals["run max contour length ratio"] = result.maxContourLengthRatio;
    checkpoint.reals["run max cell length"] = result.maxCellLength;
    checkpoint.reals["run max abs area drift"] = result.maxAbsAreaDrift;
    if (const auto* warm = model_.gmresWarmStart(); warm && !warm->empty()) {   // the next solve's start
      checkpoint.arrays["run gmres warm start rhs"] = warm->rightHandSides();
      checkpoint.arrays["run gmres warm start solutions"] = warm->solutions();
    }
    io::writeCheckpoint(directory->file("checkpoint.h5"), checkpoint);
  };

  if (restartDirectory) {
    const std::string path = *restartDirectory + "/checkpoint.h5";
    const io::Checkpoint checkpoint = io::readCheckpoint(path);
    timeint::StateRecord record;
    record.arrays = checkpoint.arrays;
    record.reals = checkpoint.reals;
    record.integers = checkpoint.integers;
    state = timeint::fromRecord(record, path);
    core::require<core::InputError>(state.y.size() == 2 * static_cast<std::size_t>(model_.numberOfNodes()),
                                    "The checkpoint ", path, " holds ", state.y.size() / 2,
                                    " nodes but the deck asks for Cell/Number of points = ",
                                    model_.numberOfNodes(), ".");
    progress.stage = static_cast<Stage>(checkpoint.integers.at("run stage"));
    progress.outputIndex = checkpoint.integers.at("run output index");
    progress.steps = checkpoint.integers.at("run steps");
    progress.evaluations = checkpoint.integers.at("run evaluations");
    progress.lastSnapshot = checkpoint.integers.at("run last snapshot");
    progress.origin = checkpoint.reals.at("run origin");
    stageTauStart = checkpoint.time;
    progress.previousD12 = checkpoint.reals.at("run previous D12");
    const auto rate = checkpoint.reals.find("run preparation rate"); // absent before the windowed check
    progress.preparationRate = rate == checkpoint.reals.end() ? 0.0 : rate->second;
    const auto end = checkpoint.reals.find("run preparation end");
    progress.preparationEnd = end == checkpoint.reals.end() ? -1.0 : end->second;
    // Absent from checkpoints written before the placement phase: not placing.
    const auto placing = checkpoint.integers.find("run placing");
    if (placing != checkpoint.integers.end() && placing->second != 0) {
      progress.placing = true;
      progress.placeNode = static_cast<int>(checkpoint.integers.at("run place node"));
      progress.placeSlope = checkpoint.reals.at("run place slope");
      progress.placeTime = checkpoint.reals.at("run place time");
      progress.placeTarget = checkpoint.reals.at("run place target");
    }
    result.preparationTime = checkpoint.reals.at("run preparation time");
    result.maxTetherForce = checkpoint.reals.at("run max tether force");
    result.timeOfMaxTetherForce = checkpoint.reals.at("run time of max tether force");
    if (const auto after = checkpoint.reals.find("run max tether force after transient");
        after != checkpoint.reals.end()) {   // absent from checkpoints written before it existed
      result.maxTetherForceAfterTransient = after->second;
      result.timeOfMaxTetherForceAfterTransient = checkpoint.reals.at("run time of max tether force after transient");
    }
    result.maxContourLengthRatio = checkpoint.reals.at("run max contour length ratio");
    result.maxCellLength = checkpoint.reals.at("run max cell length");
    result.maxAbsAreaDrift = checkpoint.reals.at("run max abs area drift");
    result.tethered = progress.stage == Stage::Tethered;
    // Absent from checkpoints written before Cell/Prestress existed: those runs had none.
    const auto prestress = checkpoint.reals.find("run cell prestress");
    const double checkpointPrestress = prestress == checkpoint.reals.end() ? 0.0 : prestress->second;
    core::require<core::InputError>(checkpointPrestress == model_.cell().prestress, "The checkpoint ", path,
                                    " was written with Cell/Prestress = ", checkpointPrestress,
                                    " but the deck has ", model_.cell().prestress,
                                    ": the membrane's reference would change; restart with the run's deck.");
    if (const auto next = checkpoint.reals.find("run next regrid"); next != checkpoint.reals.end()) {
      progress.nextRegrid = next->second;
    }
    if (const auto free = checkpoint.arrays.find("run free reference nodes"); free != checkpoint.arrays.end()) {
      core::require<core::InputError>(free->second.size() == state.y.size(), "The checkpoint ", path, " holds ",
                                      free->second.size() / 2, " free reference nodes for ", state.y.size() / 2,
                                      " nodes.");
      model_.regridFree(Eigen::Map<const Eigen::Matrix2Xd>(free->second.data(), 2, model_.numberOfNodes()));
    }
    if (progress.stage == Stage::Tethered) {
      if (const auto regridded = checkpoint.arrays.find("run regridded reference nodes");
          regridded != checkpoint.arrays.end()) {
        core::require<core::InputError>(regridded->second.size() == state.y.size(), "The checkpoint ", path,
                                        " holds ", regridded->second.size() / 2, " regridded reference nodes for ",
                                        state.y.size() / 2, " nodes.");
        model_.tether(Eigen::Map<const Eigen::Matrix2Xd>(regridded->second.data(), 2, model_.numberOfNodes()));
      } else {
        model_.tether(static_cast<int>(checkpoint.integers.at("run tether offset")));
      }
    }
    // After tether(), which drops the history: the next solve starts where it would have.
    const auto warmRhs = checkpoint.arrays.find("run gmres warm start rhs");
    const auto warmSolutions = checkpoint.arrays.find("run gmres warm start solutions");
    if (warmRhs != checkpoint.arrays.end() && warmSolutions != checkpoint.arrays.end()) {
      model_.restoreGmresWarmStart(warmRhs->second, warmSolutions->second);
    }
    if (writing) {
      const std::string file = progress.stage == Stage::Preparation ? "preparation.csv" : "metrics.csv";
      table.emplace(io::MetricsCsv::resume(directory->file(file), columns, checkpoint.time));
      series.emplace(io::SnapshotSeries::resume(outputDirectory, baseName(progress.stage), checkpoint.time));
    }
    if (log_ != nullptr) {
      *log_ << "Restarting from " << path << " at tau = " << checkpoint.time << " (step " << checkpoint.step
            << ")\n";
    }
  } else {
    state = integrator.start(0.0, model_.initialState());
    startStage(tether_.enabled ? Stage::Preparation : Stage::Free);
    progress.previousD12 = contour::taylorDeformation(model_.contour(state.y));
    observe(0.0, 0.0, true);
    if (progress.stage == Stage::Free) {
      trackExtremes();
    }
  }

  const long long evaluationsAtStart = progress.evaluations + state.statistics.rhsEvaluations;
  for (;;) {
    const bool preparing = progress.stage == Stage::Preparation;
    const double stageEnd = preparing ? tether_.maximumPreparationTime : endTau;
    if (!preparing && (progress.steady || tauOf(state.time) >= stageEnd * (1.0 - 1e-12))) {
      break;
    }
    // Output k at k * interval; one within a hair of the stage's end is the end (no sliver).
    double nextOutputTau = static_cast<double>(progress.outputIndex + 1) * output_.interval;
    if (nextOutputTau >= stageEnd - 1e-9 * output_.interval) {
      nextOutputTau = stageEnd;
    }
    const double tOut = progress.origin + lambda * nextOutputTau;
    // The preparation stage also lands on its check times (multiples of the window).
    const double nextCheckTau =
      !preparing || progress.placing ? stageEnd
      : progress.preparationEnd > 0.0 ? std::min(progress.preparationEnd, stageEnd)
                                       : std::min(nextPreparationCheck(tether_, tauOf(state.time)), stageEnd);
    const double tCheck = progress.origin + lambda * nextCheckTau;
    const double tPlace =
      preparing && progress.placing && progress.placeTarget > state.time ? progress.placeTarget : tCheck;
    const double tTarget = preparing ? std::min({tOut, tCheck, tPlace}) : tOut;
    if (!(tTarget > state.time)) { // a stage of zero length
      if (preparing) {
        progress.outputIndex += 1;
      } else {
        break;
      }
    } else {
      const timeint::StepReport report = integrator.step(state, tTarget);
      ++progress.steps;
      if (!report.switchReason.empty()) {   // Auto changed method
        methodSwitches.push_back({progress.stage == Stage::Preparation ? "preparation"
                                  : progress.stage == Stage::Tethered ? "tethered"
                                                                      : "free",
                                  tauOf(state.time), report.switchReason});
        if (log_ != nullptr) {
          *log_ << "tau = " << tauOf(state.time) << ": " << report.switchReason << "\n";
        }
      }
      const bool atOutput = state.time == tOut;
      if (atOutput) {
        ++progress.outputIndex;
      }
      if (!preparing) {
        trackExtremes();
        progress.steady = settings.steadyCriterion != timeint::SteadyStateCriterion::Off && !report.shortened &&
                          report.steadyMeasure < settings.steadyTolerance;
        if (atOutput || progress.steady) {
          const bool last = progress.steady || tauOf(state.time) >= endTau * (1.0 - 1e-12);
          observe(report.stepSize, report.steadyMeasure, last);
          if (output_.checkpointEvery > 0 && progress.outputIndex % output_.checkpointEvery == 0) {
            writeCheckpoint();
          }
        }
        continue;
      }
      const double tau = tauOf(state.time);
      bool done = tau >= tether_.maximumPreparationTime * (1.0 - 1e-12);
      bool settled = false; // the shape criterion holds: wait for a node at the bottom
      if (progress.placing) {
        // A node through the lowest point of the contour (TetherProcedure2D.hpp).
        const LowestNodeSlope lowest = lowestNodeSlope(model_.contour(state.y));
        const bool sameNode = lowest.node == progress.placeNode;
        if (state.time == tPlace || (sameNode && lowest.slope * progress.placeSlope <= 0.0)) {
          done = true;
        } else {
          progress.placeTarget =
            sameNode ? predictedZeroCrossing(progress.placeTime, progress.placeSlope, state.time, lowest.slope) : -1.0;
        }
        progress.placeNode = lowest.node;
        progress.placeSlope = lowest.slope;
        progress.placeTime = state.time;
      } else if (state.time == tCheck && progress.preparationEnd > 0.0) {
        settled = true; // landed on the predicted end (TetherProcedure2D.hpp)
      } else if (state.time == tCheck) {
        // d D12 / d tau over the window since the last check (TetherProcedure2D.hpp).
        const double d12 = contour::taylorDeformation(model_.contour(state.y));
        const double previousRate = progress.preparationRate;
        progress.preparationRate = (d12 - progress.previousD12) / tether_.preparationWindow;
        progress.previousD12 = d12;
        if (tau >= tether_.minimumPreparationTime) {
          settled = preparationComplete(tether_, tau, progress.preparationRate);
          const double end = predictedPreparationEnd(tether_, tau, previousRate, progress.preparationRate);
          if (!settled && end > tau) {
            progress.preparationEnd = end;
          } else if (!settled && end > 0.0) {
            settled = true; // the extrapolated crossing lies inside the last window: now
          }
        }
      }
      if (!done && !settled && state.time == tCheck && tether_.preparationRegridInterval > 0.0 &&
          tau >= progress.nextRegrid * (1.0 - 1e-12)) {
        // New markers graded towards the free cell's lowest point (TetherRegrid2D.hpp).
        const TetherRegrid2D regrid = regridTowardsLowestPoint(contour::Contour(model_.freeReferenceNodes()),
                                                               model_.contour(state.y), tether_.grading);
        model_.regridFree(regrid.referenceNodes);
        progress.evaluations += state.statistics.rhsEvaluations;
        const double proposed = state.proposedStep;
        const long long accepted = state.statistics.acceptedSteps;
        timeint::IntegrationState regridded = integrator.start(
          state.time, std::vector<double>(regrid.currentNodes.data(),
                                          regrid.currentNodes.data() + regrid.currentNodes.size()));
        keepStiffProgress(state, regridded);
        state = std::move(regridded);
        state.proposedStep = proposed;
        state.statistics.acceptedSteps = accepted;
        const double interval = tether_.preparationRegridInterval;
        progress.nextRegrid = (std::floor(tau / interval + 1e-9) + 1.0) * interval;
      }
      if (settled && !done && !tether_.waitForNodeAtBottom) {
        done = true;
      } else if (settled && !done) {
        const LowestNodeSlope lowest = lowestNodeSlope(model_.contour(state.y));
        progress.placing = true;
        progress.placeNode = lowest.node;
        progress.placeSlope = lowest.slope;
        progress.placeTime = state.time;
        progress.placeTarget = -1.0;
        done = lowest.slope == 0.0;
      }
      if (atOutput || done) {
        observe(report.stepSize, progress.preparationRate, done);
        if (!done && output_.checkpointEvery > 0 && progress.outputIndex % output_.checkpointEvery == 0) {
          writeCheckpoint();
        }
      }
      if (!done) {
        continue;
      }
    }
    // Tether (thesis Section 4.1): lowest node to the anchor, relabelled node 0.
    const Eigen::Map<const Eigen::Matrix2Xd> nodes(state.y.data(), 2, model_.numberOfNodes());
    const Eigen::Vector2d anchor(0.0, tether_.anchorHeight);
    const TetherPlacement2D placement = tetherPlacement(nodes, anchor);
    Eigen::Matrix2Xd tethered;
    result.preparationTime = tauOf(state.time);
    if (tether_.regrid) {   // new markers graded towards the lowest point (TetherRegrid2D.hpp)
      const TetherRegrid2D regrid = regridAtTether(contour::Contour(model_.freeReferenceNodes()),
                                                   model_.contour(state.y), tether_.grading, anchor);
      tethered = regrid.currentNodes;
      model_.tether(regrid.referenceNodes);
    } else {
      tethered = tetheredNodes(nodes, placement);
      model_.tether(placement.lowestNode);
    }
    progress.evaluations += state.statistics.rhsEvaluations;
    const double proposed = state.proposedStep;
    const long long acceptedBefore = state.statistics.acceptedSteps;
    timeint::IntegrationState fresh =
      integrator.start(state.time, std::vector<double>(tethered.data(), tethered.data() + tethered.size()));
    keepStiffProgress(state, fresh);
    state = std::move(fresh);
    state.proposedStep = proposed;
    state.statistics.acceptedSteps = acceptedBefore;
    result.tethered = true;
    if (log_ != nullptr) {
      if (tether_.regrid) {
        *log_ << "Tethered at tau = " << result.preparationTime << " (the lowest point of the spline, moved to (0, "
              << tether_.anchorHeight << "), with " << model_.numberOfNodes() << " new markers graded towards it)\n";
      } else {
        *log_ << "Tethered at tau = " << result.preparationTime << " (node " << placement.lowestNode
              << " of the free cell moved by (" << placement.shift.x() << ", " << placement.shift.y()
              << ") to (0, " << tether_.anchorHeight << "))\n";
      }
    }
    startStage(Stage::Tethered);
    observe(0.0, 0.0, true);
    trackExtremes();
  }
  writeCheckpoint();

  result.steady = progress.steady;
  result.steps = progress.steps;
  const double wallSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  if (writing) {
    io::JsonValue summary = io::JsonValue::object();
    summary["application"] = "tether2d";
    summary["git_sha"] = core::gitSha();
    summary["capsula_version"] = core::capsulaVersion();
    summary["trilinos_version"] = core::trilinosVersion();
    summary["ranks"] = comm_->getSize();
    io::JsonValue terms = io::JsonValue::array();
    terms.append(std::string("single layer, ") + model_.kernelName() + " Green's function, log-singular rule");
    if (lambda != 1.0) {
      terms.append("double layer (subtracted) with Belos GMRES, lambda != 1");
    }
    if (model_.discretisation().nearSingularDistance > 0.0) {
      terms.append("near-singular subdivision");
    }
    if (tether_.enabled) {
      terms.append("tether constraint after a free preparation stage");
    }
    for (const std::string& term : timeIntegrationTerms) {
      terms.append(term);
    }
    summary["terms"] = terms;
    summary["time_integration"]["method"] = timeint::toString(integrator.settings().method);
    summary["time_integration"]["in_use"] = integrator.activeMethodName(state);
    summary["time_integration"]["switches"] = io::JsonValue::array();
    for (const MethodSwitch& methodSwitch : methodSwitches) {
      io::JsonValue change = io::JsonValue::object();
      change["stage"] = methodSwitch.stage;
      change["tau"] = methodSwitch.tau;
      change["reason"] = methodSwitch.reason;
      summary["time_integration"]["switches"].append(change);
    }
    summary["tethered"] = result.tethered;
    summary["steady"] = result.steady;
    summary["preparation_time"] = result.preparationTime;
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
    summary["timings"]["wall_seconds_this_process"] = wallSeconds;
    summary["timings"]["accepted_steps"] = static_cast<long long>(state.statistics.acceptedSteps);
    summary["timings"]["rejected_steps"] = static_cast<long long>(state.statistics.rejectedSteps);
    const long long evaluations = progress.evaluations + state.statistics.rhsEvaluations;
    summary["timings"]["rhs_evaluations"] = evaluations;
    summary["timings"]["seconds_per_rhs_evaluation_this_process"] =
      wallSeconds / static_cast<double>(std::max(1LL, evaluations - evaluationsAtStart));
    writeStiffStatistics(state.statistics, jacobian ? jacobian->applications() : 0, summary["timings"]);
    summary["steps"] = result.steps;
    summary["deck"] = core::deckToXml(deck_, false);
    io::writeJsonFile(directory->file("summary.json"), summary);
  }
  return result;
}

} // namespace capsula::scene2d
