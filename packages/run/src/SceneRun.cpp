#include "capsula/run/SceneRun.hpp"

#include "capsula/run/SceneOutputSettings.hpp"

#include "capsula/run/MetricsTable.hpp"
#include "capsula/run/OutputMetrics.hpp"
#include "capsula/run/PairMetrics.hpp"
#include <capsula/scene/Scene.hpp>
#include <capsula/scene/SceneDescription.hpp>
#include "capsula/run/SceneSnapshot.hpp"
#include "capsula/run/SummaryJson.hpp"
#include "capsula/run/WallShearStressMap.hpp"

#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/core/RunInfo.hpp>
#include <capsula/core/Timers.hpp>
#include <capsula/io/Checkpoint.hpp>
#include <capsula/io/Json.hpp>
#include <capsula/io/MetricsCsv.hpp>
#include <capsula/io/OutputDirectory.hpp>
#include <capsula/io/SnapshotSeries.hpp>
#include <capsula/timeint/TimeIntegrationParameters.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_oblackholestream.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>

namespace capsula::run {

namespace core = capsula::core;
namespace fs = std::filesystem;
using mesh::Vec3;
using scene::AdaptedCells;
using scene::MeshRegularisation;
using scene::Scene;
using scene::SceneDescription;
using scene::SceneFields;

namespace {

// --- collective error handling ------------------------------------------------------

enum class ErrorKind : int { None = 0, Input = 1, Io = 2, Other = 3 };

// Runs `action` on rank 0 only; if it throws, every rank throws the same error, so no rank
// is left waiting in a collective. Input problems become InputError (one message, exit 2).
void onRoot(const Teuchos::Comm<int>& comm, const std::function<void()>& action)
{
  int kind = 0;
  std::string message;
  if (comm.getRank() == 0) {
    try {
      action();
    } catch (const core::InputError& e) {
      kind = static_cast<int>(ErrorKind::Input);
      message = e.what();
    } catch (const core::IoError& e) {
      kind = static_cast<int>(ErrorKind::Io);
      message = e.what();
    } catch (const std::exception& e) {
      kind = static_cast<int>(ErrorKind::Other);
      message = e.what();
    }
  }
  Teuchos::broadcast(comm, 0, &kind);
  if (kind == 0) {
    return;
  }
  int length = static_cast<int>(message.size());
  Teuchos::broadcast(comm, 0, &length);
  message.resize(static_cast<std::size_t>(length));
  if (length > 0) {
    Teuchos::broadcast(comm, 0, length, message.data());
  }
  switch (static_cast<ErrorKind>(kind)) {
  case ErrorKind::Input:
    throw core::InputError(message);
  case ErrorKind::Io:
    throw core::IoError(message);
  default:
    throw core::Error(message);
  }
}

// --- restart: the deck must describe the same run ------------------------------------

// The keys that may change on restart: where to stop and where to write.
void removeRestartFreeKeys(Teuchos::ParameterList& deck)
{
  if (deck.isSublist("Time integration")) {
    deck.sublist("Time integration").remove("End time", false);
  }
  if (deck.isSublist("Output")) {
    deck.sublist("Output").remove("Directory", false);
  }
}

// The first key whose value differs (or that only one list has), "" if none.
std::string firstDifference(const Teuchos::ParameterList& a, const Teuchos::ParameterList& b,
                            const std::string& prefix)
{
  for (auto it = a.begin(); it != a.end(); ++it) {
    const std::string& name = a.name(it);
    const std::string path = prefix.empty() ? name : prefix + "/" + name;
    if (!b.isParameter(name)) {
      return path;
    }
    if (a.isSublist(name) != b.isSublist(name)) {
      return path;
    }
    if (a.isSublist(name)) {
      const std::string inner = firstDifference(a.sublist(name), b.sublist(name), path);
      if (!inner.empty()) {
        return inner;
      }
    } else if (!a.getEntry(name).getAny(false).same(b.getEntry(name).getAny(false))) {
      return path;
    }
  }
  for (auto it = b.begin(); it != b.end(); ++it) {
    if (!a.isParameter(b.name(it))) {
      return prefix.empty() ? b.name(it) : prefix + "/" + b.name(it);
    }
  }
  return "";
}

void requireSameRun(const Teuchos::ParameterList& current, const std::string& checkpointDeckXml,
                    const std::string& checkpointPath)
{
  // Both decks pass through the same XML text, so equal values compare equal.
  auto now = core::readDeckFromString(core::deckToXml(current, false), "the current deck");
  auto then = core::readDeckFromString(checkpointDeckXml, checkpointPath);
  removeRestartFreeKeys(*now);
  removeRestartFreeKeys(*then);
  const std::string key = firstDifference(*then, *now, "");
  core::require<core::InputError>(
    key.empty(), "Cannot restart from '", checkpointPath, "': the deck differs from the one the run was ",
    "started with at '", key, "'. Only 'Time integration/End time' and 'Output/Directory' may change on ",
    "restart (use the deck.xml written next to the checkpoint).");
}

// --- progress -------------------------------------------------------------------------

std::string clock(double seconds)
{
  if (!std::isfinite(seconds) || seconds < 0.0) {
    return "?";
  }
  const long s = std::lround(seconds);
  std::ostringstream out;
  out << s / 3600 << ":" << std::setw(2) << std::setfill('0') << (s / 60) % 60 << ":" << std::setw(2)
      << std::setfill('0') << s % 60;
  return out.str();
}

// --- the run --------------------------------------------------------------------------

constexpr const char* kCheckpointFile = "checkpoint.h5";
constexpr const char* kSnapshotBase = "snapshots";   // snapshots.h5 + snapshots.xdmf

class Run {
public:
  Run(const Teuchos::ParameterList& deck, const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
      const SceneRunOptions& options, const operators::KernelRegistry& kernels);

