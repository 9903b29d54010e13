#include "capsula/run/SceneOutputs.hpp"

#include "capsula/run/MetricsTable.hpp"
#include "capsula/run/RelativeViscosity.hpp"
#include "capsula/run/RollingStatistics.hpp"
#include "capsula/run/SceneSnapshot.hpp"
#include "capsula/run/SummaryJson.hpp"

#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/core/Timers.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace capsula::run {

namespace core = capsula::core;
using mesh::Vec3;

namespace {

constexpr const char* kSnapshotBase = "snapshots";    // snapshots.h5 + snapshots.xdmf
constexpr const char* kSuspensionBase = "suspension"; // suspension.h5 + suspension.xdmf

// An adhering cell slower than this along the flow (a k: a hundredth of the undisturbed flow
// one radius above the wall) counts as paused (RollingStatistics.hpp); a free cell near the
// wall moves at ~0.5 a k, a firmly adhered one at ~0.
constexpr double kPauseVelocity = 0.01;

std::vector<std::string> probeColumns(std::size_t probes)
{
  std::vector<std::string> columns{"time"};
  for (std::size_t p = 0; p < probes; ++p) {
    for (const char* axis : {"u", "v", "w"}) {
      columns.push_back("probe" + std::to_string(p) + "_" + axis);
    }
  }
  return columns;
}

} // namespace

struct SceneOutputs::WallSample {
  WallGrid grid;
  operators::WallShearStress stress;
};

SceneOutputs::SceneOutputs(RunScene& live, const scene::SceneDescription& description,
                           const SceneOutputSettings& settings, RunOutputs& files, double steadyTolerance)
    : live_(live),
      description_(description),
      settings_(settings),
      files_(files),
      steadyTolerance_(steadyTolerance),
      metrics_(description.numCells())
{
  if (settings.suspension.enabled) {
    suspension_.emplace(settings.suspension, description.domain);
    std::vector<std::string> types;
    for (const scene::CellDescription& cell : description.cells) {
      types.push_back(cell.type);
    }
    const std::string& counted = settings.suspension.hematocritType;
    core::require<core::InputError>(counted.empty() || std::find(types.begin(), types.end(), counted) != types.end(),
                                    "'Output/Suspension/Hematocrit type' = '", counted,
                                    "', but no cell has that 'Type'.");
    if (std::any_of(types.begin(), types.end(), [](const std::string& type) { return !type.empty(); })) {
      cellTypes_.emplace(types, description.domain, settings.suspension.bins, settings.suspension.averageFrom);
    }
  }
}

std::vector<std::string> SceneOutputs::terms() const
{
  std::vector<std::string> terms;
  if (settings_.wallShearStress.enabled) {
    const auto& wall = settings_.wallShearStress;
    std::ostringstream line;
    line << "output: wall shear stress on a grid of spacing " << wall.spacing << " (" << wall.upstream << " upstream, "
         << wall.downstream << " downstream, half width " << wall.halfWidth << "), threshold " << wall.threshold;
    if (description_.domain.hasUpperWall()) {
      line << ", on the lower and the upper wall";
    }
    terms.push_back(line.str());
  }
  if (!settings_.flowProbes.empty()) {
    terms.push_back("output: fluid velocity at " + std::to_string(settings_.flowProbes.size()) + " flow probes");
  }
  if (suspension_) {
    terms.push_back(suspension_->term());
  }
  if (settings_.snapshots) {
    terms.push_back("output: snapshots every " + std::to_string(settings_.snapshotStride) + " output(s)");
  }
  if (settings_.checkpoint) {
    terms.push_back("output: checkpoint at every output");
  }
  return terms;
}

