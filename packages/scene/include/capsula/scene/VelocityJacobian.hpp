#pragma once
// The Jacobian the stiff time integrators need (timeint::LinearisedSystem) for a scene's
// right-hand side dx/dt = u(x) (Scene::velocity), built only when the deck asks for a stiff
// method. With c_d = 1 / (4 pi (1 + lambda_d) Ca) for the cell d a node belongs to,
//
//   J~ v = P [ -c_d S(x_n)[M(x_n)^-1 H(x_n) v] + 2/(1 + lambda_d) grad u_inf . v ],
//
// (with bending, H includes the bending stiffness; with bonds or wall contact, H
// includes the stiffness K = -dF/dx of those forces, ExternalLoadStiffness.hpp, since the
// membrane passes dE/dx - F to the fluid),
//
// frozen at the step's start x_n: H the membranes' tangent stiffness (second variation
// of the strain energy, elasticity::TangentStiffness), M their mass matrices (the load is
// M^-1 of the nodal forces), S the single layer on a geometry of its own frozen at x_n, P
// the stage constraints (fixed height, volume; if any) at x_n. Left out: how S, M and the double layer
// move with the nodes, which is of the size of the load itself and does not make the
// system stiff; and for lambda != 1 the double layer, which vanishes on the fast
// grid-scale modes (a locally flat surface has no double layer). The Rosenbrock-W
// methods keep their order with such a J~; it needs to be right only on the stiff modes.
//
// Solves with W = I - shift J~ run Belos GMRES on a locally replicated map
// (operators::StageJacobian, shared with the 2D cell's VelocityJacobian2D) with the
// LocalMobilityPreconditioner on the right; each application of J~ is one single-layer
// evaluation, its rows shared by the ranks. A cell's tangent stiffness, mass matrix and
// preconditioner block are held by the rank that owns its membrane (CellOwnership.hpp),
// which computes the cell's share of M^-1 H v; every rank receives it. The results do not
// depend on the number of ranks (the right-hand side's do not either).
#include "capsula/scene/LocalMobilityPreconditioner.hpp"
#include "capsula/scene/StiffSolverParameters.hpp"

#include <capsula/elasticity/TangentStiffness.hpp>
#include <capsula/mesh/SurfaceMassMatrix.hpp>
#include <capsula/operators/BoundaryIntegralSolver.hpp>
#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/operators/OperatorParameters.hpp>
#include <capsula/operators/StageJacobian.hpp>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace capsula::scene {

class Scene;

class VelocityJacobian final : public operators::StageJacobian {
public:
  /// For `scene` (it must outlive this object), with the deck's "Solver/Stiff" settings
  /// and its Discretisation. Throws core::InputError naming the keys if a cell's membrane
  /// has no tangent stiffness (the contour-integral load).
  VelocityJacobian(Scene& scene, const Teuchos::ParameterList& deck, const operators::KernelRegistry& kernels);

  /// One line for the run's "Terms built".
  std::string describe() const;

private:
  VelocityJacobian(Scene& scene, const Teuchos::ParameterList& deck, const operators::KernelRegistry& kernels,
                   const StiffSolverSettings& settings);

  void freeze(double t, const std::vector<double>& y) override;
  /// 3 unknowns per node.
  void applyFrozen(const double* x, double* y) override;

  Scene& scene_;
  StiffSolverSettings settings_;
  std::unique_ptr<operators::BoundaryIntegralSolver> frozen_; // the single layer at x_n
  // Per cell at x_n, held for the cells this rank owns (empty or null elsewhere).
  std::vector<std::optional<elasticity::TangentStiffness>> stiffness_;
  std::vector<adhesion::LoadStiffness> external_; // bonds, contact
  std::vector<std::unique_ptr<mesh::SurfaceMassMatrix>> mass_;
  std::vector<std::size_t> cellUnknownOffsets_; // 3 per node: where each cell's unknowns begin
  std::vector<double> frozenPositions_;
  std::vector<double> coefficient_;       // -c_d per node
  std::vector<double> flowFactor_;        // 2 / (1 + lambda_d) per node
  std::vector<mesh::Mat3> flowGradients_; // grad u_inf per node at the step's start, k(t_n)
  Teuchos::RCP<LocalMobilityPreconditioner> preconditioner_;
  std::vector<double> forces_, loads_, product_;
};

} // namespace capsula::scene
