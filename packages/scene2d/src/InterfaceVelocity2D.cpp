#include "capsula/scene2d/InterfaceVelocity2D.hpp"

#include "capsula/scene2d/LayerPotentials2D.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/operators/SecondKindSolve.hpp>

#include <algorithm>
#include <cmath>

namespace capsula::scene2d {

namespace {

template <class Kernel>
class KernelInterfaceVelocity2D final : public InterfaceVelocity2D {
public:
  KernelInterfaceVelocity2D(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int numNodes,
                            const ContourDiscretisation2D& discretisation, const operators::SolverParameters& solver)
      : distribution_(comm, numNodes, 2), potentials_(discretisation), solver_(solver)
  {
    validate(solver_);
  }

  std::string kernelName() const override { return Kernel::name; }
  const operators::NodeDistribution& distribution() const override { return distribution_; }

  VelocitySolution2D nodeVelocities(const contour::Contour& contour, const ContourLoad2D& load,
                                    const FlowConditions2D& flow, const std::vector<int>& fixedNodes,
                                    operators::WarmStartHistory* history) override
  {
    core::require<core::InputError>(flow.capillaryNumber > 0.0 && flow.viscosityRatio > 0.0,
                                    "Flow: the capillary number and the viscosity ratio must be > 0, got ",
                                    flow.capillaryNumber, " and ", flow.viscosityRatio, ".");
    update(contour);
    const int first = distribution_.firstOwnedNode();
    const int owned = distribution_.numOwnedNodes();
    std::vector<char> fixed(static_cast<std::size_t>(owned), 0);
    for (const int g : fixedNodes) {
      core::require<core::InputError>(g >= 0 && g < contour.numberOfNodes(), "fixed node ", g,
                                      " is not a node of the contour");
      if (g >= first && g < first + owned) {
        fixed[static_cast<std::size_t>(g - first)] = 1;
      }
    }

    // Right-hand side: 2/(1+lambda) u_inf - 1/(2 pi (1+lambda) Ca) SL[Delta f] (eq A.35).
    const double lambda = flow.viscosityRatio;
    std::vector<double> rhs(2 * static_cast<std::size_t>(owned));
    potentials_.singleLayerAtNodes(load, rhs.data());
    const double slScale = -1.0 / (2.0 * M_PI * (1.0 + lambda) * flow.capillaryNumber);
    for (int t = 0; t < owned; ++t) {
      const auto k = static_cast<std::size_t>(t);
      if (fixed[k]) {
        rhs[2 * k] = rhs[2 * k + 1] = 0.0;
        continue;
      }
      const Eigen::Vector2d u = flow.background.at(contour.nodes().col(first + t));
      rhs[2 * k] = 2.0 / (1.0 + lambda) * u.x() + slScale * rhs[2 * k];
      rhs[2 * k + 1] = 2.0 / (1.0 + lambda) * u.y() + slScale * rhs[2 * k + 1];
    }

    VelocitySolution2D solution;
    if (lambda == 1.0) {
      solution.velocities = distribution_.gather(rhs);
      return solution;
    }

    const double coefficient = (1.0 - lambda) / (2.0 * M_PI * (1.0 + lambda));
    std::vector<double> rowScale(static_cast<std::size_t>(owned), coefficient);
    for (std::size_t k = 0; k < rowScale.size(); ++k) {
      if (fixed[k]) {
        rowScale[k] = 0.0; // a prescribed velocity: the row is the identity
      }
    }
    operators::SecondKindEquation equation{distribution_,
                                           [this](const double* density, double* rows) {
                                             potentials_.doubleLayerAtNodes(
                                                 density, operators::DoubleLayerForm::Subtracted, rows);
                                           },
                                           {},
                                           std::move(rowScale),
                                           core::message("the viscosity-ratio equation (lambda = ", lambda, ")")};
    operators::SecondKindSolution solved =
        operators::solveSecondKind(std::move(equation), rhs, solver_, nullptr, history);
    solution.velocities = std::move(solved.velocities);
    solution.iterations = solved.krylov.iterations;
    solution.residual = solved.krylov.residual;
    return solution;
  }

  std::vector<double> singleLayer(const contour::Contour& contour, const ContourLoad2D& density) override
  {
    update(contour);
    std::vector<double> rows(2 * static_cast<std::size_t>(distribution_.numOwnedNodes()));
    potentials_.singleLayerAtNodes(density, rows.data());
    return distribution_.gather(rows);
  }

  std::vector<double> doubleLayer(const contour::Contour& contour, const double* nodalDensity,
                                  operators::DoubleLayerForm form) override
  {
    update(contour);
    std::vector<double> rows(2 * static_cast<std::size_t>(distribution_.numOwnedNodes()));
    potentials_.doubleLayerAtNodes(nodalDensity, form, rows.data());
    return distribution_.gather(rows);
  }

private:
  void update(const contour::Contour& contour)
  {
    core::require<core::InputError>(contour.numberOfNodes() == distribution_.numNodes(), "the contour has ",
                                    contour.numberOfNodes(), " nodes; the velocity evaluator was built for ",
                                    distribution_.numNodes());
    // The geometry of the last call again (a stiff Jacobian applies one frozen contour many
    // times): its pair classification and double-layer weights still hold.
    if (geometrySet_ && sameGeometry(potentials_.contour(), contour)) {
      return;
    }
    potentials_.update(contour, distribution_.firstOwnedNode(), distribution_.numOwnedNodes());
    geometrySet_ = true;
  }

  static bool sameGeometry(const contour::Contour& a, const contour::Contour& b)
  {
    const contour::ContourOptions& p = a.options();
    const contour::ContourOptions& q = b.options();
    return p.closure == q.closure && p.parametrisation == q.parametrisation && p.tetherEnds == q.tetherEnds &&
           p.arcLengthPoints == q.arcLengthPoints && a.nodes() == b.nodes();
  }

  operators::NodeDistribution distribution_;
  LayerPotentials2D<Kernel> potentials_;
  operators::SolverParameters solver_;
  bool geometrySet_ = false;
};

} // namespace

std::unique_ptr<InterfaceVelocity2D>
makeInterfaceVelocity2D(bool wall, const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int numNodes,
                        const ContourDiscretisation2D& discretisation, const operators::SolverParameters& solver)
{
  if (wall) {
    return std::make_unique<KernelInterfaceVelocity2D<greens::Wall2D>>(comm, numNodes, discretisation, solver);
  }
  return std::make_unique<KernelInterfaceVelocity2D<greens::FreeSpace2D>>(comm, numNodes, discretisation, solver);
}

} // namespace capsula::scene2d
