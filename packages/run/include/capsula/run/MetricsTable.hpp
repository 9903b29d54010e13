#pragma once
// The layout of metrics.csv (SceneRun.hpp): which columns, in which order, and one row of
// them from the samples of an output. One cell: the cell's metrics with a "cell" column
// after the first 13 (the layout predates the others), gmres_iterations, the wall stress
// columns, the stability diagnostics last. Several cells: a column "NAME_c" per metric and
// cell, the pair columns, the wall stress, the stability diagnostics per cell and each
// pair's gap per element size; with adhesion, last, each cell's bonds, bond_force (the
// magnitude of their total force), bond_force_x, bond_force_y, contact_area and min_gap; with
// a tether, after them and once whatever the number of cells, tether_force (|F| on the
// membrane, G a), tether_force_x, tether_force_y, tether_force_z, tether_length,
// tether_angle_deg (the tether's angle to the wall) and pivot_angle_deg (the tethered cell's
// centroid about the anchor). Columns are only ever appended, so readers of the leading ones
// keep working.
#include "capsula/run/OutputMetrics.hpp"
#include "capsula/run/PairMetrics.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace capsula::run {

/// The metrics.csv columns of one cell; the wall-shear-stress ones only when that output is
/// on; the stability diagnostics last.
std::vector<std::string> metricsColumns(bool wallShearStress);
/// The metrics.csv columns of `numCells` cells (the one-cell layout for numCells = 1); with
/// `isolatedRange` (and the wall stress) also wall_area_below_isolated,
/// wall_area_above_isolated ('Output/Wall shear stress/Isolated range'); with
/// `upperWallShearStress` (and the wall stress: a channel) the upper wall's map after the
/// lower wall's, wall_stress_min_upper, wall_stress_max_upper, wall_area_upstream_upper,
/// wall_area_downstream_upper (the unsuffixed wall columns are the lower wall's); with
/// `adhesion` the adhesion columns (suffixed _c with several cells); with `tether` the
/// tether's.
std::vector<std::string> metricsColumns(bool wallShearStress, int numCells, bool isolatedRange = false,
                                        bool adhesion = false, bool tether = false, bool upperWallShearStress = false);

/// One row in the order of metricsColumns: time, accepted steps, last step size, the cells'
/// samples, their pairs, and `wallValues` (the wall stress columns in force, possibly none);
/// the adhesion columns if the samples carry adhesion, the tether's if one carries a tether.
std::vector<double> metricsRow(double time, std::int64_t acceptedSteps, double lastStep,
                               const std::vector<CellSample>& samples, const std::vector<PairSample>& pairs,
                               const std::vector<double>& wallValues);

} // namespace capsula::run