  SceneRunResult execute();

private:
  bool root() const { return comm_->getRank() == 0; }
  std::ostream& log() { return *log_; }
  void prepareOutputDirectory();
  void restoreFromCheckpoint();
  void startOutputs();
  bool observe(const timeint::IntegrationState& state);
  bool cellsTooClose();
  void regulariseMeshes();
  void adaptMeshes();
  std::unique_ptr<Scene> restoredScene() const;
  void writeSummary(const std::string& status, const std::string& note);
  void progress(const timeint::IntegrationState& state, double lastD12);

  const Teuchos::ParameterList& deck_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  const operators::KernelRegistry& kernels_;
  SceneRunOptions options_;
  std::ostream* log_;
  Teuchos::oblackholestream quiet_;
  SceneDescription description_;
  SceneOutputSettings outputSettings_;
  std::string directory_;
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<timeint::TimeIntegrator> integrator_;
  timeint::IntegrationState state_;
  OutputMetrics metrics_;
  bool restarted_ = false;
  io::Checkpoint restartPoint_;
  std::vector<std::string> terms_;

  // Files (rank 0 only).
  std::optional<io::OutputDirectory> output_;
  std::optional<io::MetricsCsv> metricsCsv_;
  std::optional<io::MetricsCsv> probesCsv_;
  std::optional<io::SnapshotSeries> snapshots_;

