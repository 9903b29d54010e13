#pragma once
// The metrics of each pair of cells at one output time (thesis Chapter 6, Figs 6.3-6.4 and
// 6.9-6.10): where one cell is relative to the other, how fast they move apart or
// together, and how close their surfaces come.
//
// Sign convention (thesis Fig 6.1): for the pair (i, j), i < j, every difference is
// "cell i minus cell j". The Chapter 6 decks put the thesis's cell (1) at
// (+Delta x/2, h, +Delta z/2) as Cell 0 and cell (2) at (-Delta x/2, h, -Delta z/2) as
// Cell 1, so dx_0_1 = Delta x, dz_0_1 = Delta z, dw_0_1 = U_z(1) - U_z(2) (Fig 6.4) and
// dslip_0_1 = U_slip(1) - U_slip(2) (Fig 6.10).
#include <capsula/mesh/Vec3.hpp>
#include <capsula/run/OutputMetrics.hpp>
#include <capsula/scene/Scene.hpp>
#include <capsula/scene/SurfaceGap.hpp>

#include <string>
#include <vector>

namespace capsula::run {

struct PairSample {
  int first = 0, second = 1;
  mesh::Vec3 separation = mesh::Vec3::Zero();       ///< x_c(i) - x_c(j), of the nearest periodic image
  double distance = 0.0;                            ///< |x_c(i) - x_c(j)|
  mesh::Vec3 relativeVelocity = mesh::Vec3::Zero(); ///< dx_c/dt(i) - dx_c/dt(j), instantaneous
  double relativeSlip = 0.0;                        ///< u_slip(i) - u_slip(j) (eq 3.55)
  scene::SurfaceGap gap;                            ///< between the two surfaces (SurfaceGap.hpp)
  /// gap over the local element size at the closest points (the larger of the two cells'
  /// CellStability localElementSize at the node nearest to its closest point): below ~1 the
  /// film between the cells is thinner than the elements that bound it.
  double gapPerElementSize = 0.0;
};

/// Every pair (i < j, in order (0,1), (0,2), ..., (1,2), ...) of the cells of `scene` at
/// `positions` (the global state), with the velocities of `samples` (one per cell, from
/// OutputMetrics::record at the same time).
std::vector<PairSample> pairSamples(const scene::Scene& scene, const std::vector<double>& positions,
                                    const std::vector<CellSample>& samples);

/// The metrics.csv column names of the pair metrics of `numCells` cells (none for one
/// cell): for each pair dx_i_j, dy_i_j, dz_i_j, distance_i_j, du_i_j, dv_i_j, dw_i_j,
/// dslip_i_j, gap_i_j.
std::vector<std::string> pairColumns(int numCells);

/// The values of one pair in the order of pairColumns.
std::vector<double> pairValues(const PairSample& pair);

/// The pair of cells whose surfaces are closest at `positions` (the global state), and
/// their gap. first = second = -1 and gap = infinity for a single cell.
struct ClosestPair {
  int first = -1, second = -1;
  double gap = 0.0;
};
ClosestPair closestPair(const scene::Scene& scene, const std::vector<double>& positions);

} // namespace capsula::run
