#pragma once
// The velocity of the cells and of the fluid from the boundary-integral equation, for any
// Green's function: the interface a scene holds (KernelRegistry.hpp makes one from a
// deck name). Dimensionless as in the thesis (length L, velocity k L, membrane load E/L).
//
// For node x0 of cell c, with lambda_d the viscosity ratio of cell d (eq 3.15 for many
// cells, Pozrikidis 1992 Section 5.3):
//   u(x0) = 2/(1+lambda_c) u_inf(x0) - 1/(4 pi (1+lambda_c) Ca) sum_d SL_d[<Delta f>](x0)
//           + 1/(4 pi (1+lambda_c)) sum_d (1-lambda_d) DL_d[u](x0),
//   SL_d[f](x0) = sum_{m in d} <Delta f>_m,i int_Em G_ij(x, x0) dS   (eq 3.36),
//   DL_d[u](x0) = PV int_Sd u_i T_ijk(x, x0) n_k dS                  (eq 3.44, ERRATA),
// Delta f = (sigma_outside - sigma_inside) . n, n outward. With every lambda = 1 the
// velocity is explicit; otherwise the Belos solver of 'Solver/Method' solves for it
// (KrylovSolve.hpp, on SecondKindOperator.hpp).
//
// Distribution: every rank holds the whole geometry and the loads (replicated) and
// evaluates the rows of the nodes it owns (velocityMap()); results are gathered back to
// every rank. They do not depend on the number of ranks beyond round-off.
#include <capsula/operators/CellSurfaces.hpp>
#include <capsula/operators/DoubleLayerForm.hpp>
#include <capsula/operators/LinearFlow.hpp>
#include <capsula/operators/LoadDensity.hpp>
#include <capsula/operators/WarmStartHistory.hpp>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>
#include <Tpetra_Map.hpp>

#include <string>
#include <vector>

namespace capsula::operators {

/// Node velocities and how they were obtained.
struct VelocitySolution {
  std::vector<double> velocities; ///< 3 per node, global numbering, on every rank
  int iterations = 0;             ///< Krylov iterations (0: explicit, every lambda = 1)
  double residual = 0.0;          ///< achieved ||b - A u|| / ||b|| (0 when explicit)
};

class BoundaryIntegralSolver {
public:
  virtual ~BoundaryIntegralSolver() = default;

  /// The Green's function's name, e.g. "plane wall 3D".
  virtual std::string kernelName() const = 0;
  virtual const CellSurfaces& surfaces() const = 0;

  /// The distributed unknowns: 3 per node (GID 3 g + i), whole nodes per rank.
  virtual Teuchos::RCP<const Tpetra::Map<>> velocityMap() const = 0;
  /// The nodes this rank evaluates: [firstOwnedNode(), firstOwnedNode() + numOwnedNodes()).
  virtual int firstOwnedNode() const = 0;
  virtual int numOwnedNodes() const = 0;

  /// Moves the nodes (3 per node, all cells, the same on every rank) and rebuilds the
  /// quadrature caches. Throws core::InputError if a node leaves the fluid domain.
  virtual void setPositions(const double* positions) = 0;

  /// Rebuild the preconditioner of the viscosity-ratio equation, if it has one, at the next
  /// solve (SolverParameters::preconditionerRefresh). Until then a solve at a new geometry
  /// keeps the blocks of the geometry they were built at: they steer the iteration only, the
  /// solution is the tolerance's either way.
  virtual void refreshPreconditioner() {}

  /// The velocity of every node (eq above) for the membrane load `load` (LoadDensity.hpp:
  /// Delta f at the nodes of every element, global numbering). `initialGuess` (3 per node, or null: the right-hand
  /// side) starts the Krylov solve when some lambda != 1. Collective; throws
  /// core::NumericalError if the solve does not converge.
  virtual VelocitySolution nodeVelocities(const LoadDensity& load, const FlowConditions& flow,
                                          const double* initialGuess = nullptr) = 0;
  /// The same, the solve starting from history.initialGuess(b) (the warm start of a time
  /// integration, WarmStartHistory.hpp); the solved pair (b, u) joins `history`. With every
  /// lambda = 1 the velocity is explicit and `history` is left as it is. Collective.
  virtual VelocitySolution nodeVelocities(const LoadDensity& load, const FlowConditions& flow,
                                          WarmStartHistory& history) = 0;

  /// The fluid velocity at points off the surfaces (eq 3.59; 3 per point, the same list
  /// on every rank):
  ///   u = u_inf - 1/(8 pi Ca) sum_d SL_d + sum_d (1 - lambda_d)/(8 pi) DL_d[u_nodes],
  /// divided by lambda_c for a point inside cell c. Needs the node velocities of the same
  /// geometry (may be null when every lambda = 1). Points must lie off the surfaces (a
  /// point on one gets a meaningless value) and in the kernel's fluid domain (else
  /// core::InputError). Collective.
  virtual std::vector<double> flowVelocity(const std::vector<double>& points, const LoadDensity& load,
                                           const double* nodeVelocities, const FlowConditions& flow) = 0;

  /// The raw integrals (no prefactors), for checks and diagnostics; collective, results
  /// on every rank. At the nodes: SL(x_t), 3 per node, and DL(x_t) of a nodal density.
  virtual std::vector<double> singleLayer(const LoadDensity& load) = 0;
  /// SL(x_t) of a load continuous across the elements, given at the nodes (3 per node):
  /// the same as singleLayer() up to the near-singular tolerance, its corrections kept
  /// from one call to the next at one geometry (the applications of a linear solve).
  virtual std::vector<double> singleLayerOfNodalLoad(const double* nodalLoad) = 0;
  virtual std::vector<double> doubleLayer(const double* density, DoubleLayerForm form) = 0;
  /// At points off the surfaces (3 per point).
  virtual std::vector<double> singleLayerAt(const std::vector<double>& points, const LoadDensity& load) = 0;
  virtual std::vector<double> doubleLayerAt(const std::vector<double>& points, const double* density) = 0;
  /// Solid angle of each cell seen from each point: [numCells * p + c], 4 pi inside.
  virtual std::vector<double> solidAnglesAt(const std::vector<double>& points) = 0;
};

} // namespace capsula::operators
