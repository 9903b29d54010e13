#include "capsula/run/MetricsTable.hpp"

namespace capsula::run {

namespace {

// The metrics of one cell, in the order of cellValues. One cell: one row with these columns
// ("cell" after mean_shear_stress); several cells: one row per output with a column
// "NAME_c" for every metric and cell.
const std::vector<std::string>& cellMetricNames()
{
  static const std::vector<std::string> names{"D12",
                                              "D13",
                                              "D23",
                                              "x_c",
                                              "y_c",
                                              "z_c",
                                              "u_slip",
                                              "u_migr",
                                              "volume",
                                              "area",
                                              "reduced_volume",
                                              "footprint_xz",
                                              "mean_shear_stress",
                                              "inclination_deg",
                                              "w_c",
                                              "u_slip_spline",
                                              "u_migr_spline",
                                              "omega_x",
                                              "omega_y",
                                              "omega_z",
                                              "volume_change",
                                              "area_change",
                                              "max_shear_stress",
                                              "mean_shear_stress_increase",
                                              "max_shear_stress_increase",
                                              "shape_change_rate",
                                              "u_lift"};
  return names;
}

// The one-cell table puts "cell" after this many metrics (its layout predates the others).
constexpr std::size_t kMetricsBeforeCellColumn = 13;

std::vector<double> cellValues(const CellSample& s)
{
  const auto& d = s.shape.deformation;
  return {d.D12,
          d.D13,
          d.D23,
          s.shape.centroid[0],
          s.shape.centroid[1],
          s.shape.centroid[2],
          s.slipVelocity(),
          s.migrationVelocity(),
          s.shape.volume,
          s.shape.area,
          s.shape.reducedVolume,
          s.shape.footprintXZ,
          s.stress.mean,
          d.inclinationDegrees,
          s.instantVelocity[2],
          s.splineSlipVelocity(),
          s.splineMigrationVelocity(),
          s.rotation[0],
          s.rotation[1],
          s.rotation[2],
          s.volumeChange,
          s.areaChange,
          s.stress.maximum,
          s.meanStressIncrease,
          s.maximumStressIncrease,
          s.shapeChangeRate,
          s.unconstrainedVelocity[1]};
}

// The stability diagnostics of one cell (CellStability.hpp), in the order of
// stabilityValues. They came after the other columns, so they sit at the end of every
// table (after the wall stress columns): older readers of the leading columns still work.
const std::vector<std::string>& stabilityMetricNames()
{
  static const std::vector<std::string> names{"min_angle_deg",  "max_edge_ratio", "min_tension",
                                              "wall_gap_per_h", "max_distortion", "min_stiffness"};
  return names;
}

std::vector<double> stabilityValues(const CellSample& s)
{
  return {s.stability.minAngleDegrees,       s.stability.maxEdgeRatio,  s.stability.mostCompressiveTension,
          s.stability.wallGapPerElementSize, s.stability.maxDistortion, s.stability.minPrincipalStiffness};
}

// The adhesion of one cell (adhesion/AdhesionOutputs.hpp), in the order of adhesionValues;
// the last columns of every table.
const std::vector<std::string>& adhesionMetricNames()
{
  static const std::vector<std::string> names{"bonds",        "bond_force",   "bond_force_x",
                                              "bond_force_y", "contact_area", "min_gap"};
  return names;
}

std::vector<double> adhesionValues(const adhesion::AdhesionSummary& a)
{
  return {a.bonds, a.bondForce.norm(), a.bondForce[0], a.bondForce[1], a.contactArea, a.minimumGap};
}

// The tether (adhesion/Tether.hpp), one set of columns whatever the number of cells (one
// cell is tethered), after everything else.
const std::vector<std::string>& tetherMetricNames()
{
  static const std::vector<std::string> names{"tether_force",  "tether_force_x",   "tether_force_y", "tether_force_z",
                                              "tether_length", "tether_angle_deg", "pivot_angle_deg"};
  return names;
}

std::vector<double> tetherValues(const TetherSample& t)
{
  const adhesion::TetherState& s = t.state;
  return {s.force.norm(), s.force[0], s.force[1], s.force[2], s.length, s.inclinationDegrees, t.pivotAngleDegrees};
}

// Appends `names`: as they are for one cell, NAME_c for every cell of several.
void appendPerCell(std::vector<std::string>& columns, const std::vector<std::string>& names, int numCells)
{
  for (const auto& name : names) {
    if (numCells <= 1) {
      columns.push_back(name);
      continue;
    }
    for (int c = 0; c < numCells; ++c) {
      columns.push_back(name + "_" + std::to_string(c));
    }
  }
}

// The upper wall's map in a channel (WallShearStressMap.hpp), after the lower wall's columns,
// which keep their names.
const std::vector<std::string>& upperWallMetricNames()
{
  static const std::vector<std::string> names{"wall_stress_min_upper", "wall_stress_max_upper",
                                              "wall_area_upstream_upper", "wall_area_downstream_upper"};
  return names;
}

std::vector<std::string> columnsWithoutAdhesion(bool wallShearStress, int numCells, bool isolatedRange,
                                                bool upperWallShearStress)
{
  if (numCells <= 1) {
    const auto& names = cellMetricNames();
    std::vector<std::string> columns{"time", "step", "dt"};
    const auto split = names.begin() + static_cast<std::ptrdiff_t>(kMetricsBeforeCellColumn);
    columns.insert(columns.end(), names.begin(), split);
    columns.push_back("cell");
    columns.insert(columns.end(), split, names.end());
    columns.push_back("gmres_iterations");
    if (wallShearStress) {
      columns.insert(columns.end(),
                     {"wall_stress_min", "wall_stress_max", "wall_area_upstream", "wall_area_downstream"});
    }
    if (wallShearStress && isolatedRange) {
      columns.insert(columns.end(), {"wall_area_below_isolated", "wall_area_above_isolated"});
    }
    if (wallShearStress && upperWallShearStress) {
      columns.insert(columns.end(), upperWallMetricNames().begin(), upperWallMetricNames().end());
    }
    columns.insert(columns.end(), stabilityMetricNames().begin(), stabilityMetricNames().end());
    return columns;
  }
  std::vector<std::string> columns{"time", "step", "dt"};
  for (const auto& name : cellMetricNames()) {
    for (int c = 0; c < numCells; ++c) {
      columns.push_back(name + "_" + std::to_string(c));
    }
  }
  columns.push_back("gmres_iterations");
  const auto pairs = pairColumns(numCells);
  columns.insert(columns.end(), pairs.begin(), pairs.end());
  if (wallShearStress) {
    columns.insert(columns.end(), {"wall_stress_min", "wall_stress_max", "wall_area_upstream", "wall_area_downstream"});
    if (isolatedRange) {
      columns.insert(columns.end(), {"wall_area_below_isolated", "wall_area_above_isolated"});
    }
    if (upperWallShearStress) {
      columns.insert(columns.end(), upperWallMetricNames().begin(), upperWallMetricNames().end());
    }
  }
  for (const auto& name : stabilityMetricNames()) {
    for (int c = 0; c < numCells; ++c) {
      columns.push_back(name + "_" + std::to_string(c));
    }
  }
  for (int i = 0; i < numCells; ++i) {
    for (int j = i + 1; j < numCells; ++j) {
      columns.push_back("gap_per_h_" + std::to_string(i) + "_" + std::to_string(j));
    }
  }
  return columns;
}

} // namespace

std::vector<std::string> metricsColumns(bool wallShearStress, int numCells, bool isolatedRange, bool adhesion,
                                        bool tether, bool upperWallShearStress)
{
  std::vector<std::string> columns =
      columnsWithoutAdhesion(wallShearStress, numCells, isolatedRange, upperWallShearStress);
  if (adhesion) {
    appendPerCell(columns, adhesionMetricNames(), numCells);
  }
  if (tether) {
    columns.insert(columns.end(), tetherMetricNames().begin(), tetherMetricNames().end());
  }
  return columns;
}

std::vector<std::string> metricsColumns(bool wallShearStress)
{
  return metricsColumns(wallShearStress, 1, false);
}

std::vector<double> metricsRow(double time, std::int64_t acceptedSteps, double lastStep,
                               const std::vector<CellSample>& samples, const std::vector<PairSample>& pairs,
                               const std::vector<double>& wallValues)
{
  std::vector<double> row{time, static_cast<double>(acceptedSteps), lastStep};
  if (samples.size() == 1) {
    const std::vector<double> values = cellValues(samples.front());
    const auto split = values.begin() + static_cast<std::ptrdiff_t>(kMetricsBeforeCellColumn);
    row.insert(row.end(), values.begin(), split);
    row.push_back(0.0); // the cell's index
    row.insert(row.end(), split, values.end());
  } else {
    std::vector<std::vector<double>> values;
    for (const auto& s : samples) {
      values.push_back(cellValues(s));
    }
    for (std::size_t m = 0; m < cellMetricNames().size(); ++m) {
      for (const auto& cell : values) {
        row.push_back(cell[m]);
      }
    }
  }
  row.push_back(static_cast<double>(samples.front().gmresIterations));
  for (const auto& pair : pairs) {
    const std::vector<double> values = pairValues(pair);
    row.insert(row.end(), values.begin(), values.end());
  }
  row.insert(row.end(), wallValues.begin(), wallValues.end());
  if (samples.size() == 1) {
    const std::vector<double> values = stabilityValues(samples.front());
    row.insert(row.end(), values.begin(), values.end());
  } else {
    for (std::size_t m = 0; m < stabilityMetricNames().size(); ++m) {
      for (const auto& s : samples) {
        row.push_back(stabilityValues(s)[m]);
      }
    }
    for (const auto& pair : pairs) {
      row.push_back(pair.gapPerElementSize);
    }
  }
  if (samples.front().adhesion) { // metric by metric, cell by cell, as appendPerCell names them
    for (std::size_t m = 0; m < adhesionMetricNames().size(); ++m) {
      for (const auto& s : samples) {
        row.push_back(adhesionValues(*s.adhesion)[m]);
      }
    }
  }
  for (const auto& s : samples) { // the tethered cell's, if there is one
    if (s.tether) {
      const std::vector<double> values = tetherValues(*s.tether);
      row.insert(row.end(), values.begin(), values.end());
    }
  }
  return row;
}

} // namespace capsula::run
