#pragma once
// The Jacobian the stiff time integrators need (timeint::LinearisedSystem) for the 2D
// capsule's right-hand side dx/dt = u(x) (CapsuleModel2D::rightHandSide). With
// c = 1 / (2 pi (1 + lambda) Ca) (thesis eq A.35),
//
//   J~ v = P [ -c S(x_n)[K v] + 2/(1 + lambda) grad u_inf . v ],
//
// frozen at the step's start x_n: K v the derivative of the membrane load Delta f in the
// direction v, S the single layer of the frozen contour (a velocity evaluator of its own,
// 'Solver/Stiff/Gauss-Legendre points'), P the tether (the tethered node's rows zero; none
// on a free cell). The load comes through splines of the whole contour, so K is not local;
// K v is a fourth-order central difference of the load function,
//   [8 (Delta f(x_n + e v) - Delta f(x_n - e v)) - (Delta f(x_n + 2e v) - Delta f(x_n - 2e v))] / 12e,
// taken at the frozen contour's quadrature points (segment, t): four membrane evaluations,
// O(N) each, against the single layer's O(N^2). The load is nonlinear on the scale of the
// node spacing, so the step is e |v|_max = 1e-3 l_min (l_min the shortest segment): the
// truncation, ~(1e-3)^4, and the round-off, ~1e-16 / 1e-3, leave J~ linear to ~1e-12 of
// |J~ v| (GMRES needs a linear operator; second-order differences at their best step leave
// 1e-10, on which unpreconditioned GMRES stalled above a relative residual of 1e-8).
//
// Left out: how S moves with the nodes (it multiplies the load itself, small where the
// membrane is stiff), and for lambda != 1 the double layer. On a straight contour the
// double layer of a velocity along it vanishes identically, so it acts only on modes of
// the contour's own curvature scale, which are not the stiff ones; the Rosenbrock-W
// methods keep their order with any J~ (docs/stiff-integration.md has the measurement).
//
// Solves with W = I - shift J~ run Belos GMRES on a locally replicated map
// (operators::StageJacobian, shared with the 3D scenes' VelocityJacobian) with a dense
// preconditioner on the right (operators::DenseStagePreconditioner). J~ reads the model at every linearisation (its closure,
// tethered node and membrane reference), so it follows tethering and regridding without
// being rebuilt. Every rank computes the same J~ v (the single layer's rows are shared and
// gathered in a fixed order), so the solves do not depend on the number of ranks.
#include "capsula/scene2d/CapsuleModel2D.hpp"
#include "capsula/scene2d/InterfaceVelocity2D.hpp"
#include "capsula/scene2d/StiffSolverParameters2D.hpp"

#include <capsula/operators/DenseStagePreconditioner.hpp>
#include <capsula/operators/StageJacobian.hpp>

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace capsula::scene2d {

class VelocityJacobian2D final : public operators::StageJacobian {
public:
  /// For `model` (it must outlive this object), with the deck's "Solver/Stiff" and
  /// "Discretisation" settings.
  VelocityJacobian2D(CapsuleModel2D& model, const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                     const Teuchos::ParameterList& deck);

  /// One line for the run's "terms".
  std::string describe() const;
  /// The dense approximation of J~ the preconditioner factorises (single precision).
  /// Throws core::Error without a preconditioner.
  const Eigen::MatrixXf& approximateJacobian() const;

private:
  VelocityJacobian2D(CapsuleModel2D& model, const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                     const Teuchos::ParameterList& deck, const StiffSolverSettings2D& settings);

  void freeze(double t, const std::vector<double>& y) override;
  /// 2 unknowns per node.
  void applyFrozen(const double* x, double* y) override;
  Eigen::MatrixXf approximateJacobian(const contour::Contour& frozen);

  CapsuleModel2D& model_;
  StiffSolverSettings2D settings_;
  std::unique_ptr<InterfaceVelocity2D> velocity_; // S on the frozen contour
  std::optional<contour::Contour> frozen_;
  std::vector<double> frozenState_;
  std::vector<int> fixed_;
  double shortestSegment_ = 0.0;
  double coefficient_ = 0.0;                               // c
  double flowFactor_ = 0.0;                                // 2 / (1 + lambda)
  Eigen::Matrix2d flowGradient_ = Eigen::Matrix2d::Zero(); // grad u_inf at the step's start, k(t_n)
  bool tetherEnabled_ = false;
  Teuchos::RCP<operators::DenseStagePreconditioner> preconditioner_;
  std::vector<double> probe_;
};

} // namespace capsula::scene2d
