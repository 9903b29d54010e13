#pragma once
// The velocity of the nodes of a 2D cell contour from the boundary-integral equation
// (thesis eqs A.12, A.35), dimensionless with length L, velocity k L and membrane load E/L:
//   u_j(x0) = 2/(1+lambda) u_inf,j(x0) - 1/(2 pi (1+lambda) Ca) SL_j[Delta f](x0)
//             + (1-lambda)/(2 pi (1+lambda)) DL_j[u](x0)
// with SL and DL as in LayerPotentials2D (DL subtracted: -2 pi u(x0) at a smooth point),
// Delta f = (sigma_ext - sigma_int) . n, n outward. lambda = 1: explicit; otherwise the
// Belos solver of 'Solver/Method' on SecondKindOperator (App. A.7 used LAPACK's dense LU on
// one CPU).
// Nodes listed as fixed (the tether) get u = 0: their rows become u = 0, so the double
// layer sees the constrained velocity.
//
// Distribution: every rank holds the whole contour and evaluates the rows of its own
// nodes (NodeDistribution, 2 unknowns per node); the velocities are gathered to every rank. They do not
// depend on the number of ranks beyond round-off (bit for bit when lambda = 1: every row
// is summed in the same order whoever owns it).
#include "capsula/scene2d/ContourDiscretisation2D.hpp"

#include <capsula/contour/Contour.hpp>
#include <capsula/operators/DoubleLayerForm.hpp>
#include <capsula/operators/LinearFlow.hpp>
#include <capsula/operators/NodeDistribution.hpp>
#include <capsula/operators/OperatorParameters.hpp>
#include <capsula/operators/WarmStartHistory.hpp>

#include <Eigen/Core>
#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace capsula::scene2d {

/// u_inf(x) = velocity + gradient x, gradient(i, j) = d u_i / d x_j; simpleShear(rate) is
/// u_inf = (rate y, 0) over the wall y = 0 (rate 1 in units of k).
using LinearFlow2D = operators::LinearFlowOf<2>;

struct FlowConditions2D {
  double capillaryNumber = 1.0; ///< Ca = mu k L / E (eq A.13)
  double viscosityRatio = 1.0;  ///< lambda = mu_inside / mu_outside
  LinearFlow2D background = LinearFlow2D::simpleShear();
};

/// The load at a contour point (segment, t), e.g. MembraneState2D::loadAt.
using ContourLoad2D = std::function<Eigen::Vector2d(const contour::ContourPoint& point, int segment, double t)>;

struct VelocitySolution2D {
  std::vector<double> velocities; ///< 2 per node, on every rank
  int iterations = 0;             ///< Krylov iterations (0: lambda = 1, explicit)
  double residual = 0.0;          ///< achieved relative residual (0 when explicit)
};

class InterfaceVelocity2D {
public:
  virtual ~InterfaceVelocity2D() = default;

  /// The Green's function's name ("free-space 2D", "plane wall 2D").
  virtual std::string kernelName() const = 0;
  virtual const operators::NodeDistribution& distribution() const = 0;

  /// Node velocities of `contour` under `load` (collective). Throws core::InputError if a
  /// node lies below the wall, core::NumericalError if the Krylov solve does not converge.
  /// With a `history` (lambda != 1), the solve starts from its least-squares guess
  /// (WarmStartHistory.hpp) instead of the lambda = 1 velocity, and the solved pair is
  /// added to it.
  virtual VelocitySolution2D nodeVelocities(const contour::Contour& contour, const ContourLoad2D& load,
                                            const FlowConditions2D& flow, const std::vector<int>& fixedNodes,
                                            operators::WarmStartHistory* history = nullptr) = 0;

  /// The raw integrals at every node (2 per node, on every rank; collective), for checks.
  virtual std::vector<double> singleLayer(const contour::Contour& contour, const ContourLoad2D& density) = 0;
  virtual std::vector<double> doubleLayer(const contour::Contour& contour, const double* nodalDensity,
                                          operators::DoubleLayerForm form) = 0;
};

/// The evaluator for free space (wall = false) or for the wall y = 0 (Blake's 2D image
/// system, thesis App. B.1), for contours of `numNodes` nodes.
std::unique_ptr<InterfaceVelocity2D>
makeInterfaceVelocity2D(bool wall, const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int numNodes,
                        const ContourDiscretisation2D& discretisation, const operators::SolverParameters& solver);

} // namespace capsula::scene2d