void SceneOutputs::open(std::optional<double> resumeAfter)
{
  const auto& wall = settings_.wallShearStress;
  std::vector<std::string> columns =
      metricsColumns(wall.enabled, description_.numCells(), wall.isolatedRange, description_.adhesion.enabled,
                     description_.tether.enabled, description_.domain.hasUpperWall());
  if (suspension_) {
    const std::vector<std::string> more = suspension_->columns();
    columns.insert(columns.end(), more.begin(), more.end());
  }
  if (cellTypes_) {
    const std::vector<std::string> more = cellTypes_->columns();
    columns.insert(columns.end(), more.begin(), more.end());
  }
  if (suspension_) {
    files_.openSnapshots(kSuspensionBase, resumeAfter);
  }
  files_.openTable("metrics.csv", columns, resumeAfter);
  if (!settings_.flowProbes.empty()) {
    files_.openTable("probes.csv", probeColumns(settings_.flowProbes.size()), resumeAfter);
  }
  if (settings_.snapshots) {
    files_.openSnapshots(kSnapshotBase, resumeAfter);
  }
}

timeint::ObserverVerdict SceneOutputs::atOutput(const timeint::IntegrationState& state, timeint::OutputReason)
{
  steady_ = observe(state);
  return steady_ ? timeint::ObserverVerdict::Stop : timeint::ObserverVerdict::Continue;
}

// Wall shear stress on a grid that follows the cells, one per wall of the domain, lower
// first (collective).
std::vector<SceneOutputs::WallSample> SceneOutputs::sampleWallStress(const timeint::IntegrationState& state,
                                                                     const scene::SceneFields& fields,
                                                                     const std::vector<CellSample>& samples)
{
  std::vector<WallSample> maps;
  lastWallAreas_.clear();
  const auto& wallOutput = settings_.wallShearStress;
  if (!wallOutput.enabled) {
    return maps;
  }
  Vec3 centre = Vec3::Zero();
  for (const auto& s : samples) {
    centre += s.shape.centroid / static_cast<double>(samples.size());
  }
  scene::Scene& scene = live_.scene();
  const operators::FlowConditions flow = scene.flowAt(state.time);
  for (const domain::Wall& wall : description_.domain.walls()) {
    WallGrid grid = WallGrid::around(wall, centre[0], centre[2], wallOutput.upstream, wallOutput.downstream,
                                     wallOutput.halfWidth, wallOutput.spacing);
    // Stencil step: 1/20 of the gap between the wall and the nearest node (the stencil
    // reaches 4 steps into the fluid, a fifth of the gap), never more than a fifth of the
    // grid spacing.
    double gap = HUGE_VAL;
    for (std::size_t k = 1; k < state.y.size(); k += 3) {
      gap = std::min(gap, wall.distance(state.y[k]));
    }
    const double step = std::min(gap / 20.0, wallOutput.spacing / 5.0);
    operators::WallShearStress stress =
        wallShearStressOnGrid(scene.solver(), grid, step, operators::LoadDensity(fields.loadDensity.data()),
                              fields.solverVelocities.data(), flow);
    // The threshold is relative to the undisturbed stress on this wall at the instant,
    // |k(t) f'(wall)| = |k(t)| on either wall of every profile (domain/FlowProfile.hpp).
    const double ambient =
        std::abs(description_.shearRate.factor(state.time)) * std::abs(description_.flowProfile.wallShearRate(wall));
    lastWallAreas_.push_back(elevatedStressAreas(grid, stress.magnitude, centre[0], wallOutput.threshold * ambient));
    // The isolated cell's range is the lower wall's (wall_stress_min, wall_stress_max).
    if (wallOutput.isolatedRange && maps.empty()) {
      lastOutsideIsolated_ =
          areasOutsideRange(grid, stress.magnitude, wallOutput.isolatedMinimum, wallOutput.isolatedMaximum);
    }
    maps.push_back(WallSample{std::move(grid), std::move(stress)});
  }
  return maps;
}

