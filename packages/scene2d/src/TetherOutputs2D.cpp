#include "capsula/scene2d/TetherOutputs2D.hpp"

#include <capsula/contour/ContourMetrics.hpp>
#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/run/WallClock.hpp>

#include <algorithm>
#include <cmath>
#include <ostream>

namespace capsula::scene2d {

void declareOutputParameters2D(Teuchos::ParameterList& output)
{
  namespace core = capsula::core;
  const OutputSettings2D defaults;
  core::declareString(output, "Directory", defaults.directory,
                      "Where the run writes (empty: nowhere). --output overrides it.");
  core::declareReal(output, "Interval", defaults.interval, "tau = k t / lambda between rows of the metrics tables.",
                    core::greaterThan(0.0));
  core::declareInt(output, "Snapshot every", defaults.snapshotEvery,
                   "Outputs between contour snapshots (HDF5 + XDMF); 0: none but the first and last.", 0, 1000000);
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

const char* baseName(TetherStage stage)
{
  return stage == TetherStage::Preparation ? "preparation" : "contour";
}

const char* tableName(TetherStage stage)
{
  return stage == TetherStage::Preparation ? "preparation.csv" : "metrics.csv";
}

io::Snapshot snapshotOf(const contour::Contour& contour, const MembraneState2D& membrane,
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

} // namespace

TetherOutputs2D::TetherOutputs2D(CapsuleModel2D& model, const TetherStages2D& stages, const OutputSettings2D& settings,
                                 const timeint::TimeIntegrationSettings& integration, double forceTransient,
                                 run::RunOutputs& files, timeint::IntegrationState& state, std::ostream* log)
    : model_(model),
      stages_(stages),
      settings_(settings),
      integration_(integration),
      forceTransient_(forceTransient),
      files_(files),
      state_(state),
      log_(log)
{}

void TetherOutputs2D::beginStage(std::optional<double> resumeAfter)
{
  const TetherStage stage = stages_.stage();
  files_.openTable(tableName(stage), tableColumns(), resumeAfter);
  files_.openSnapshots(baseName(stage), resumeAfter);
  stageWallStart_ = std::chrono::steady_clock::now();
  stageTauStart_ = resumeAfter ? *resumeAfter : 0.0;
  if (!resumeAfter) {
    lastSnapshot_ = -1;
  }
}

void TetherOutputs2D::observe(double stepSize, double steadyMeasure, bool forceSnapshot)
{
  const contour::Contour current = model_.contour(state_.y);
  const MembraneState2D membrane = model_.membrane(current);
  const std::vector<double> velocities = model_.velocities(state_.time, current, membrane).velocities;
  const CellMetrics2D metrics = cellMetrics2D(model_, current, membrane, velocities);
  const double tau = stages_.tau(state_.time);
  const std::int64_t index = outputIndex();
  const long long steps = static_cast<long long>(state_.statistics.acceptedSteps);
  result_.final = metrics;
  result_.finalTime = tau;
  result_.maxAbsAreaDrift = std::max(result_.maxAbsAreaDrift, std::abs(metrics.areaDrift));
  const bool snapshot = forceSnapshot || (settings_.snapshotEvery > 0 && index % settings_.snapshotEvery == 0);
  std::vector<double> row{tau, static_cast<double>(steps), stepSize};
  for (const double v : metricValues(metrics)) {
    row.push_back(v);
  }
  row.push_back(state_.time);
  row.push_back(model_.lastIterations());
  row.push_back(steadyMeasure);
  files_.appendRow(tableName(stages_.stage()), row);
  if (snapshot && lastSnapshot_ != index) {
    files_.writeSnapshot(baseName(stages_.stage()),
                         [&] { return snapshotOf(current, membrane, velocities, tau, steps); });
  }
  if (snapshot) {
    lastSnapshot_ = index;
    logLine(tau, metrics);
  }
}

void TetherOutputs2D::logLine(double tau, const CellMetrics2D& metrics) const
{
  if (log_ == nullptr) {
    return;
  }
  *log_ << (stages_.preparing() ? "preparation" : "tau") << " = " << tau << ": A/A0 = " << metrics.contourLengthRatio
        << ", L_cell = " << metrics.cellLength << ", F = " << metrics.tetherForce << ", D12 = " << metrics.D12
        << ", area drift = " << metrics.areaDrift;
  // The time left in the stage at its wall time per unit tau so far (the preparation's end
  // depends on the shape, so it has none).
  const double endTau = integration_.endTime;
  if (!stages_.preparing() && tau > stageTauStart_ && tau < endTau) {
    const double spent = std::chrono::duration<double>(std::chrono::steady_clock::now() - stageWallStart_).count();
    *log_ << " (" << std::llround(100.0 * tau / endTau) << "% of tau = " << endTau << ", ETA "
          << run::wallClock(run::timeLeft(spent, stageTauStart_, tau, endTau)) << ")";
  }
  *log_ << std::endl; // flushed: a log read while the run goes on (tail -f, a pipe) shows it
}

// The extremes of the tethered (or free) stage, after every accepted step.
void TetherOutputs2D::trackExtremes()
{
  const contour::Contour current = model_.contour(state_.y);
  const double force = model_.membrane(current).netForce(model_.discretisation().gaussLegendrePoints).norm();
  const double tau = stages_.tau(state_.time);
  if (force > result_.maxTetherForce) {
    result_.maxTetherForce = force;
    result_.timeOfMaxTetherForce = tau;
  }
  // tau counts from tethering in the tethered stage (from 0 in a free run).
  if (tau >= forceTransient_ && force > result_.maxTetherForceAfterTransient) {
    result_.maxTetherForceAfterTransient = force;
    result_.timeOfMaxTetherForceAfterTransient = tau;
  }
  result_.maxContourLengthRatio = std::max(result_.maxContourLengthRatio, current.length() / model_.referenceLength());
  result_.maxCellLength = std::max(result_.maxCellLength, contour::cellLength(current));
}

timeint::ObserverVerdict TetherOutputs2D::afterStep(timeint::IntegrationState& state, const timeint::StepReport& report,
                                                    bool)
{
  lastStep_ = report;
  if (!stages_.preparing()) {
    trackExtremes();
    state.steady = integration_.steadyCriterion != timeint::SteadyStateCriterion::Off && !report.shortened &&
                   report.steadyMeasure < integration_.steadyTolerance;
  }
  return timeint::ObserverVerdict::Continue;
}

timeint::ObserverVerdict TetherOutputs2D::atOutput(const timeint::IntegrationState& state, timeint::OutputReason reason)
{
  if (reason == timeint::OutputReason::Start) {
    observe(0.0, 0.0, true);
    if (!stages_.preparing()) {
      trackExtremes();
    }
    return timeint::ObserverVerdict::Continue;
  }
  if (stages_.preparing()) {
    observe(lastStep_.stepSize, stages_.preparationRate(), false);
  } else {
    const bool last =
        reason == timeint::OutputReason::SteadyState || stages_.tau(state.time) >= integration_.endTime * (1.0 - 1e-12);
    observe(lastStep_.stepSize, lastStep_.steadyMeasure, last);
  }
  if (settings_.checkpointEvery > 0 && outputIndex() % settings_.checkpointEvery == 0) {
    writeCheckpoint_();
  }
  return timeint::ObserverVerdict::Continue;
}

void TetherOutputs2D::save(io::Checkpoint& checkpoint) const
{
  checkpoint.integers["run output index"] = outputIndex();
  checkpoint.integers["run last snapshot"] = lastSnapshot_;
  checkpoint.reals["run max tether force"] = result_.maxTetherForce;
  checkpoint.reals["run time of max tether force"] = result_.timeOfMaxTetherForce;
  checkpoint.reals["run max tether force after transient"] = result_.maxTetherForceAfterTransient;
  checkpoint.reals["run time of max tether force after transient"] = result_.timeOfMaxTetherForceAfterTransient;
  checkpoint.reals["run max contour length ratio"] = result_.maxContourLengthRatio;
  checkpoint.reals["run max cell length"] = result_.maxCellLength;
  checkpoint.reals["run max abs area drift"] = result_.maxAbsAreaDrift;
}

void TetherOutputs2D::load(const io::Checkpoint& checkpoint, const std::string& source)
{
  const auto real = [&](const char* name) { return io::requiredReal(checkpoint, name, source); };
  state_.nextOutput = io::requiredInteger(checkpoint, "run output index", source) + 1;
  lastSnapshot_ = io::requiredInteger(checkpoint, "run last snapshot", source);
  result_.maxTetherForce = real("run max tether force");
  result_.timeOfMaxTetherForce = real("run time of max tether force");
  result_.maxTetherForceAfterTransient = real("run max tether force after transient");
  result_.timeOfMaxTetherForceAfterTransient = real("run time of max tether force after transient");
  result_.maxContourLengthRatio = real("run max contour length ratio");
  result_.maxCellLength = real("run max cell length");
  result_.maxAbsAreaDrift = real("run max abs area drift");
}

} // namespace capsula::scene2d
