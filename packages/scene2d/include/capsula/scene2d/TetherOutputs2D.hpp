#pragma once
// The outputs of a tether2d run (an observer of the time loop), per stage, at every
// Output/Interval of tau (TetherStages2D.hpp):
//   preparation.csv, metrics.csv   time (tau), step, dt (k t), the CellMetrics2D columns,
//                                  raw_time (k t), gmres_iterations, steady_measure (the
//                                  preparation's window rate of D12 in preparation.csv)
//   preparation.h5, contour.h5 (+ .xdmf)   the contour as a 2D polyline with node fields
//                                  tension (the membrane's principal stress sigma L / E),
//                                  stretch, load, velocity, s_over_smax; every 'Snapshot
//                                  every' outputs and at the start and end of a stage
//   checkpoint.h5                  every 'Checkpoint every' outputs
// and a progress line at every snapshot. After every accepted step of the tethered (or
// free) stage it tracks the extremes of the tether force, the contour length and the cell
// length (they need the membrane only, no velocity solve, and output times would sample
// them coarsely), and judges equilibrium: 'Time integration/Steady tolerance' > 0 (the
// thesis: L2 change of the positions over a step < 1e-7, Steady criterion L2Change), on
// steps not shortened to land on an output time; then the stage ends with one more output.
//
// Its checkpoint section holds the extremes and the output bookkeeping ("run output
// index", "run last snapshot", "run max ...").
#include "capsula/scene2d/CapsuleModel2D.hpp"
#include "capsula/scene2d/CellMetrics2D.hpp"
#include "capsula/scene2d/TetherStages2D.hpp"

#include <capsula/io/CheckpointSection.hpp>
#include <capsula/run/RunOutputs.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

#include <Teuchos_ParameterList.hpp>

#include <chrono>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace capsula::scene2d {

struct OutputSettings2D {
  std::string directory;    ///< empty: write nothing
  double interval = 0.1;    ///< tau between metrics rows
  int snapshotEvery = 10;   ///< outputs between contour snapshots (0: none)
  int checkpointEvery = 10; ///< outputs between checkpoints (0: only at the end)
};

/// Declares Directory, Interval, Snapshot every and Checkpoint every in `output`.
void declareOutputParameters2D(Teuchos::ParameterList& output);
OutputSettings2D readOutputSettings2D(const Teuchos::ParameterList& output);

/// The numbers a run ends with (also in summary.json).
struct TetherRunResult2D {
  bool tethered = false;        ///< the tethered stage was reached
  bool steady = false;          ///< it ended at equilibrium
  double preparationTime = 0.0; ///< tau at which the cell was tethered
  double finalTime = 0.0;       ///< tau at the end
  long long steps = 0;          ///< accepted steps, both stages
  CellMetrics2D final;          ///< at the end
  double maxTetherForce = 0.0;  ///< over the accepted steps of the tethered (or free) stage
  double timeOfMaxTetherForce = 0.0;
  /// The same from Tether/Force transient after tethering on (0 while none has come).
  double maxTetherForceAfterTransient = 0.0;
  double timeOfMaxTetherForceAfterTransient = 0.0;
  double maxContourLengthRatio = 0.0; ///< idem
  double maxCellLength = 0.0;         ///< idem
  double maxAbsAreaDrift = 0.0;       ///< over all outputs, both stages
};

class TetherOutputs2D final : public timeint::IntegrationObserver, public io::CheckpointSection {
public:
  /// `endTau`: the duration of the tethered (or free) stage; `forceTransient`: tau after
  /// tethering that the second maximum of the force leaves out.
  TetherOutputs2D(CapsuleModel2D& model, const TetherStages2D& stages, const OutputSettings2D& settings,
                  const timeint::TimeIntegrationSettings& integration, double forceTransient, run::RunOutputs& files,
                  timeint::IntegrationState& state, std::ostream* log);

  /// The stage's table and snapshot series: new, or continued after `resumeAfter` (tau,
  /// a restart). The estimate of the time left counts from here.
  void beginStage(std::optional<double> resumeAfter = std::nullopt);
  /// Writes checkpoint.h5 every 'Checkpoint every' outputs (RunBackbone::writeCheckpoint).
  void setCheckpointWriter(std::function<void()> write) { writeCheckpoint_ = std::move(write); }

  /// One output of the state: a row, and a snapshot if due or `forceSnapshot` (collective:
  /// needs the velocity). `stepSize` and `steadyMeasure` go into the row.
  void observe(double stepSize, double steadyMeasure, bool forceSnapshot);

  timeint::ObserverVerdict afterStep(timeint::IntegrationState& state, const timeint::StepReport& report,
                                     bool atOutputTime) override;
  timeint::ObserverVerdict atOutput(const timeint::IntegrationState& state, timeint::OutputReason reason) override;

  /// The final values and extremes so far (steps, tethering and steadiness are the run's).
  const TetherRunResult2D& result() const { return result_; }

  void save(io::Checkpoint& checkpoint) const override;
  void load(const io::Checkpoint& checkpoint, const std::string& source) override;

private:
  std::int64_t outputIndex() const { return state_.nextOutput - 1; }
  void trackExtremes();
  void logLine(double tau, const CellMetrics2D& metrics) const;

  CapsuleModel2D& model_;
  const TetherStages2D& stages_;
  OutputSettings2D settings_;
  const timeint::TimeIntegrationSettings& integration_;
  double forceTransient_;
  run::RunOutputs& files_;
  timeint::IntegrationState& state_;
  std::ostream* log_;
  std::function<void()> writeCheckpoint_;
  TetherRunResult2D result_;
  std::int64_t lastSnapshot_ = -1; // output index of the last snapshot in this stage
  timeint::StepReport lastStep_;
  std::chrono::steady_clock::time_point stageWallStart_ = std::chrono::steady_clock::now();
  double stageTauStart_ = 0.0; // for the estimate of the time left: wall time and tau
                               // since the stage (or the restart) began
};

} // namespace capsula::scene2d