// Updates the extremes and the last samples; returns why the mesh is past the quality
// bound, or "".
std::string SceneOutputs::recordSamples(double t, const std::vector<CellSample>& samples)
{
  std::string degraded;
  for (std::size_t c = 0; c < samples.size(); ++c) {
    const CellSample& s = samples[c];
    maxVolumeDrift_ = std::max(maxVolumeDrift_, std::abs(s.volumeChange));
    smallestAngle_ = std::min(smallestAngle_, s.stability.minAngleDegrees);
    largestEdgeRatio_ = std::max(largestEdgeRatio_, s.stability.maxEdgeRatio);
    mostCompressiveTension_ = std::min(mostCompressiveTension_, s.stability.mostCompressiveTension);
    leastPrincipalStiffness_ = std::min(leastPrincipalStiffness_, s.stability.minPrincipalStiffness);
    smallestWallGap_ = std::min(smallestWallGap_, s.stability.wallGapPerElementSize);
    // The angle is checked at outputs only (an observer): between outputs the integrator's
    // own floors (non-finite state, step collapse, a node at the wall) catch a blow-up.
    if (degraded.empty() && !(s.stability.minAngleDegrees >= settings_.minimumAngle)) {
      std::ostringstream reason;
      reason << std::setprecision(6) << "At t = " << t << ", the mesh of '" << description_.cells[c].path
             << "' degraded: its smallest element angle is " << s.stability.minAngleDegrees
             << " degrees, below 'Output/Stability/Minimum angle' = " << settings_.minimumAngle
             << " (largest edge ratio " << s.stability.maxEdgeRatio << "). The metrics row of this time is "
             << "written; the last good checkpoint and outputs are in " << files_.directory()
             << ". Refine the mesh, lower 'Time integration/Tolerance', or stop earlier.";
      degraded = reason.str();
    }
  }
  return degraded;
}

bool SceneOutputs::observe(const timeint::IntegrationState& state)
{
  Teuchos::TimeMonitor metricsGuard(*core::timer("Outputs"));
  scene::Scene& scene = live_.scene();
  const double t = state.time;
  const scene::SceneFields fields = scene.evaluate(t, state.y);
  const std::vector<CellSample> samples = metrics_.record(t, scene, fields);
  const std::vector<PairSample> pairs = pairSamples(scene, fields.positions, samples);
  const std::vector<WallSample> walls = sampleWallStress(state, fields, samples);
  std::vector<double> probeVelocities;
  if (!settings_.flowProbes.empty()) {
    std::vector<double> points;
    for (const auto& p : settings_.flowProbes) {
      points.insert(points.end(), {p[0], p[1], p[2]});
    }
    probeVelocities = scene.solver().flowVelocity(points, operators::LoadDensity(fields.loadDensity.data()),
                                                  fields.solverVelocities.data(), scene.flowAt(state.time));
  }

  double shapeRate = 0.0;
  for (const CellSample& s : samples) {
    shapeRate = std::max(shapeRate, s.shapeChangeRate);
  }
  const std::string degraded = recordSamples(t, samples);
  const bool steady = steadyTolerance_ > 0.0 && t > state.outputOrigin && shapeRate < steadyTolerance_;
  lastSamples_ = samples;
  lastPairs_ = pairs;
  lastTime_ = t;
  if (steady) {
    steadySamples_ = samples;
    steadyPairs_ = pairs;
  }
  const bool snapshotDue = settings_.snapshots && outputsWritten_ % settings_.snapshotStride == 0;
  ++outputsWritten_;

  Teuchos::TimeMonitor filesGuard(*core::timer("Output files"));
  // In the order of metricsColumns: the lower wall, its isolated-range areas, the upper wall.
  std::vector<double> wallValues;
  for (std::size_t w = 0; w < lastWallAreas_.size(); ++w) {
    const ElevatedStressAreas& areas = lastWallAreas_[w];
    wallValues.insert(wallValues.end(), {areas.minimum, areas.maximum, areas.upstream, areas.downstream});
    if (w == 0 && lastOutsideIsolated_) {
      wallValues.insert(wallValues.end(), {lastOutsideIsolated_->below, lastOutsideIsolated_->above});
    }
  }
  std::vector<double> row =
      metricsRow(t, state.statistics.acceptedSteps, state.statistics.lastStep, samples, pairs, wallValues);
  std::optional<SuspensionSample> suspensionSample;
  if (suspension_) {
    std::vector<const mesh::SurfaceMesh*> cells;
    const std::string& counted = settings_.suspension.hematocritType;
    for (int c = 0; c < scene.numCells(); ++c) {
      if (counted.empty() || description_.cells[static_cast<std::size_t>(c)].type == counted) {
        cells.push_back(&scene.cell(c));
      }
    }
    double viscosity = 0.0;
    if (suspension_->measuresRelativeViscosity()) {
      viscosity = relativeViscosity(scene.solver().surfaces(), operators::LoadDensity(fields.loadDensity.data()),
                                    fields.solverVelocities.data(), scene.flowAt(t).capillaryNumber,
                                    description_.domain, description_.flowProfile, description_.shearRate.factor(t));
    }
    suspensionSample = suspension_->measure(t, cells, viscosity);
    const std::vector<double> more = suspension_->row(*suspensionSample);
    row.insert(row.end(), more.begin(), more.end());
  }
  std::optional<CellTypeOutput::Sample> typeSample;
  if (cellTypes_) {
    std::vector<mesh::Vec3> centroids, velocities;
    for (const CellSample& s : samples) {
      centroids.push_back(s.shape.centroid);
      velocities.push_back(s.instantVelocity);
    }
    typeSample = cellTypes_->measure(t, centroids, velocities);
    const std::vector<double> more = cellTypes_->row(*typeSample);
    row.insert(row.end(), more.begin(), more.end());
  }
  files_.appendRow("metrics.csv", row);
  if (suspensionSample) {
    files_.writeSnapshot(kSuspensionBase, [&] {
      io::Snapshot snapshot{t, state.statistics.acceptedSteps, {suspension_->profileBlock(*suspensionSample)}};
      if (typeSample) {
        for (io::SnapshotBlock& block : cellTypes_->blocks(*typeSample)) {
          snapshot.blocks.push_back(std::move(block));
        }
      }
      return snapshot;
    });
  }
  if (!settings_.flowProbes.empty()) {
    std::vector<double> probeRow{t};
    probeRow.insert(probeRow.end(), probeVelocities.begin(), probeVelocities.end());
    files_.appendRow("probes.csv", probeRow);
  }
  if (snapshotDue && degraded.empty()) {
    files_.writeSnapshot(kSnapshotBase, [&] {
      io::Snapshot snapshot = sceneSnapshot(scene, fields, t, state.statistics.acceptedSteps, settings_.foldIntoBox);
      for (const WallSample& wall : walls) {
        snapshot.blocks.push_back(wallSnapshotBlock(wall.grid, wall.stress));
      }
      return snapshot;
    });
  }
  if (!degraded.empty()) {
    throw core::NumericalError(degraded); // the run records it in summary.json
  }
  if (settings_.checkpoint) {
    writeCheckpoint_();
  }
  return steady;
}

