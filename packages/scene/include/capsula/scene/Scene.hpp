#pragma once
// A scene: cells in a linear shear flow, free or above a plane wall, built once from a
// validated deck. Building decides which terms exist, and only those are created:
//   - one membrane law per cell (NeoHookean or Skalak), with a prestressed reference
//     shape only where Prestress > 0;
//   - the Green's function 'Operator/Kernel' names, by default free space or the wall
//     (from an operators::KernelRegistry);
//   - the double layer and the Krylov solve only if the viscosity ratio is not 1 (the
//     operators skip both when every lambda = 1);
//   - the fixed-height stage constraint only if some cell asks for it;
//   - contact repulsion, receptor-ligand bonds (SceneBonds.hpp) and a tether only if
//     'Contact', 'Adhesion' and 'Tether' enable them: their nodal forces on each membrane
//     enter its load (ExternalForces.hpp).
// terms() lists what was built; the run log prints it.
//
// The state the time integrator advances is the positions of all nodes of all cells,
// cell after cell (operators::CellSurfaces numbering), the same on every rank. The
// right-hand side is a pure function of the positions, except that with lambda != 1 and
// 'Solver/Warm start' the Krylov solve starts from a combination of the last solutions
// (gmresWarmStart(), operators/WarmStartHistory.hpp); the checkpoint carries them, so a
// restarted run still repeats the uninterrupted one bit for bit. evaluate() (outputs)
// always starts cold. With adhesion the right-hand side also depends on the bond set, which
// only updateBonds() changes, between steps.
//
// A cell's membrane mechanics live on one rank, its owner (CellOwnership.hpp): the owner
// evaluates the cell's loads and tensions and every rank receives them. Everything else
// (positions, reference shapes, the loads, the fields of evaluate()) is on every rank.
#include <capsula/elasticity/MembraneMechanics.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/operators/BoundaryIntegralSolver.hpp>
#include <capsula/operators/KernelChoice.hpp>
#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/operators/LinearFlow.hpp>
#include <capsula/operators/WarmStartHistory.hpp>
#include <capsula/scene/CellOwnership.hpp>
#include <capsula/scene/CellStability.hpp>
#include <capsula/scene/ExternalForces.hpp>
#include <capsula/scene/FixedHeightConstraint.hpp>
#include <capsula/scene/VolumeConstraint.hpp>
#include <capsula/scene/SceneBonds.hpp>
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
  std::vector<double> positions;        ///< 3 per node
  std::vector<double> velocities;       ///< 3 per node, constraints applied (the motion)
  std::vector<double> solverVelocities; ///< 3 per node, the boundary-integral solution
  std::vector<double> elementLoads;     ///< <Delta f>_m, 3 per element: the average over each element
  std::vector<double> loadDensity; ///< Delta f at the nodes of each element, 18 per element (operators::LoadDensity)
  std::vector<double> principalTensions; ///< major, minor per node (eq 3.30)
  std::vector<double> stretches;         ///< major, minor principal stretch per node
  std::vector<double> nodeNormals;       ///< 3 per node: the membranes' averaged unit normals
  /// Per cell: the most compressive principal tension and the least principal stiffness over
  /// the shear modulus (elasticity::MembraneMechanics), what CellStability reports.
  std::vector<MembraneExtremes> membraneExtremes;
  int gmresIterations = 0; ///< 0: explicit velocity (lambda = 1)
};

/// Refined meshes for a scene (Scene::adaptedCells): one per cell, with its reference shape.
struct AdaptedCells {
  std::vector<mesh::SurfaceMesh> cells;
  std::vector<std::vector<double>> references;
  std::vector<int> markedElements; ///< per cell, the elements with Q_e >= threshold (0: kept)
};

/// What one tangential redistribution of a cell's nodes did (Scene::regulariseMeshes).
struct MeshRegularisation {
  int cell = 0;
  double minAngleBefore = 0.0;    ///< degrees
  double minAngleAfter = 0.0;     ///< degrees
  double referenceMinAngle = 0.0; ///< degrees, of the reference elements afterwards
  int passes = 0;
  double maxDisplacement = 0.0; ///< the largest node move
  double volumeOffset = 0.0;    ///< the normal offset that restored the volume
};

class Scene {
public:
  /// Builds the scene `description` asks for; `deck` supplies the "Discretisation",
  /// "Solver" and "Operator" sublists, `kernels` the Green's function 'Operator/Kernel'
  /// names (KernelChoice.hpp; a deck without "Operator": Auto).
  /// Throws core::InputError for cells crossing the wall or overlapping, and for
  /// settings the deck validators cannot check.
  Scene(const SceneDescription& description, const Teuchos::ParameterList& deck,
        const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const operators::KernelRegistry& kernels);

