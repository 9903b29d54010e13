#pragma once
// The outputs of a scene run at every output time (an observer of the time loop): the
// fields of the scene at the state, the metrics of every cell and pair (OutputMetrics,
// PairMetrics), the wall shear stress on a grid that follows the cells (on each wall of a
// channel: WallShearStressMap.hpp), the fluid velocity
// at the flow probes; then one row of metrics.csv (MetricsTable.hpp) and probes.csv, a
// snapshot every 'Output/Snapshot stride' outputs and the checkpoint. Observers measure at
// output times only, never inside the right-hand side.
//
// Steady state: the root-mean-square normal speed of the nodes relative to their cell's
// centroid, (u_i - dx_c/dt) . n_i, falls below 'Time integration/Steady tolerance' for every
// cell (the change of positions per unit time that is neither translation nor
// tank-treading); atOutput then ends the integration.
//
// Mesh degraded: at an output where some element's smallest angle is below
// 'Output/Stability/Minimum angle', the metrics row is written (it shows the cause), the
// checkpoint and snapshot are not (the last good ones stay), and core::NumericalError names
// the cell, the angle and the time.
//
// It keeps what summary.json reports (addResults): the last and the steady samples, and the
// extremes of the stability diagnostics over the outputs of this process. Its checkpoint
// section holds the metrics' memory (OutputMetrics, "metrics.") and the number of outputs
// written ("scene.outputs", which the snapshot stride counts), and with
// 'Output/Suspension/Enabled' the suspension's running average (SuspensionOutput.hpp).
#include <capsula/io/CheckpointSection.hpp>
#include <capsula/io/Json.hpp>
#include <capsula/run/CellTypeOutput.hpp>
#include <capsula/run/OutputMetrics.hpp>
#include <capsula/run/PairMetrics.hpp>
#include <capsula/run/RunOutputs.hpp>
#include <capsula/run/RunScene.hpp>
#include <capsula/run/SceneOutputSettings.hpp>
#include <capsula/run/SuspensionOutput.hpp>
#include <capsula/run/WallShearStressMap.hpp>
#include <capsula/scene/SceneDescription.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace capsula::run {

class SceneOutputs final : public timeint::IntegrationObserver, public io::CheckpointSection {
public:
  SceneOutputs(RunScene& live, const scene::SceneDescription& description, const SceneOutputSettings& settings,
               RunOutputs& files, double steadyTolerance);

  /// The output terms, one line each ("output: wall shear stress on a grid ...").
  std::vector<std::string> terms() const;
  /// Starts metrics.csv, probes.csv and the snapshots, or continues them after a restart at
  /// `resumeAfter`. Collective.
  void open(std::optional<double> resumeAfter);
  /// Writes checkpoint.h5 at every output ('Output/Checkpoint'; RunBackbone::writeCheckpoint).
  void setCheckpointWriter(std::function<void()> write) { writeCheckpoint_ = std::move(write); }

  /// Measures the scene at `state` and writes the outputs; true if the shape is steady.
  /// Throws core::NumericalError for a degraded mesh (see above). Collective.
  bool observe(const timeint::IntegrationState& state);
  /// observe(); Stop at steady state.
  timeint::ObserverVerdict atOutput(const timeint::IntegrationState& state, timeint::OutputReason reason) override;
  bool steady() const { return steady_; }

  /// The time of the last output, its samples, and the first cell's D12 there.
  double lastTime() const { return lastTime_; }
  /// The rows written to metrics.csv since the start of the run (a restart's included).
  std::int64_t outputsWritten() const { return outputsWritten_; }
  const std::vector<CellSample>& lastSamples() const { return lastSamples_; }
  /// The first cell's D12 at `time` if the last output of this process was at that time;
  /// none before the first output and between outputs (the state has moved on since).
  std::optional<double> d12At(double time) const
  {
    if (lastSamples_.empty() || lastTime_ != time) {
      return std::nullopt;
    }
    return lastSamples_.front().shape.deformation.D12;
  }
  /// The scene's entries of summary.json.
  void addResults(io::JsonValue& summary) const;
  /// What a failure message should add when, at the last output, the membrane law of some
  /// cell had softened under compression (CellStability::minPrincipalStiffness < 0): a fold
  /// or a step collapse that follows has that cause (docs/stability.md). Empty otherwise.
  std::string softeningNote() const;

  void save(io::Checkpoint& checkpoint) const override;
  void load(const io::Checkpoint& checkpoint, const std::string& source) override;

private:
  struct WallSample;
  std::vector<WallSample> sampleWallStress(const timeint::IntegrationState& state, const scene::SceneFields& fields,
                                           const std::vector<CellSample>& samples);
  std::string recordSamples(double t, const std::vector<CellSample>& samples);

  RunScene& live_;
  const scene::SceneDescription& description_;
  const SceneOutputSettings& settings_;
  RunOutputs& files_;
  double steadyTolerance_;
  OutputMetrics metrics_;
  std::optional<SuspensionOutput> suspension_; ///< 'Output/Suspension/Enabled'
  std::optional<CellTypeOutput> cellTypes_;    ///< the same, in a scene whose cells have a 'Type'
  std::function<void()> writeCheckpoint_;
  std::int64_t outputsWritten_ = 0;
  bool steady_ = false;

  // What summary.json reports.
  double lastTime_ = 0.0;
  std::vector<CellSample> lastSamples_, steadySamples_;
  std::vector<PairSample> lastPairs_, steadyPairs_;
  double maxVolumeDrift_ = 0.0;
  double smallestAngle_ = HUGE_VAL; // extremes of the stability diagnostics over
  double largestEdgeRatio_ = 1.0;   // the outputs of this process
  double mostCompressiveTension_ = HUGE_VAL;
  double leastPrincipalStiffness_ = HUGE_VAL;
  double smallestWallGap_ = HUGE_VAL;
  std::vector<ElevatedStressAreas> lastWallAreas_; ///< per wall of the domain, lower first
  std::optional<OutsideRangeAreas> lastOutsideIsolated_;
};

} // namespace capsula::run
