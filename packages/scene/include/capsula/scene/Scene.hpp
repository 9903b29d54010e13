#pragma once
// A scene: cells in a linear shear flow, free or above a plane wall, built once from a
// validated deck. Building decides which terms exist, and only those are created:
//   - one membrane law per cell (NeoHookean or Skalak), with a prestressed reference
//     shape only where Prestress > 0;
//   - the free-space or the wall Green's function (from an operators::KernelRegistry);
//   - the double layer and the GMRES solve only if the viscosity ratio is not 1 (the
//     operators skip both when every lambda = 1);
//   - the fixed-height stage constraint only if some cell asks for it.
// terms() lists what was built; the run log prints it.
//
// The state the time integrator advances is the positions of all nodes of all cells,
// cell after cell (operators::CellSurfaces numbering), the same on every rank. The
// right-hand side is a pure function of the positions (no warm start of GMRES), which
// makes a restarted run repeat the uninterrupted one bit for bit.
#include <capsula/elasticity/MembraneMechanics.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/operators/BoundaryIntegralSolver.hpp>
#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/operators/LinearFlow.hpp>
#include <capsula/scene/FixedHeightConstraint.hpp>
#include <capsula/scene/SceneDescription.hpp>

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>
#include <Teuchos_Time.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace capsula::scene {

/// Everything an output needs at one state (all arrays in the global numbering, on every
/// rank).
struct SceneFields {
  std::vector<double> positions;          ///< 3 per node
  std::vector<double> velocities;         ///< 3 per node, constraints applied (the motion)
  std::vector<double> solverVelocities;   ///< 3 per node, the boundary-integral solution
  std::vector<double> elementLoads;       ///< <Delta f>_m, 3 per element: the average over each element
  std::vector<double> loadDensity;        ///< Delta f at the nodes of each element, 18 per element (operators::LoadDensity)
  std::vector<double> principalTensions;  ///< major, minor per node (eq 3.30)
  std::vector<double> stretches;          ///< major, minor principal stretch per node
  int gmresIterations = 0;                ///< 0: explicit velocity (lambda = 1)
};

class Scene {
public:
  /// Builds the scene `description` asks for; `deck` supplies the "Discretisation" and
  /// "Solver" sublists, `kernels` the Green's functions by name ("FreeSpace", "Wall").
  /// Throws core::InputError for cells crossing the wall or overlapping, and for
  /// settings the deck validators cannot check.
  Scene(const SceneDescription& description, const Teuchos::ParameterList& deck,
        const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const operators::KernelRegistry& kernels);

  const SceneDescription& description() const { return description_; }
  const Teuchos::RCP<const Teuchos::Comm<int>>& comm() const { return comm_; }
  int numCells() const { return static_cast<int>(cells_.size()); }
  int numNodes() const { return solver_->surfaces().numNodes(); }
  int numElements() const { return solver_->surfaces().numElements(); }
  int nodeOffset(int cell) const { return solver_->surfaces().nodeOffset(cell); }
  int elementOffset(int cell) const { return solver_->surfaces().elementOffset(cell); }
  /// Cell `c` with the positions of the latest setPositions / velocity / evaluate.
  const mesh::SurfaceMesh& cell(int c) const { return cells_[static_cast<std::size_t>(c)]; }
  const elasticity::MembraneMechanics& membrane(int c) const { return *membranes_[static_cast<std::size_t>(c)]; }
  operators::BoundaryIntegralSolver& solver() { return *solver_; }
  const operators::FlowConditions& flow() const { return flow_; }
  std::string kernelName() const { return solver_->kernelName(); }

  /// The initial positions of all nodes (the state at t = 0).
  const std::vector<double>& initialPositions() const { return initialPositions_; }

  /// The terms built, one line each ("kernel: Wall (...)", "membrane Cells/Cell 0: ...").
  const std::vector<std::string>& terms() const { return terms_; }

  /// Moves every cell and the boundary-integral geometry to `positions`. Throws
  /// core::NumericalError naming the cell, the node and the time if a position is not
  /// finite or a node has reached the wall.
  void setPositions(double t, const std::vector<double>& positions);

  /// The right-hand side dx/dt = u (eq 3.46): node velocities at `positions`, without the
  /// stage constraints. Collective.
  void velocity(double t, const std::vector<double>& positions, std::vector<double>& velocities);

  /// True if some cell has a fixed height (then constrain() must follow velocity()).
  bool hasConstraints() const { return fixedHeight_.has_value(); }
  /// Applies the stage constraints to velocities belonging to `positions`.
  void constrain(const std::vector<double>& positions, std::vector<double>& velocities);

  /// Positions, constrained velocities, loads and tensions at `positions`. Collective.
  SceneFields evaluate(double t, const std::vector<double>& positions);

  /// Element loads of the latest evaluation (3 per element, global numbering): the
  /// average of Delta f over each element.
  const std::vector<double>& elementLoads() const { return loads_; }
  /// Delta f at the nodes of each element (18 per element), what the single layer integrates.
  operators::LoadDensity loadDensity() const { return operators::LoadDensity(loadDensity_.data()); }

private:
  void computeLoads(double t);

  SceneDescription description_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::vector<mesh::SurfaceMesh> cells_;   // sized once: the membranes point into it
  std::vector<std::unique_ptr<elasticity::MembraneMechanics>> membranes_;
  std::unique_ptr<operators::BoundaryIntegralSolver> solver_;
  std::optional<FixedHeightConstraint> fixedHeight_;
  operators::FlowConditions flow_;
  std::vector<double> initialPositions_;
  std::vector<double> loads_;
  std::vector<double> loadDensity_;
  std::vector<std::string> terms_;
  Teuchos::RCP<Teuchos::Time> membraneTimer_, velocityTimer_, constraintTimer_;
};

} // namespace capsula::scene
