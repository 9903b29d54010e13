#pragma once
// The suspension's outputs per cell type (the cells' 'Type', set by suspension3d from
// 'Suspension/Cell types'), part of 'Output/Suspension' (SuspensionOutput.hpp). At every
// output, for every type in the order its first cell has:
//   metrics.csv   y_mean_<type>: the mean centroid height of its cells;
//                 u_mean_<type>: the mean centroid velocity along the flow, dx_c/dt from the
//                 surface velocity (OutputMetrics.hpp, CellSample::instantVelocity)
//   suspension.h5 in a channel, the block height_<type>: the wall-normal distribution of its
//                 centroids (suspension::heightDistribution, the hematocrit profile's bins) as
//                 a polyline of the bin centres (0, y_k, 0) with the node field "density"
// and in summary.json "cell types"/<type>: its count and, over the outputs at t >= 'Output/
// Suspension/Average from', the means of those columns and the mean distribution. The running
// sums are checkpointed ("suspension.type."), so a restart continues them bit for bit.
// Cells without a type are left out; a scene without typed cells has none of these outputs.
#include <capsula/domain/Domain.hpp>
#include <capsula/io/Checkpoint.hpp>
#include <capsula/io/Json.hpp>
#include <capsula/io/Snapshot.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace capsula::run {

class CellTypeOutput {
public:
  /// `cellTypes`: each cell's type ("" for none), in cell order; `bins` and `averageFrom`
  /// as the hematocrit profile's.
  CellTypeOutput(const std::vector<std::string>& cellTypes, const domain::Domain& domain, int bins, double averageFrom);

  /// The types, in order of their first cell.
  const std::vector<std::string>& types() const { return types_; }
  std::vector<std::string> columns() const;

  struct Sample {
    std::vector<double> meanHeight;           ///< per type
    std::vector<double> meanVelocity;         ///< per type, along the flow
    std::vector<std::vector<double>> density; ///< per type, per bin (in a channel)
  };
  /// Measures the cells' `centroids` and centroid `velocities` (cell order) at time t, and
  /// adds them to the averages if t is in the window.
  Sample measure(double t, const std::vector<mesh::Vec3>& centroids, const std::vector<mesh::Vec3>& velocities);
  std::vector<double> row(const Sample& sample) const;
  /// The blocks height_<type> (none outside a channel).
  std::vector<io::SnapshotBlock> blocks(const Sample& sample) const;

  /// summary.json's "cell types".
  void addResults(io::JsonValue& summary) const;
  void save(io::Checkpoint& checkpoint) const;
  void load(const io::Checkpoint& checkpoint, const std::string& source);

private:
  const domain::Domain& domain_;
  int bins_;
  double averageFrom_;
  std::vector<std::string> types_;
  std::vector<int> typeOfCell_; // index into types_, -1 for none
  std::vector<int> counts_;
  // Running sums over the window: [type] for the means, [type * bins + k] for the densities.
  std::vector<double> heightSum_, velocitySum_, densitySum_;
  std::int64_t averaged_ = 0;
};

} // namespace capsula::run