void SceneOutputs::save(io::Checkpoint& checkpoint) const
{
  metrics_.save(checkpoint);
  if (suspension_) {
    suspension_->save(checkpoint);
  }
  if (cellTypes_) {
    cellTypes_->save(checkpoint);
  }
  checkpoint.integers["scene.outputs"] = outputsWritten_;
}

void SceneOutputs::load(const io::Checkpoint& checkpoint, const std::string& source)
{
  metrics_.load(checkpoint, source);
  if (suspension_) {
    suspension_->load(checkpoint, source);
  }
  if (cellTypes_) {
    cellTypes_->load(checkpoint, source);
  }
  const auto outputs = checkpoint.integers.find("scene.outputs");
  outputsWritten_ = outputs == checkpoint.integers.end() ? 0 : outputs->second;
}

std::string SceneOutputs::softeningNote() const
{
  std::string softened;
  for (std::size_t c = 0; c < lastSamples_.size(); ++c) {
    const double stiffness = lastSamples_[c].stability.minPrincipalStiffness;
    if (stiffness < 0.0) {
      softened += core::message(softened.empty() ? "" : "; ", "the membrane law of '", description_.cells[c].path,
                                "' had softened under compression (least principal stiffness ", stiffness, " G)");
    }
  }
  if (softened.empty()) {
    return "";
  }
  return core::message(" [at the last output, t = ", lastTime_, ", ", softened,
                       ": compressed material crowds at the element scale, docs/stability.md, min_stiffness]");
}

