#pragma once
// The metrics of every cell at every output time (thesis Sections 3.11, 5.2-5.4), with
// the memory they need across outputs: the centroid history for the spline velocity
// (Section 3.11.2) and the values at t = 0 for the drifts and the stress increase
// (eq 3.58). The memory goes into checkpoints, so a restarted run writes the same rows.
#include <capsula/adhesion/AdhesionOutputs.hpp>
#include <capsula/adhesion/Tether.hpp>
#include <capsula/io/Checkpoint.hpp>
#include <capsula/scene/CellMetrics.hpp>
#include <capsula/scene/CellStability.hpp>
#include <capsula/scene/Scene.hpp>

#include <optional>
#include <string>
#include <vector>

namespace capsula::run {

/// The tether at one output time: its spring (adhesion/Tether.hpp) and the angle of the
/// tethered cell's centroid about the anchor (adhesion::pivotAngleDegrees).
struct TetherSample {
  adhesion::TetherState state;
  double pivotAngleDegrees = 0.0;
};

/// One cell at one output time.
struct CellSample {
  scene::CellShape shape;
  scene::MembraneStress stress;
  mesh::Vec3 splineVelocity = mesh::Vec3::Zero();  ///< dx_c/dt from the cubic spline in time
  mesh::Vec3 instantVelocity = mesh::Vec3::Zero(); ///< dx_c/dt from the surface velocity
  /// dx_c/dt from the boundary-integral velocity before any constraint: for a cell held at
  /// a fixed height, its y-component is the migration velocity the constraint removes
  /// (thesis Fig 5.14); for a free cell it equals instantVelocity.
  mesh::Vec3 unconstrainedVelocity = mesh::Vec3::Zero();
  mesh::Vec3 rotation = mesh::Vec3::Zero(); ///< rigid-body fit Omega
  double shapeChangeRate = 0.0;             ///< RMS over nodes of (u_i - dx_c/dt) . n_i
  double volumeChange = 0.0;                ///< V / V(0) - 1
  double areaChange = 0.0;                  ///< S / S(0) - 1
  double meanStressIncrease = 0.0;          ///< mean sigma_SS - its value at t = 0 (eq 3.58)
  double maximumStressIncrease = 0.0;
  int gmresIterations = 0;
  double shearRate = 1.0; ///< k(t) over its mean at this output ('Flow/Shear rate')
  /// f(y_c) of the undisturbed profile at the centroid (y_c in shear, y_c (1 - y_c / H) in
  /// Poiseuille flow; domain/FlowProfile.hpp), for k = 1.
  double profileAtCentroid = 0.0;
  scene::CellStability stability; ///< mesh quality, compression, wall gap (CellStability.hpp)
  /// Bonds, their force, contact area and gap; only in a scene with 'Adhesion' enabled.
  std::optional<adhesion::AdhesionSummary> adhesion;
  /// The tether; only on the tethered cell of a scene with 'Tether' enabled.
  std::optional<TetherSample> tether;

  /// u_slip = k f(y_c) - dx_c/dt (eq 3.55, k = k(t) of this instant, 1 in steady shear;
  /// f(y_c) = y_c in shear), and
  /// u_migr = dy_c/dt, with dx_c/dt the centroid velocity of this instant (the mean surface
  /// velocity): independent of how often the run writes output.
  double slipVelocity() const { return shearRate * profileAtCentroid - instantVelocity[0]; }
  double migrationVelocity() const { return instantVelocity[1]; }
  /// The same from the cubic spline through the output centroids (thesis Section 3.11.2):
  /// for comparison with the thesis; it moves with Output/Interval.
  double splineSlipVelocity() const { return shearRate * profileAtCentroid - splineVelocity[0]; }
  double splineMigrationVelocity() const { return splineVelocity[1]; }
};

class OutputMetrics {
public:
  explicit OutputMetrics(int numCells);

  /// Measures every cell of `scene` (positioned at `fields` by Scene::evaluate) at time
  /// t, appends the centroids to the history and returns the samples. The first call
  /// fixes the t = 0 references.
  std::vector<CellSample> record(double t, const scene::Scene& scene, const scene::SceneFields& fields);

  int numOutputs() const { return static_cast<int>(times_.size()); }
  /// The output times so far, and cell c's centroids there (x, y, z per output).
  const std::vector<double>& times() const { return times_; }
  const std::vector<double>& centroidHistory(int c) const { return centroids_[static_cast<std::size_t>(c)]; }

  /// Adds the history and references to a checkpoint (names prefixed "metrics.").
  void save(io::Checkpoint& checkpoint) const;
  /// Restores them; throws core::IoError naming the missing entry.
  void load(const io::Checkpoint& checkpoint, const std::string& source);

private:
  int numCells_;
  std::vector<double> times_;
  std::vector<std::vector<double>> centroids_; // per cell: x, y, z per output
  std::vector<double> initialVolume_, initialArea_, initialMeanStress_, initialMaximumStress_;
};

/// The root-mean-square over the nodes of (u_i - v) . n_i: how fast the shape of a cell
/// changes, in the frame moving with its centroid velocity v. Tangential (tank-treading)
/// motion of the membrane does not count: a steady tank-treading cell scores ~0. The mean
/// square, not the maximum, because single nodes of a Lagrangian mesh jitter (the
/// maximum stays ~0.03 at level 2 in the Lac & Barthes-Biesel case where the RMS falls
/// well below 1e-2).
/// `nodeVelocities` and `nodeNormals`: 3 per node, `numNodes` nodes.
double shapeChangeRate(const double* nodeVelocities, const double* nodeNormals, int numNodes,
                       const mesh::Vec3& centroidVelocity);

} // namespace capsula::run