  /// The same scene on other surfaces: `cells` (one per cell of the description, their
  /// positions the current state) with the unstressed shapes `references` (3 per node; empty:
  /// the deck's, as above). What a mesh adaption or a restart after one builds.
  Scene(const SceneDescription& description, const Teuchos::ParameterList& deck,
        const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const operators::KernelRegistry& kernels,
        std::vector<mesh::SurfaceMesh> cells, std::vector<std::vector<double>> references);

  const SceneDescription& description() const { return description_; }
  const Teuchos::RCP<const Teuchos::Comm<int>>& comm() const { return comm_; }
  int numCells() const { return static_cast<int>(cells_.size()); }
  int numNodes() const { return solver_->surfaces().numNodes(); }
  int numElements() const { return solver_->surfaces().numElements(); }
  int nodeOffset(int cell) const { return solver_->surfaces().nodeOffset(cell); }
  int elementOffset(int cell) const { return solver_->surfaces().elementOffset(cell); }
  /// Cell `c` with the positions of the latest setPositions / velocity / evaluate.
  const mesh::SurfaceMesh& cell(int c) const { return cells_[static_cast<std::size_t>(c)]; }
  /// Which rank holds which cell's membrane.
  const CellOwnership& cellOwnership() const { return ownership_; }
  /// The membrane of cell `c`, on its owner only (cellOwnership().owns(c)); other ranks get
  /// an error naming the cell.
  const elasticity::MembraneMechanics& membrane(int c) const;
  operators::BoundaryIntegralSolver& solver() { return *solver_; }
  /// Ca, lambda and the undisturbed flow at the mean shear rate, u_inf = (y, 0, 0).
  const operators::FlowConditions& flow() const { return flow_; }
  /// The same at time t: u_inf = (k(t) y, 0, 0) ('Flow/Shear rate', operators/ShearRate.hpp).
  operators::FlowConditions flowAt(double t) const;
  std::string kernelName() const { return solver_->kernelName(); }
  /// The name the kernel registry knows the Green's function by ("Wall", "FreeSpace"):
  /// 'Operator/Kernel', Auto resolved.
  const std::string& kernelKey() const { return kernel_.name; }
  /// The kernel's own settings ('Operator/<kernelKey()>'; empty for the built-in kernels).
  const Teuchos::ParameterList& kernelParameters() const { return kernel_.parameters; }

  /// The positions of all nodes the scene was built with (the state at t = 0, or where an
  /// adaption or a restart rebuilt it).
  const std::vector<double>& initialPositions() const { return initialPositions_; }

  /// The terms built, one line each ("kernel: Wall (...)", "membrane Cells/Cell 0: ...").
  const std::vector<std::string>& terms() const { return terms_; }

  /// Moves every cell and the boundary-integral geometry to `positions`. Throws
  /// core::NumericalError naming the cell, the node and the time if a position is not
  /// finite or a node has reached the wall.
  void setPositions(double t, const std::vector<double>& positions);

  /// The right-hand side dx/dt = u (eq 3.46): node velocities at `positions`, without the
  /// stage constraints. Collective. A membrane folded or crushed at `positions` throws
  /// timeint::StateOutsideDomain (the integrator rejects the attempt), naming the cell and t.
  void velocity(double t, const std::vector<double>& positions, std::vector<double>& velocities);

  /// True if some cell has a fixed height or conserves its volume (then constrain() must follow velocity()).
  bool hasConstraints() const { return fixedHeight_.has_value() || volume_.has_value(); }
  /// Applies the stage constraints to velocities belonging to `positions`.
  void constrain(const std::vector<double>& positions, std::vector<double>& velocities);

  /// True if the deck asks for mesh regularisation ('Mesh regularisation/Enabled').
  bool regularisesMeshes() const { return description_.meshRegularisation.enabled; }
  /// For every cell whose smallest element angle at `positions` is below 'Mesh
  /// regularisation/Minimum angle': redistributes its nodes along its surface
  /// (mesh::redistributeNodes), writes their new positions into `positions` and gives
  /// its membrane the matching reference shape. Returns one entry per cell changed (none
  /// if regularisation is off). Every rank does the same (same state, same arithmetic).
  std::vector<MeshRegularisation> regulariseMeshes(double t, std::vector<double>& positions);
  /// True if the deck asks for mesh adaption ('Mesh adaption/Enabled').
  bool adaptsMeshes() const { return description_.meshAdaption.enabled; }
  /// The cells' meshes at `positions`, refined where Q_e = kappa^2 A >= 'Mesh
  /// adaption/Threshold' (mesh::adaptMembraneMesh), with their reference shapes; nothing
  /// if no cell needs (or may get) a refinement. Build a new Scene from it to go on.
  std::optional<AdaptedCells> adaptedCells(const std::vector<double>& positions) const;

