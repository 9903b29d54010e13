#include "ScaledStokesletKernel.hpp"

#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/operators/BuiltInKernels.hpp>

#include <memory>
#include <utility>

namespace capsula::run::testing {

namespace {

using operators::BoundaryIntegralSolver;
using operators::FlowConditions;
using operators::LoadDensity;

// FreeSpace's solver with the Stokeslet scaled: every single layer times c, every
// velocity at Ca / c (the prefactor of the single layer is 1 / Ca), the rest unchanged.
class ScaledStokesletSolver final : public BoundaryIntegralSolver {
public:
  ScaledStokesletSolver(std::unique_ptr<BoundaryIntegralSolver> freeSpace, double scale)
      : freeSpace_(std::move(freeSpace)), scale_(scale)
  {}

  std::string kernelName() const override { return "free space, scaled Stokeslet"; }
  const operators::CellSurfaces& surfaces() const override { return freeSpace_->surfaces(); }
  Teuchos::RCP<const Tpetra::Map<>> velocityMap() const override { return freeSpace_->velocityMap(); }
  int firstOwnedNode() const override { return freeSpace_->firstOwnedNode(); }
  int numOwnedNodes() const override { return freeSpace_->numOwnedNodes(); }
  void setPositions(const double* positions) override { freeSpace_->setPositions(positions); }

  operators::VelocitySolution nodeVelocities(const LoadDensity& load, const FlowConditions& flow,
                                             const double* initialGuess) override
  {
    return freeSpace_->nodeVelocities(load, scaled(flow), initialGuess);
  }
  operators::VelocitySolution nodeVelocities(const LoadDensity& load, const FlowConditions& flow,
                                             operators::WarmStartHistory& history) override
  {
    return freeSpace_->nodeVelocities(load, scaled(flow), history);
  }
  std::vector<double> flowVelocity(const std::vector<double>& points, const LoadDensity& load,
                                   const double* nodeVelocities, const FlowConditions& flow) override
  {
    return freeSpace_->flowVelocity(points, load, nodeVelocities, scaled(flow));
  }

  std::vector<double> singleLayer(const LoadDensity& load) override { return times(freeSpace_->singleLayer(load)); }
  std::vector<double> singleLayerOfNodalLoad(const double* nodalLoad) override
  {
    return times(freeSpace_->singleLayerOfNodalLoad(nodalLoad));
  }
  std::vector<double> doubleLayer(const double* density, operators::DoubleLayerForm form) override
  {
    return freeSpace_->doubleLayer(density, form);
  }
  std::vector<double> singleLayerAt(const std::vector<double>& points, const LoadDensity& load) override
  {
    return times(freeSpace_->singleLayerAt(points, load));
  }
  std::vector<double> doubleLayerAt(const std::vector<double>& points, const double* density) override
  {
    return freeSpace_->doubleLayerAt(points, density);
  }
  std::vector<double> solidAnglesAt(const std::vector<double>& points) override
  {
    return freeSpace_->solidAnglesAt(points);
  }

private:
  FlowConditions scaled(FlowConditions flow) const
  {
    flow.capillaryNumber /= scale_;
    return flow;
  }
  std::vector<double> times(std::vector<double> values) const
  {
    for (double& value : values) {
      value *= scale_;
    }
    return values;
  }

  std::unique_ptr<BoundaryIntegralSolver> freeSpace_;
  double scale_;
};

Teuchos::RCP<const Teuchos::ParameterList> scaledStokesletParameters()
{
  auto keys = Teuchos::rcp(new Teuchos::ParameterList("ScaledFreeSpace"));
  core::declareReal(*keys, "Stokeslet scale", 1.0, "c: the fluid's viscosity is mu / c.", core::greaterThan(0.0));
  return keys;
}

} // namespace

void registerScaledStokesletKernel(operators::KernelRegistry& kernels)
{
  kernels.add("ScaledFreeSpace",
              operators::KernelInfo{"Free space, viscosity mu / 'Operator/ScaledFreeSpace/Stokeslet scale'.",
                                    operators::FluidDomain::Unbounded, scaledStokesletParameters()},
              [](const Teuchos::RCP<const Teuchos::Comm<int>>& comm, operators::CellSurfaces surfaces,
                 const operators::DiscretisationParameters& discretisation, const operators::SolverParameters& solver,
                 const Teuchos::ParameterList& settings, const domain::Domain& domain) {
                auto freeSpace = operators::solverFactory<operators::FreeSpace3DKernel>()(
                    comm, std::move(surfaces), discretisation, solver, settings, domain);
                return std::unique_ptr<BoundaryIntegralSolver>(
                    new ScaledStokesletSolver(std::move(freeSpace), settings.get<double>("Stokeslet scale")));
              });
}

} // namespace capsula::run::testing
