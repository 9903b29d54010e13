#pragma once
// Runs a scene from a validated deck to its end time or steady state and writes the
// output contract of the 3D apps (cell3d, twocell3d) into the output directory:
//
//   metrics.csv    one row per output time (header row; columns in metricsColumns()):
//                  with one cell its metrics (and a column "cell" = 0); with N > 1 cells
//                  a column NAME_c for every metric and cell (x_c_0, x_c_1, ...), then
//                  the pair metrics of every pair i < j (PairMetrics.hpp: dx_i_j, ...,
//                  gap_i_j); last, the stability diagnostics of every cell (CellStability.hpp:
//                  min_angle_deg, ..., max_distortion, min_stiffness; with N > 1
//                  cells suffixed _c, then gap_per_h_i_j of every pair); rewritten
//                  atomically at every output
//   probes.csv     fluid velocity at 'Output/Flow probes', only if some are given
//   summary.json   status, final (and steady) values per cell and pair, the terms built,
//                  step statistics, timings, code version and the validated deck
//                  (RunSummary.hpp, SceneOutputs::addResults)
//   snapshots.h5 + snapshots.xdmf   one HDF5 file with every snapshot (mesh, positions,
//                  velocities, loads, tensions, wall shear stress; io/SnapshotSeries.hpp)
//                  that ParaView opens as one time series through the XDMF
//   checkpoint.h5  everything needed to continue (--restart DIR)
//   deck.xml, run.json   the validated deck and the run record
//
// The run is the model the run backbone drives (RunBackbone.hpp: restart checks, the
// checkpoint, summary.json, Auto's switches, interruption), one time loop of
// timeint::TimeIntegrator::integrate with these observers:
//   RunBackbone.hpp   first, after every step: Auto's switches
//   RunScene.hpp      after every step: mesh regularisation and adaption
//   TetherRecord.hpp  after every step and output: the tether's peak force (with 'Tether')
//   SceneOutputs.hpp  at every output: the metrics, probes, wall stress, snapshot and
//                     checkpoint; steady state; a degraded mesh
//   the run itself    after every step: the gap between the cells; progress lines; at every
//                     output: summary.json
//   InterruptionWatch.hpp   last: a signal the ranks agreed on
// and the checkpoint sections of the integration state ("timeint."), the outputs, the scene
// and the tether record. Restart: the deck must equal the checkpoint's except for 'Time
// integration/End time' and 'Output/Directory' (RestartDeck.hpp); the continued run writes
// the same rows, bit for bit, as the uninterrupted one.
//
// Cells too close: after every step the smallest gap between two cell surfaces is compared
// with 'Cells/Minimum gap'; below it the run records that state as an output (metrics row,
// snapshot, checkpoint), writes the reason naming the two cells, the gap and the time into
// summary.json and the log, and returns with status "too close" (not an error: the cells
// met, which is a result; the thin film between them is no longer resolved).
//
// All ranks run this together; rank 0 writes the files. A failure (non-finite state, a
// step-size collapse below 'Time integration/Minimum step', a cell reaching the wall, a
// degraded mesh, a GMRES breakdown) is rethrown after summary.json records it; the last
// checkpoint and outputs stay.
#include "capsula/run/MetricsTable.hpp" // metricsColumns(): the layout of metrics.csv

#include <capsula/elasticity/MembraneLawRegistry.hpp>
#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/timeint/MethodRegistry.hpp>

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace capsula::run {

struct SceneRunOptions {
  std::string application = "cell3d";          ///< named in run.json and summary.json
  std::string deckSource;                      ///< the deck file, for the record
  std::optional<std::string> outputDirectory;  ///< overrides 'Output/Directory'
  std::optional<std::string> restartDirectory; ///< continue from its checkpoint.h5
  std::ostream* log = nullptr;                 ///< progress (rank 0), or nothing
};

struct SceneRunResult {
  std::string status; ///< "finished" (end time), "steady" or "too close" (two cells met)
  double time = 0.0;  ///< where the run stopped
  std::int64_t acceptedSteps = 0;
  std::string outputDirectory;
  std::vector<std::string> terms; ///< physics and output terms built
};

/// Runs the scene `validatedDeck` describes, with the Green's functions of `kernels`, the
/// membrane laws of `laws` and the time-integration methods of `methods` (the registries the
/// deck was declared from). Collective over `comm`.
SceneRunResult runScene(const Teuchos::ParameterList& validatedDeck, const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                        const SceneRunOptions& options, const operators::KernelRegistry& kernels,
                        const elasticity::MembraneLawRegistry& laws = elasticity::builtInMembraneLaws(),
                        const timeint::MethodRegistry& methods = timeint::builtInMethods());

} // namespace capsula::run