  /// The unstressed shape of cell `c` (3 per node): the initial (or prestressed) shape,
  /// or what the redistributions made of it.
  const std::vector<double>& referencePositions(int c) const { return references_[static_cast<std::size_t>(c)]; }
  /// Replaces the reference shape of cell `c` (a restart after redistributions).
  void setReferencePositions(int c, std::vector<double> reference);

  /// Positions, constrained velocities, loads and tensions at `positions`. Collective.
  /// GMRES starts cold: an output does not change the warm start of the next stage.
  SceneFields evaluate(double t, const std::vector<double>& positions);

  /// What velocity()'s next GMRES solve starts from: the last solved pairs (right-hand
  /// side, solution), or null with 'Solver/Warm start' off (start from the right-hand side).
  /// Empty until the first solve, and always with every lambda = 1.
  const operators::WarmStartHistory* gmresWarmStart() const { return warmStart_ ? &*warmStart_ : nullptr; }
  /// Restores it from a checkpoint (WarmStartHistory::rightHandSides() and solutions()).
  /// Throws core::InputError if they do not fit this scene's nodes.
  void restoreGmresWarmStart(const std::vector<double>& rightHandSides, const std::vector<double>& solutions);

  /// A time step begins: the cell-block preconditioner ('Solver/Preconditioner') is rebuilt
  /// at the next solve and kept through the step's stages (their geometries differ by the
  /// step only). A restarted run begins at a step, so it rebuilds where the uninterrupted run
  /// did and repeats it bit for bit.
  void startStep() { solver_->refreshPreconditioner(); }

  /// True if the deck enables 'Adhesion': the cells carry receptors and bonds.
  bool hasBonds() const { return external_->hasBonds(); }
  /// The bonds (only with hasBonds()).
  const SceneBonds& bonds() const { return external_->bonds(); }
  SceneBonds& bonds() { return external_->bonds(); }
  /// Bond formation and breakage over the accepted step numbered `step` of length dt that
  /// ended at `positions` (SceneBonds::update for every cell). Collective.
  adhesion::BondEvents updateBonds(const std::vector<double>& positions, double dt, std::uint64_t step);
  /// True if the deck enables 'Tether': one cell is tied to an anchor on the wall.
  bool hasTether() const { return external_->hasTether(); }
  /// The tether (only with hasTether()).
  const adhesion::Tether& tether() const { return external_->tether(); }
  /// The forces from outside on cell c's nodes at the latest evaluation (contact, bonds and
  /// tether, 3 per node), or null when none is enabled.
  const std::vector<double>* externalForces(int c) const { return external_->forces(c); }

  /// Element loads of the latest evaluation (3 per element, global numbering): the
  /// average of Delta f over each element.
  const std::vector<double>& elementLoads() const { return loads_; }
  /// Delta f at the nodes of each element (18 per element), what the single layer integrates.
  operators::LoadDensity loadDensity() const { return operators::LoadDensity(loadDensity_.data()); }

private:
  void computeLoads(double t, elasticity::MembraneEvaluation what);
  void buildExternalForces();
  void replaceReference(int c, std::vector<double> reference);
  std::vector<std::size_t> perElementOffsets(std::size_t width) const;
  std::vector<std::size_t> perNodeOffsets(std::size_t width) const;
  std::string nonFiniteCause(double t) const;

  SceneDescription description_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::vector<mesh::SurfaceMesh> cells_; // sized once: the membranes point into it
  CellOwnership ownership_;
  std::vector<std::unique_ptr<elasticity::MembraneMechanics>> membranes_; // null where another rank owns the cell
  std::vector<std::vector<double>> references_;                           // every cell's unstressed shape
  std::unique_ptr<operators::BoundaryIntegralSolver> solver_;
  std::optional<FixedHeightConstraint> fixedHeight_;
  std::optional<VolumeConstraint> volume_;
  operators::FlowConditions flow_;
  std::vector<double> initialPositions_;
  std::vector<double> loads_;
  std::vector<double> loadDensity_;
  std::optional<ExternalForces> external_; // built after the membranes, whose unstressed shapes it uses
  std::vector<std::string> terms_;
  operators::KernelChoice kernel_;
  std::optional<operators::WarmStartHistory> warmStart_; // with 'Solver/Warm start'
  Teuchos::RCP<Teuchos::Time> membraneTimer_, velocityTimer_, constraintTimer_;
};

} // namespace capsula::scene
