#pragma once
// A run of the 2D tethered-cell study (thesis Chapter 4) from a validated deck: the
// preparation stage and the tethered stage (TetherProcedure2D.hpp), with outputs at every
// Output/Interval of tau (= k t / lambda in the preparation, k (t - t0) / lambda after
// tethering):
//   preparation.csv, metrics.csv   time (tau), step, dt (k t), the CellMetrics2D columns,
//                                  raw_time (k t), gmres_iterations, steady_measure
//   preparation_*.h5, contour_*.h5 (+ .xdmf)   the contour as a 2D polyline with node fields
//                                  tension (the membrane's principal stress sigma L / E),
//                                  stretch, load, velocity, s_over_smax
//   checkpoint.h5                  everything needed to continue bit for bit
//   summary.json                   final and extreme values, terms built, timings, provenance
// Equilibrium ends the tethered stage early when Time integration/Steady tolerance > 0
// (the thesis: L2 change of the positions over a step < 1e-7, Steady criterion L2Change),
// judged on steps not shortened to land on an output time.
#include <capsula/scene2d/CapsuleModel2D.hpp>
#include <capsula/scene2d/CellMetrics2D.hpp>
#include <capsula/scene2d/TetherProcedure2D.hpp>

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <iosfwd>
#include <optional>
#include <string>

namespace capsula::run {

struct OutputSettings2D {
  std::string directory;       ///< empty: write nothing
  double interval = 0.1;       ///< tau between metrics rows
  int snapshotEvery = 10;      ///< outputs between contour snapshots (0: none)
  int checkpointEvery = 10;    ///< outputs between checkpoints (0: only at the end)
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
  scene2d::CellMetrics2D final;          ///< at the end
  double maxTetherForce = 0.0;  ///< over the accepted steps of the tethered (or free) stage
  double timeOfMaxTetherForce = 0.0;
  /// The same from Tether/Force transient after tethering on (0 while none has come).
  double maxTetherForceAfterTransient = 0.0;
  double timeOfMaxTetherForceAfterTransient = 0.0;
  double maxContourLengthRatio = 0.0; ///< idem
  double maxCellLength = 0.0;         ///< idem
  double maxAbsAreaDrift = 0.0; ///< over all outputs, both stages
};

class TetherRun2D {
public:
  /// Builds the model from a validated deck (Tether2DDeck.hpp). `log` receives progress
  /// lines (may be null).
  TetherRun2D(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const Teuchos::ParameterList& deck,
              std::ostream* log);

  /// Runs to the end, writing into `outputDirectory` (empty: no files) on rank 0, or
  /// continues from `restartDirectory`/checkpoint.h5. Collective.
  TetherRunResult2D run(const std::string& outputDirectory, const std::optional<std::string>& restartDirectory);

  scene2d::CapsuleModel2D& model() { return model_; }

private:
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  Teuchos::ParameterList deck_;
  std::ostream* log_;
  scene2d::TetherSettings2D tether_;
  OutputSettings2D output_;
  scene2d::CapsuleModel2D model_;
};

} // namespace capsula::run