  // What summary.json reports.
  std::vector<CellSample> lastSamples_;
  std::vector<CellSample> steadySamples_;
  std::vector<PairSample> lastPairs_;
  std::vector<PairSample> steadyPairs_;
  std::string stopReason_;
  double lastTime_ = 0.0;
  double maxVolumeDrift_ = 0.0;
  // Extremes of the stability diagnostics over the outputs of this process (summary.json).
  double smallestAngle_ = HUGE_VAL;
  double largestEdgeRatio_ = 1.0;
  double mostCompressiveTension_ = HUGE_VAL;
  double smallestWallGap_ = HUGE_VAL;
  std::optional<ElevatedStressAreas> lastWallAreas_;
  std::optional<OutsideRangeAreas> lastOutsideIsolated_;
  std::int64_t outputsWritten_ = 0;
  std::int64_t regularisations_ = 0;   // node redistributions of a cell, over the whole run
  std::int64_t adaptions_ = 0;         // mesh refinements of a cell, over the whole run
  std::chrono::steady_clock::time_point wallStart_;
  double simulatedStart_ = 0.0;
  double lastD12_ = 0.0;
};

Run::Run(const Teuchos::ParameterList& deck, const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
         const SceneRunOptions& options, const operators::KernelRegistry& kernels)
    : deck_(deck),
      comm_(comm),
      kernels_(kernels),
      options_(options),
      log_(options.log && comm->getRank() == 0 ? options.log : &quiet_),
      description_(scene::describeScene(deck)),
      outputSettings_(readSceneOutputSettings(deck, description_)),
      metrics_(description_.numCells())
{
  directory_ = options_.outputDirectory ? *options_.outputDirectory
               : options_.restartDirectory ? *options_.restartDirectory
                                           : outputSettings_.directory;
  core::require<core::InputError>(!directory_.empty(),
                                  "No output directory: set 'Output/Directory' or give --output DIR.");
  if (options_.restartDirectory) {
    restoreFromCheckpoint();
  }
  scene_ = restarted_ ? restoredScene() : std::make_unique<Scene>(description_, deck_, comm_, kernels);
  if (restarted_) {   // GMRES's warm start (lambda != 1): the next solve starts where the interrupted run's would
    const auto rhs = restartPoint_.arrays.find("scene.gmresWarmStart.rhs");
    const auto solutions = restartPoint_.arrays.find("scene.gmresWarmStart.solutions");
    if (rhs != restartPoint_.arrays.end() && solutions != restartPoint_.arrays.end()) {
      scene_->restoreGmresWarmStart(rhs->second, solutions->second);
    }
  }
  terms_ = scene_->terms();
  const auto& out = outputSettings_;
  if (out.wallShearStress.enabled) {
    std::ostringstream line;
    line << "output: wall shear stress on a grid of spacing " << out.wallShearStress.spacing << " ("
         << out.wallShearStress.upstream << " upstream, " << out.wallShearStress.downstream
         << " downstream, half width " << out.wallShearStress.halfWidth << "), threshold "
         << out.wallShearStress.threshold;
    terms_.push_back(line.str());
  }
  if (!out.flowProbes.empty()) {
    terms_.push_back("output: fluid velocity at " + std::to_string(out.flowProbes.size()) + " flow probes");
  }
  if (out.snapshots) {
    terms_.push_back("output: snapshots every " + std::to_string(out.snapshotStride) + " output(s)");
  }
  if (out.checkpoint) {
    terms_.push_back("output: checkpoint at every output");
  }

  auto settings = timeint::timeIntegrationSettings(deck_.sublist("Time integration"));
  // Steady state is judged on the shape at output times (see SceneRun.hpp), not on the
  // raw node positions, which keep moving as the membrane tank-treads.
  settings.steadyCriterion = timeint::SteadyStateCriterion::Off;
  // The scene is looked up at every call: a mesh adaption replaces it during the run.
  integrator_ = std::make_unique<timeint::TimeIntegrator>(
    settings, [this](double t, const std::vector<double>& y, std::vector<double>& dydt) {
      scene_->velocity(t, y, dydt);
    });
  if (scene_->hasConstraints()) {
    integrator_->setStageConstraint(
      [this](double, const std::vector<double>& y, std::vector<double>& dydt) { scene_->constrain(y, dydt); });
  }
}

void Run::restoreFromCheckpoint()
{
  const std::string path = (fs::path(*options_.restartDirectory) / kCheckpointFile).string();
  // Every rank reads the (small) checkpoint itself: no broadcast of its contents needed.
  try {
    restartPoint_ = io::readCheckpoint(path);
  } catch (const core::IoError& e) {
    throw core::InputError(core::message("--restart ", *options_.restartDirectory, ": ", e.what()));
  }
  requireSameRun(deck_, restartPoint_.deckXml, path);
  timeint::StateRecord record;
  const std::string prefix = "timeint.";
  for (const auto& [name, value] : restartPoint_.reals) {
    if (name.rfind(prefix, 0) == 0) {
      record.reals[name.substr(prefix.size())] = value;
    }
  }
  for (const auto& [name, value] : restartPoint_.integers) {
    if (name.rfind(prefix, 0) == 0) {
      record.integers[name.substr(prefix.size())] = value;
    }
  }
  for (const auto& [name, value] : restartPoint_.arrays) {
    if (name.rfind(prefix, 0) == 0) {
      record.arrays[name.substr(prefix.size())] = value;
    }
  }
  state_ = timeint::fromRecord(record, path);
  metrics_.load(restartPoint_, path);
  const auto outputs = restartPoint_.integers.find("scene.outputs");
  outputsWritten_ = outputs == restartPoint_.integers.end() ? 0 : outputs->second;
  const auto regularisations = restartPoint_.integers.find("scene.regularisations");
  regularisations_ = regularisations == restartPoint_.integers.end() ? 0 : regularisations->second;
  const auto adaptions = restartPoint_.integers.find("scene.adaptions");
  adaptions_ = adaptions == restartPoint_.integers.end() ? 0 : adaptions->second;
  restarted_ = true;
}

// The scene a checkpoint continues: the deck's, or, where redistributions or adaptions
// changed the cells, their meshes (connectivity from the checkpoint, positions from its
// state) and reference shapes.
std::unique_ptr<Scene> Run::restoredScene() const
{
  const auto& arrays = restartPoint_.arrays;
  const int n = description_.numCells();
  if (arrays.count("scene.connectivity.0") == 0) {
    auto scene = std::make_unique<Scene>(description_, deck_, comm_, kernels_);
    for (int c = 0; c < n; ++c) {
      const auto reference = arrays.find("scene.reference." + std::to_string(c));
      if (reference != arrays.end()) {
        scene->setReferencePositions(c, reference->second);
      }
    }
    return scene;
  }
  std::vector<mesh::SurfaceMesh> cells;
  std::vector<std::vector<double>> references;
  std::size_t offset = 0;
  for (int c = 0; c < n; ++c) {
    const std::string suffix = std::to_string(c);
    const auto connectivity = arrays.find("scene.connectivity." + suffix);
    const auto reference = arrays.find("scene.reference." + suffix);
    core::require<core::InputError>(connectivity != arrays.end() && reference != arrays.end(),
                                    "The checkpoint of ", *options_.restartDirectory,
                                    " lacks the adapted mesh of cell ", c, ": it is incomplete.");
    std::vector<mesh::ElementConnectivity> elements(connectivity->second.size() / 6);
    for (std::size_t k = 0; k < connectivity->second.size(); ++k) {
      elements[k / 6][k % 6] = static_cast<int>(connectivity->second[k]);
    }
    const std::size_t values = reference->second.size();
    core::require<core::InputError>(offset + values <= state_.y.size(), "The checkpoint of ",
                                    *options_.restartDirectory, " is inconsistent: its state is too short for its meshes.");
    std::vector<double> positions(state_.y.begin() + static_cast<std::ptrdiff_t>(offset),
                                  state_.y.begin() + static_cast<std::ptrdiff_t>(offset + values));
    offset += values;
    cells.emplace_back(std::move(positions), std::move(elements));
    references.push_back(reference->second);
  }
  return std::make_unique<Scene>(description_, deck_, comm_, kernels_, std::move(cells), std::move(references));
}

void Run::prepareOutputDirectory()
{
  onRoot(*comm_, [&] {
    try {
      output_.emplace(directory_);
    } catch (const core::IoError& e) {
      throw core::InputError(core::message(
        "The output directory '", directory_, "' cannot be used (", e.what(),
        "). Choose another with --output DIR or 'Output/Directory'."));
    }
    if (restarted_ && fs::path(*options_.restartDirectory) != fs::path(directory_)) {
      // Continuing into a new directory: carry the tables over, so they hold the whole run.
      for (const char* table : {"metrics.csv", "probes.csv"}) {
        const fs::path from = fs::path(*options_.restartDirectory) / table;
        if (fs::exists(from)) {
          fs::copy_file(from, fs::path(directory_) / table, fs::copy_options::overwrite_existing);
        }
      }
    }
    io::RunMetadata metadata;
    metadata.application = options_.application;
    metadata.deckSource = options_.deckSource;
    metadata.ranks = comm_->getSize();
    output_->writeRunMetadata(deck_, metadata);
  });
}

void Run::startOutputs()
{
  onRoot(*comm_, [&] {
    const auto& wallOutput = outputSettings_.wallShearStress;
    const auto columns = metricsColumns(wallOutput.enabled, description_.numCells(), wallOutput.isolatedRange);
    std::vector<std::string> probeColumns{"time"};
    for (std::size_t p = 0; p < outputSettings_.flowProbes.size(); ++p) {
      for (const char* axis : {"u", "v", "w"}) {
        probeColumns.push_back("probe" + std::to_string(p) + "_" + axis);
      }
    }
    const std::string metricsPath = output_->file("metrics.csv");
    const std::string probesPath = output_->file("probes.csv");
    const bool probes = !outputSettings_.flowProbes.empty();
    if (restarted_) {
      metricsCsv_.emplace(io::MetricsCsv::resume(metricsPath, columns, state_.time));
      if (probes) {
        probesCsv_.emplace(io::MetricsCsv::resume(probesPath, probeColumns, state_.time));
      }
      if (outputSettings_.snapshots) {
        snapshots_.emplace(
          io::SnapshotSeries::resume(directory_, kSnapshotBase, state_.time, *options_.restartDirectory));
      }
    } else {
      metricsCsv_.emplace(metricsPath, columns);
      if (probes) {
        probesCsv_.emplace(probesPath, probeColumns);
      }
      if (outputSettings_.snapshots) {
        snapshots_.emplace(directory_, kSnapshotBase);
      }
    }
  });
}

void Run::progress(const timeint::IntegrationState& state, double lastD12)
{
  const double end = integrator_->settings().endTime;
  const double elapsed =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart_).count();
  const double done = state.time - simulatedStart_;
  const double eta = done > 0.0 ? elapsed / done * (end - state.time)
                                 : std::numeric_limits<double>::quiet_NaN();
  std::ostringstream line;
  line << std::setprecision(4) << "t = " << state.time << " / " << end << " ("
       << std::setprecision(3) << 100.0 * state.time / end << "%)  step " << state.statistics.acceptedSteps
       << "  dt " << std::scientific << std::setprecision(2) << state.statistics.lastStep
       << std::defaultfloat << std::setprecision(4) << "  D12 " << lastD12 << "  ETA " << clock(eta);
  log() << line.str() << std::endl;
}

bool Run::observe(const timeint::IntegrationState& state)
{
  Teuchos::TimeMonitor metricsGuard(*core::timer("Outputs"));
  const double t = state.time;
  SceneFields fields = scene_->evaluate(t, state.y);
  std::vector<CellSample> samples = metrics_.record(t, *scene_, fields);
  std::vector<PairSample> pairs = pairSamples(*scene_, fields.positions, samples);

  // Wall shear stress on a grid that follows the cells (collective).
  const auto& wallOutput = outputSettings_.wallShearStress;
  std::optional<WallGrid> grid;
  std::optional<operators::WallShearStress> wallStress;
  if (wallOutput.enabled) {
    Vec3 centre = Vec3::Zero();
    for (const auto& s : samples) {
      centre += s.shape.centroid / static_cast<double>(samples.size());
    }
    grid = WallGrid::around(centre[0], centre[2], wallOutput.upstream, wallOutput.downstream,
                            wallOutput.halfWidth, wallOutput.spacing);
    // Stencil step: 1/20 of the gap under the lowest node (the stencil reaches 4 steps up,
    // a fifth of the gap), never more than a fifth of the grid spacing.
    double gap = HUGE_VAL;
    for (std::size_t k = 1; k < state.y.size(); k += 3) {
      gap = std::min(gap, state.y[k]);
    }
    const double step = std::min(gap / 20.0, wallOutput.spacing / 5.0);
    wallStress = wallShearStressOnGrid(scene_->solver(), *grid, step, operators::LoadDensity(fields.loadDensity.data()),
                                       fields.solverVelocities.data(), scene_->flow());
    lastWallAreas_ = elevatedStressAreas(*grid, wallStress->magnitude, centre[0], wallOutput.threshold);
    if (wallOutput.isolatedRange) {
      lastOutsideIsolated_ = areasOutsideRange(*grid, wallStress->magnitude, wallOutput.isolatedMinimum,
                                               wallOutput.isolatedMaximum);
    }
  }
  std::vector<double> probeVelocities;
  if (!outputSettings_.flowProbes.empty()) {
    std::vector<double> points;
    for (const auto& p : outputSettings_.flowProbes) {
      points.insert(points.end(), {p[0], p[1], p[2]});
    }
    probeVelocities = scene_->solver().flowVelocity(points, operators::LoadDensity(fields.loadDensity.data()),
                                                    fields.solverVelocities.data(), scene_->flow());
  }

  double shapeRate = 0.0;
  std::string degraded;   // why the mesh is past the quality bound, or ""
  for (std::size_t c = 0; c < samples.size(); ++c) {
    const CellSample& s = samples[c];
    shapeRate = std::max(shapeRate, s.shapeChangeRate);
    maxVolumeDrift_ = std::max(maxVolumeDrift_, std::abs(s.volumeChange));
    smallestAngle_ = std::min(smallestAngle_, s.stability.minAngleDegrees);
    largestEdgeRatio_ = std::max(largestEdgeRatio_, s.stability.maxEdgeRatio);
    mostCompressiveTension_ = std::min(mostCompressiveTension_, s.stability.mostCompressiveTension);
    smallestWallGap_ = std::min(smallestWallGap_, s.stability.wallGapPerElementSize);
    // The angle is checked at outputs only (an observer): between outputs the integrator's
    // own floors (non-finite state, step collapse, a node at the wall) catch a blow-up.
    if (degraded.empty() && !(s.stability.minAngleDegrees >= outputSettings_.minimumAngle)) {
      std::ostringstream reason;
      reason << std::setprecision(6) << "At t = " << t << ", the mesh of '" << description_.cells[c].path
             << "' degraded: its smallest element angle is " << s.stability.minAngleDegrees
             << " degrees, below 'Output/Stability/Minimum angle' = " << outputSettings_.minimumAngle
             << " (largest edge ratio " << s.stability.maxEdgeRatio << "). The metrics row of this time is "
             << "written; the last good checkpoint and outputs are in " << directory_
             << ". Refine the mesh, lower 'Time integration/Tolerance', or stop earlier.";
      degraded = reason.str();
    }
  }
  const double steadyTolerance = integrator_->settings().steadyTolerance;
  const bool steady = steadyTolerance > 0.0 && t > state.outputOrigin && shapeRate < steadyTolerance;
  lastSamples_ = samples;
  lastPairs_ = pairs;
  lastTime_ = t;
  lastD12_ = samples.front().shape.deformation.D12;
  if (steady) {
    steadySamples_ = samples;
    steadyPairs_ = pairs;
  }
  const bool snapshotDue = outputSettings_.snapshots && outputsWritten_ % outputSettings_.snapshotStride == 0;
  ++outputsWritten_;

  onRoot(*comm_, [&] {
    Teuchos::TimeMonitor filesGuard(*core::timer("Output files"));
    std::vector<double> wallValues =
      lastWallAreas_ && wallOutput.enabled
        ? std::vector<double>{lastWallAreas_->minimum, lastWallAreas_->maximum, lastWallAreas_->upstream,
                              lastWallAreas_->downstream}
        : std::vector<double>{};
    if (lastOutsideIsolated_ && wallOutput.enabled) {
      wallValues.insert(wallValues.end(), {lastOutsideIsolated_->below, lastOutsideIsolated_->above});
    }
    const std::vector<double> row = metricsRow(t, state.statistics.acceptedSteps, state.statistics.lastStep,
                                               samples, pairs, wallValues);
    metricsCsv_->appendRow(row);
    if (probesCsv_) {
      std::vector<double> probeRow{t};
      probeRow.insert(probeRow.end(), probeVelocities.begin(), probeVelocities.end());
      probesCsv_->appendRow(probeRow);
    }
    if (snapshotDue && degraded.empty()) {
      io::Snapshot snapshot = sceneSnapshot(*scene_, fields, t, state.statistics.acceptedSteps);
      if (grid) {
        snapshot.blocks.push_back(wallSnapshotBlock(*grid, *wallStress));
      }
      snapshots_->write(snapshot);
    }
    if (outputSettings_.checkpoint && degraded.empty()) {   // keep the last good one
      io::Checkpoint checkpoint;
      checkpoint.time = t;
      checkpoint.step = state.statistics.acceptedSteps;
      checkpoint.stepSize = state.statistics.lastStep;
      checkpoint.deckXml = core::deckToXml(deck_, false);
      const timeint::StateRecord record = timeint::toRecord(state);
      for (const auto& [name, value] : record.reals) {
        checkpoint.reals["timeint." + name] = value;
      }
      for (const auto& [name, value] : record.integers) {
        checkpoint.integers["timeint." + name] = value;
      }
      for (const auto& [name, value] : record.arrays) {
        checkpoint.arrays["timeint." + name] = value;
      }
      metrics_.save(checkpoint);
      checkpoint.integers["scene.outputs"] = outputsWritten_;
      if (const auto* warm = scene_->gmresWarmStart(); warm && !warm->empty()) {   // the next solve's start
        checkpoint.arrays["scene.gmresWarmStart.rhs"] = warm->rightHandSides();
        checkpoint.arrays["scene.gmresWarmStart.solutions"] = warm->solutions();
      }
      if (scene_->regularisesMeshes() || scene_->adaptsMeshes()) {   // the material points moved with the nodes
        checkpoint.integers["scene.regularisations"] = regularisations_;
        checkpoint.integers["scene.adaptions"] = adaptions_;
        for (int c = 0; c < scene_->numCells(); ++c) {
          checkpoint.arrays["scene.reference." + std::to_string(c)] = scene_->referencePositions(c);
          if (scene_->adaptsMeshes()) {   // and the topology may have changed
            std::vector<double> connectivity;
            for (const auto& element : scene_->cell(c).elements()) {
              connectivity.insert(connectivity.end(), element.begin(), element.end());
            }
            checkpoint.arrays["scene.connectivity." + std::to_string(c)] = std::move(connectivity);
          }
        }
      }
      io::writeCheckpoint(output_->file(kCheckpointFile), checkpoint);
    }
    if (degraded.empty()) {
      writeSummary(steady ? "steady" : "running", "");
    }
  });
  if (!degraded.empty()) {
    throw core::NumericalError(degraded);   // execute() records it in summary.json
  }
  progress(state, lastD12_);
  return steady;
}

// After every step: if two cell surfaces are closer than 'Cells/Minimum gap', records the
// state as an output (metrics row, snapshot, checkpoint) and the reason, and returns true.
// Every rank holds the same state, so every rank takes the same decision.
bool Run::cellsTooClose()
{
  if (scene_->numCells() < 2) {
    return false;
  }
  ClosestPair closest;
  {
    Teuchos::TimeMonitor guard(*core::timer("Cell gap"));
    closest = closestPair(*scene_, state_.y);
  }
  if (closest.gap >= description_.minimumGap) {
    return false;
  }
  std::ostringstream reason;
  reason << std::setprecision(6) << "Stopped at t = " << state_.time << ": the surfaces of '"
         << description_.cells[static_cast<std::size_t>(closest.first)].path << "' and '"
         << description_.cells[static_cast<std::size_t>(closest.second)].path << "' are " << closest.gap
         << " apart, less than 'Cells/Minimum gap' = " << description_.minimumGap
         << ". The outputs and the checkpoint at this time are in " << directory_ << ".";
  stopReason_ = reason.str();
  observe(state_);
  onRoot(*comm_, [&] { writeSummary("too close", stopReason_); });
  log() << stopReason_ << "\n";
  return true;
}

// After every step: redistributes the nodes of the cells whose mesh has degraded below
// 'Mesh regularisation/Minimum angle' (Scene::regulariseMeshes). The state jumps, so a
// first-same-as-last slope no longer belongs to it.
void Run::regulariseMeshes()
{
  if (!scene_->regularisesMeshes()) {
    return;
  }
  std::vector<MeshRegularisation> done;
  {
    Teuchos::TimeMonitor guard(*core::timer("Mesh regularisation"));
    done = scene_->regulariseMeshes(state_.time, state_.y);
  }
  if (done.empty()) {
    return;
  }
  timeint::stateChangedOutside(state_);   // new slopes, and the stability limit again
  for (const auto& event : done) {
    ++regularisations_;
    log() << std::setprecision(5) << "t = " << state_.time << ": redistributed the nodes of '"
          << description_.cells[static_cast<std::size_t>(event.cell)].path << "' (smallest angle "
          << event.minAngleBefore << " -> " << event.minAngleAfter << " degrees, reference "
          << event.referenceMinAngle << ", " << event.passes
          << " passes, largest move " << event.maxDisplacement << ", volume offset " << event.volumeOffset
          << ")\n";
  }
}

// Every 'Mesh adaption/Check interval' accepted steps: refines the cells whose shape curves
// more than their elements resolve (Scene::adaptedCells) and goes on with a scene built on
// the refined meshes (new operators and maps: the number of nodes changed).
void Run::adaptMeshes()
{
  if (!scene_->adaptsMeshes() ||
      state_.statistics.acceptedSteps % description_.meshAdaption.checkInterval != 0) {
    return;
  }
  std::optional<AdaptedCells> adapted;
  {
    Teuchos::TimeMonitor guard(*core::timer("Mesh adaption"));
    adapted = scene_->adaptedCells(state_.y);
    if (!adapted) {
      return;
    }
    std::vector<int> before;
    for (int c = 0; c < scene_->numCells(); ++c) {
      before.push_back(scene_->cell(c).numElements());
    }
    std::vector<int> marked = adapted->markedElements;
    scene_ = std::make_unique<Scene>(description_, deck_, comm_, kernels_, std::move(adapted->cells),
                                     std::move(adapted->references));
    state_.y = scene_->initialPositions();
    timeint::stateChangedOutside(state_);
    for (int c = 0; c < scene_->numCells(); ++c) {
      if (marked[static_cast<std::size_t>(c)] == 0) {
        continue;
      }
      ++adaptions_;
      log() << "t = " << state_.time << ": refined the mesh of '" << description_.cells[static_cast<std::size_t>(c)].path
            << "' (" << marked[static_cast<std::size_t>(c)] << " elements over the curvature threshold; "
            << before[static_cast<std::size_t>(c)] << " -> " << scene_->cell(c).numElements() << " elements, "
            << scene_->cell(c).numNodes() << " nodes)\n";
    }
  }
}

// `note`: the failure message (status "failed") or why the run stopped early.
void Run::writeSummary(const std::string& status, const std::string& note)
{
  io::JsonValue summary = io::JsonValue::object();
  summary["application"] = options_.application;
  summary["status"] = status;
  if (!note.empty()) {
    summary[status == "failed" ? "failure" : "stop reason"] = note;
  }
  summary["time"] = lastTime_;
  summary["version"]["capsula"] = core::capsulaVersion();
  summary["version"]["git sha"] = core::gitSha();
  summary["version"]["trilinos"] = core::trilinosVersion();
  summary["ranks"] = comm_->getSize();
  summary["restarted"] = restarted_;
  for (const auto& term : terms_) {
    summary["terms"].append(term);
  }
  const auto& stats = state_.statistics;
  summary["steps"]["accepted"] = static_cast<long long>(stats.acceptedSteps);
  summary["steps"]["rejected"] = static_cast<long long>(stats.rejectedSteps);
  summary["steps"]["rhs evaluations"] = static_cast<long long>(stats.rhsEvaluations);
  summary["steps"]["smallest"] = stats.smallestStep;
  summary["steps"]["largest"] = stats.largestStep;
  summary["max volume drift"] = maxVolumeDrift_;
  if (scene_->regularisesMeshes()) {
    summary["mesh regularisations"] = static_cast<long long>(regularisations_);
  }
  if (scene_->adaptsMeshes()) {
    summary["mesh adaptions"] = static_cast<long long>(adaptions_);
    for (int c = 0; c < scene_->numCells(); ++c) {
      summary["elements per cell"].append(scene_->cell(c).numElements());
    }
  }
  if (std::isfinite(smallestAngle_)) {   // extremes over the outputs of this process
    summary["stability"]["smallest angle (degrees)"] = smallestAngle_;
    summary["stability"]["largest edge ratio"] = largestEdgeRatio_;
    summary["stability"]["most compressive tension"] = mostCompressiveTension_;
    if (description_.wall) {   // without a wall the column measures from the plane y = 0
      summary["stability"]["smallest wall gap per element size"] = smallestWallGap_;
    }
    summary["stability"]["minimum angle bound"] = outputSettings_.minimumAngle;
  }
  for (std::size_t c = 0; c < lastSamples_.size(); ++c) {
    io::JsonValue cell = io::JsonValue::object();
    cell["name"] = description_.cells[c].path;
    cell["final"] = sampleJson(lastSamples_[c], description_.wall);
    if (!steadySamples_.empty()) {
      cell["steady"] = sampleJson(steadySamples_[c], description_.wall);
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
  if (lastWallAreas_) {
    summary["wall shear stress"]["minimum"] = lastWallAreas_->minimum;
    summary["wall shear stress"]["maximum"] = lastWallAreas_->maximum;
    summary["wall shear stress"]["elevated area upstream"] = lastWallAreas_->upstream;
    summary["wall shear stress"]["elevated area downstream"] = lastWallAreas_->downstream;
  }
  if (lastOutsideIsolated_) {
    summary["wall shear stress"]["area below the isolated cell's minimum"] = lastOutsideIsolated_->below;
    summary["wall shear stress"]["area above the isolated cell's maximum"] = lastOutsideIsolated_->above;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart_).count();
  summary["timings"]["wall seconds (this process)"] = wall;
  for (const char* name : {"Membrane tensions and loads", "Boundary-integral velocity", "Single layer",
                           "Viscosity-ratio GMRES solve", "Fixed-height constraint", "Flow velocity at points",
                           "Cell gap", "Mesh regularisation", "Mesh adaption", "Outputs", "Output files"}) {
    summary["timings"][name] = core::timer(name)->totalElapsedTime();
  }
  summary["deck"] = core::deckToXml(deck_, false);
  io::writeJsonFile(output_->file("summary.json"), summary);
}

SceneRunResult Run::execute()
{
  wallStart_ = std::chrono::steady_clock::now();
  prepareOutputDirectory();
  log() << "Output directory: " << directory_ << "\n";
  log() << "Terms built:\n";
  for (const auto& term : terms_) {
    log() << "  " << term << "\n";
  }
  startOutputs();

  const double end = integrator_->settings().endTime;
  timeint::OutputSchedule schedule;
  schedule.interval = outputSettings_.interval;
  bool steady = false;
  bool tooClose = false;
  try {
    if (!restarted_) {
      state_ = integrator_->start(0.0, scene_->initialPositions());
      state_.nextOutput = 1;
      observe(state_);   // never steady: the test needs t > 0
    } else {
      steady = state_.steady;
      log() << "Restarted from " << *options_.restartDirectory << " at t = " << state_.time << ", step "
            << state_.statistics.acceptedSteps << "\n";
    }
    simulatedStart_ = state_.time;
    const int progressSteps = outputSettings_.progressSteps;
    while (!steady && !tooClose && state_.time < end) {
      while (integrator_->outputTime(state_.outputOrigin, state_.nextOutput, schedule) <= state_.time) {
        ++state_.nextOutput;
      }
      const double tOut = integrator_->outputTime(state_.outputOrigin, state_.nextOutput, schedule);
      while (state_.time < tOut) {
        integrator_->step(state_, tOut);
        regulariseMeshes();
        adaptMeshes();
        tooClose = cellsTooClose();
        if (tooClose) {
          break;
        }
        if (state_.statistics.acceptedSteps % progressSteps == 0 && state_.time < tOut) {
          progress(state_, lastD12_);
        }
      }
      if (tooClose) {
        break;
      }
      ++state_.nextOutput;
      steady = observe(state_);
      state_.steady = steady;
    }
  } catch (const std::exception& e) {
    // Record the failure next to the last good outputs, then let the app report it.
    if (root() && output_) {
      try {
        writeSummary("failed", e.what());
      } catch (const std::exception&) {
        // The original error is the one to report.
      }
    }
    throw;
  }
  const std::string status = tooClose ? "too close" : steady ? "steady" : "finished";
  onRoot(*comm_, [&] { writeSummary(status, stopReason_); });
  if (steady) {
    log() << "Steady state at t = " << state_.time << ": the shape changes slower than "
          << integrator_->settings().steadyTolerance << "\n";
  }
  log() << "Done: " << status << " at t = " << state_.time << " after " << state_.statistics.acceptedSteps
        << " steps (" << state_.statistics.rejectedSteps << " rejected); outputs in " << directory_ << "\n";
  // The key results of the last output, and how to look at the files.
  for (std::size_t c = 0; c < lastSamples_.size(); ++c) {
    const CellSample& sample = lastSamples_[c];
    log() << "  " << description_.cells[c].path << ": D12 " << sample.shape.deformation.D12 << ", centroid ("
          << sample.shape.centroid[0] << ", " << sample.shape.centroid[1] << ", " << sample.shape.centroid[2]
          << "), u_slip " << sample.slipVelocity() << ", u_migr " << sample.migrationVelocity()
          << ", volume change " << sample.volumeChange << ", mean shear stress " << sample.stress.mean << "\n";
  }
  log() << "  metrics.csv (one row per output), summary.json (final and steady values)";
  if (outputSettings_.snapshots) {
    log() << "; ParaView: open " << directory_ << "/" << kSnapshotBase << ".xdmf";
  }
  log() << "\n";
  SceneRunResult result;
  result.status = status;
  result.time = state_.time;
  result.acceptedSteps = state_.statistics.acceptedSteps;
  result.outputDirectory = directory_;
  result.terms = terms_;
  return result;
}

} // namespace

SceneRunResult runScene(const Teuchos::ParameterList& validatedDeck,
                        const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const SceneRunOptions& options,
                        const operators::KernelRegistry& kernels)
{
  Run run(validatedDeck, comm, options, kernels);
  return run.execute();
}

} // namespace capsula::run