void SceneOutputs::addResults(io::JsonValue& summary) const
{
  const scene::Scene& scene = live_.scene();
  summary["max volume drift"] = maxVolumeDrift_;
  if (scene.regularisesMeshes()) {
    summary["mesh regularisations"] = static_cast<long long>(live_.regularisations());
  }
  if (scene.adaptsMeshes()) {
    summary["mesh adaptions"] = static_cast<long long>(live_.adaptions());
    for (int c = 0; c < scene.numCells(); ++c) {
      summary["elements per cell"].append(scene.cell(c).numElements());
    }
  }
  if (std::isfinite(smallestAngle_)) { // extremes over the outputs of this process
    summary["stability"]["smallest angle (degrees)"] = smallestAngle_;
    summary["stability"]["largest edge ratio"] = largestEdgeRatio_;
    summary["stability"]["most compressive tension"] = mostCompressiveTension_;
    summary["stability"]["least principal stiffness / G"] = leastPrincipalStiffness_;
    if (description_.wall) { // without a wall the column measures from the plane y = 0
      summary["stability"]["smallest wall gap per element size"] = smallestWallGap_;
    }
    summary["stability"]["minimum angle bound"] = settings_.minimumAngle;
  }
  for (std::size_t c = 0; c < lastSamples_.size(); ++c) {
    io::JsonValue cell = io::JsonValue::object();
    cell["name"] = description_.cells[c].path;
    cell["final"] = sampleJson(lastSamples_[c], description_.wall);
    if (!steadySamples_.empty()) {
      cell["steady"] = sampleJson(steadySamples_[c], description_.wall);
    }
    if (scene.hasBonds()) { // over all outputs so far, those before a restart included
      const RollingStatistics rolling =
          rollingStatistics(metrics_.times(), metrics_.centroidHistory(static_cast<int>(c)), kPauseVelocity);
      io::JsonValue& motion = cell["adhesion"];
      motion["observed time"] = rolling.observedTime;
      motion["mean velocity along the flow"] = rolling.meanVelocity;
      motion["pause threshold (velocity)"] = kPauseVelocity;
      motion["pause fraction"] = rolling.pauseFraction;
      motion["pauses"] = rolling.pauses;
      motion["longest pause"] = rolling.longestPause;
    }
    summary["cells"].append(cell);
  }
  for (std::size_t k = 0; k < lastPairs_.size(); ++k) {
    io::JsonValue pair = io::JsonValue::object();
    pair["cells"].append(description_.cells[static_cast<std::size_t>(lastPairs_[k].first)].path);
    pair["cells"].append(description_.cells[static_cast<std::size_t>(lastPairs_[k].second)].path);
    pair["final"] = pairJson(lastPairs_[k]);
    if (k < steadyPairs_.size()) {
      pair["steady"] = pairJson(steadyPairs_[k]);
    }
    summary["pairs"].append(pair);
  }
  summary["minimum gap"] = description_.minimumGap;
  // The lower wall's map under "wall shear stress", a channel's upper wall's under
  // "upper wall shear stress".
  for (std::size_t w = 0; w < lastWallAreas_.size(); ++w) {
    io::JsonValue& entry = summary[w == 0 ? "wall shear stress" : "upper wall shear stress"];
    entry["minimum"] = lastWallAreas_[w].minimum;
    entry["maximum"] = lastWallAreas_[w].maximum;
    entry["elevated area upstream"] = lastWallAreas_[w].upstream;
    entry["elevated area downstream"] = lastWallAreas_[w].downstream;
  }
  if (suspension_) {
    suspension_->addResults(summary);
    if (suspension_->measuresRelativeViscosity()) {
      summary["relative viscosity"]["from"] = relativeViscosityDefinition(description_.flowProfile);
    }
  }
  if (cellTypes_) {
    cellTypes_->addResults(summary);
  }
  if (lastOutsideIsolated_) {
    summary["wall shear stress"]["area below the isolated cell's minimum"] = lastOutsideIsolated_->below;
    summary["wall shear stress"]["area above the isolated cell's maximum"] = lastOutsideIsolated_->above;
  }
}

} // namespace capsula::run
