#pragma once
// BoundaryIntegralSolver for one Green's function policy. A library that adds a kernel
// instantiates this template with its policy and registers solverFactory<Policy>() in a
// KernelRegistry (docs/extending.md); nothing in this package changes.
#include <capsula/operators/BoundaryIntegralSolver.hpp>
#include <capsula/operators/CellBlockPreconditioner.hpp>
#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/operators/LayerPotentials.hpp>
#include <capsula/operators/NodeDistribution.hpp>
#include <capsula/operators/SecondKindSolve.hpp>

#include <capsula/core/Error.hpp>
#include <capsula/core/Timers.hpp>

#include <cmath>
#include <memory>

namespace capsula::operators {

template <class Kernel>
class KernelBoundaryIntegralSolver final : public BoundaryIntegralSolver {
public:
  /// The surfaces' current positions are the first geometry; `kernel` is the policy
  /// instance (its periods, for a periodic kernel).
  KernelBoundaryIntegralSolver(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, CellSurfaces surfaces,
                               const DiscretisationParameters& discretisation, const SolverParameters& solver,
                               Kernel kernel = Kernel{});

  std::string kernelName() const override { return Kernel::name; }
  const CellSurfaces& surfaces() const override { return surfaces_; }
  Teuchos::RCP<const Tpetra::Map<>> velocityMap() const override { return distribution_.map(); }
  int firstOwnedNode() const override { return distribution_.firstOwnedNode(); }
  int numOwnedNodes() const override { return distribution_.numOwnedNodes(); }

  void setPositions(const double* positions) override;
  void refreshPreconditioner() override { preconditioner_ = Teuchos::null; }
  VelocitySolution nodeVelocities(const LoadDensity& load, const FlowConditions& flow,
                                  const double* initialGuess = nullptr) override;
  VelocitySolution nodeVelocities(const LoadDensity& load, const FlowConditions& flow,
                                  WarmStartHistory& history) override;
  std::vector<double> flowVelocity(const std::vector<double>& points, const LoadDensity& load,
                                   const double* nodeVelocities, const FlowConditions& flow) override;

  std::vector<double> singleLayer(const LoadDensity& load) override;
  std::vector<double> singleLayerOfNodalLoad(const double* nodalLoad) override;
  std::vector<double> doubleLayer(const double* density, DoubleLayerForm form) override;
  std::vector<double> singleLayerAt(const std::vector<double>& points, const LoadDensity& load) override;
  std::vector<double> doubleLayerAt(const std::vector<double>& points, const double* density) override;
  std::vector<double> solidAnglesAt(const std::vector<double>& points) override;

  /// The numerical core (for benchmarks and diagnostics).
  LayerPotentials<Kernel>& layerPotentials() { return potentials_; }

private:
  double lambdaOfNode(int node) const { return surfaces_.viscosityRatio(surfaces_.cellOfNode(node)); }
  // Both nodeVelocities: GMRES from `initialGuess`, or from `history` when that is given.
  VelocitySolution solveNodeVelocities(const LoadDensity& load, const FlowConditions& flow, const double* initialGuess,
                                       WarmStartHistory* history);
  void requireInFluid(const std::vector<double>& points) const;
  std::vector<double> ownedPointsShare(const std::vector<double>& points) const;
  // 'Solver/Preconditioner' = "Cell blocks": built at the first solve after setPositions
  // or refreshPreconditioner (SolverParameters::preconditionerRefresh), kept until then.
  const Teuchos::RCP<CellBlockPreconditioner>& cellBlockPreconditioner();

  NodeDistribution distribution_;
  CellSurfaces surfaces_;
  SolverParameters solverParameters_;
  LayerPotentials<Kernel> potentials_;
  Teuchos::RCP<Teuchos::Time> singleLayerTimer_, solveTimer_, flowTimer_;
  Teuchos::RCP<CellBlockPreconditioner> preconditioner_; // null: none, or to be built at the next solve
};

/// The factory a KernelRegistry stores for `Kernel` (a policy without settings or state of
/// its own, default-constructed; a kernel with state writes its own factory).
template <class Kernel>
SolverFactory solverFactory()
{
  return [](const Teuchos::RCP<const Teuchos::Comm<int>>& comm, CellSurfaces surfaces,
            const DiscretisationParameters& discretisation, const SolverParameters& solver,
            const Teuchos::ParameterList& /*kernelParameters*/, const domain::Domain& /*domain*/) {
    return std::unique_ptr<BoundaryIntegralSolver>(
        new KernelBoundaryIntegralSolver<Kernel>(comm, std::move(surfaces), discretisation, solver));
  };
}

// ---------------------------------------------------------------------------------------
// Implementation

template <class Kernel>
KernelBoundaryIntegralSolver<Kernel>::KernelBoundaryIntegralSolver(const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                                                                   CellSurfaces surfaces,
                                                                   const DiscretisationParameters& discretisation,
                                                                   const SolverParameters& solver, Kernel kernel)
    : distribution_(comm, surfaces.numNodes()),
      surfaces_(std::move(surfaces)),
      solverParameters_(solver),
      potentials_(discretisation, std::move(kernel)),
      singleLayerTimer_(core::timer("Single layer")),
      solveTimer_(core::timer("Viscosity-ratio GMRES solve")),
      flowTimer_(core::timer("Flow velocity at points"))
{
  validate(solverParameters_);
  potentials_.setTopology(surfaces_, distribution_.firstOwnedNode(), distribution_.numOwnedNodes());
}

template <class Kernel>
void KernelBoundaryIntegralSolver<Kernel>::setPositions(const double* positions)
{
  surfaces_.setPositions(positions);
  potentials_.update(surfaces_);
  if (solverParameters_.preconditionerRefresh == SolverParameters::PreconditionerRefresh::EveryGeometry) {
    preconditioner_ = Teuchos::null;
  }
}

template <class Kernel>
const Teuchos::RCP<CellBlockPreconditioner>& KernelBoundaryIntegralSolver<Kernel>::cellBlockPreconditioner()
{
  if (preconditioner_.is_null()) {
    std::vector<int> offsets(surfaces_.numCells() + 1);
    std::vector<double> scale(surfaces_.numCells());
    for (int c = 0; c < surfaces_.numCells(); ++c) {
      offsets[c] = surfaces_.nodeOffset(c);
      const double lambda = surfaces_.viscosityRatio(c);
      scale[c] = (1.0 - lambda) / (4.0 * M_PI * (1.0 + lambda)); // rowScale x densityScale (SecondKindOperator)
    }
    offsets.back() = surfaces_.numNodes();
    preconditioner_ = Teuchos::rcp(new CellBlockPreconditioner(
        distribution_.map(), std::move(offsets), std::move(scale), [this](int cell, std::vector<double>& rows) {
          Teuchos::TimeMonitor guard(*core::timer("Cell-block preconditioner: blocks"));
          return potentials_.cellDoubleLayerBlock(cell, rows);
        }));
  }
  return preconditioner_;
}

template <class Kernel>
VelocitySolution KernelBoundaryIntegralSolver<Kernel>::nodeVelocities(const LoadDensity& load,
                                                                      const FlowConditions& flow,
                                                                      const double* initialGuess)
{
  return solveNodeVelocities(load, flow, initialGuess, nullptr);
}

template <class Kernel>
VelocitySolution KernelBoundaryIntegralSolver<Kernel>::nodeVelocities(const LoadDensity& load,
                                                                      const FlowConditions& flow,
                                                                      WarmStartHistory& history)
{
  return solveNodeVelocities(load, flow, nullptr, &history);
}

template <class Kernel>
VelocitySolution
KernelBoundaryIntegralSolver<Kernel>::solveNodeVelocities(const LoadDensity& load, const FlowConditions& flow,
                                                          const double* initialGuess, WarmStartHistory* history)
{
  core::require<core::InputError>(flow.capillaryNumber > 0.0 && std::isfinite(flow.capillaryNumber),
                                  "The capillary number is ", flow.capillaryNumber,
                                  "; it must be a finite number > 0.");
  const int first = distribution_.firstOwnedNode();
  const int numOwned = distribution_.numOwnedNodes();
  const bool iterate = !surfaces_.allViscosityRatiosOne() || solverParameters_.alwaysIterate;

  std::vector<double> single(3 * static_cast<std::size_t>(numOwned));
  {
    Teuchos::TimeMonitor guard(*singleLayerTimer_);
    potentials_.singleLayerAtNodes(load, single.data());
  }
  // Right-hand side: 2/(1+lambda) u_inf - 1/(4 pi (1+lambda) Ca) SL (eq 3.15).
  std::vector<double> rhs(single.size());
  const double* positions = potentials_.quadrature().nodePositions().data();
  for (int t = 0; t < numOwned; ++t) {
    const int g = first + t;
    const double lambda = lambdaOfNode(g);
    const mesh::Vec3 background = flow.background.at(mesh::nodeAt(positions, g));
    for (int j = 0; j < 3; ++j) {
      rhs[3 * t + j] = 2.0 / (1.0 + lambda) * background[j] -
                       single[3 * t + j] / (4.0 * M_PI * (1.0 + lambda) * flow.capillaryNumber);
    }
  }
  VelocitySolution solution;
  if (!iterate) {
    solution.velocities = distribution_.gather(rhs);
    return solution;
  }

  Teuchos::TimeMonitor guard(*solveTimer_);
  std::vector<double> densityScale(surfaces_.numNodes());
  for (int g = 0; g < surfaces_.numNodes(); ++g) {
    densityScale[g] = 1.0 - lambdaOfNode(g);
  }
  std::vector<double> rowScale(numOwned);
  for (int t = 0; t < numOwned; ++t) {
    rowScale[t] = 1.0 / (4.0 * M_PI * (1.0 + lambdaOfNode(first + t)));
  }
  SecondKindEquation equation{distribution_,
                              [this](const double* density, double* rows) {
                                potentials_.doubleLayerAtNodes(density, DoubleLayerForm::Subtracted, rows);
                              },
                              std::move(densityScale), std::move(rowScale), "the viscosity-ratio equation"};
  SecondKindSolution solved =
      solveSecondKind(std::move(equation), rhs, solverParameters_, initialGuess, history,
                      solverParameters_.cellBlockPreconditioner ? cellBlockPreconditioner() : Teuchos::null);
  solution.velocities = std::move(solved.velocities);
  solution.iterations = solved.krylov.iterations;
  solution.residual = solved.krylov.residual;
  return solution;
}

template <class Kernel>
void KernelBoundaryIntegralSolver<Kernel>::requireInFluid(const std::vector<double>& points) const
{
  core::require<core::InputError>(points.size() % 3 == 0, "Flow points come as (x, y, z) triples; got ", points.size(),
                                  " numbers.");
  for (std::size_t p = 0; p < points.size(); p += 3) {
    core::require<core::InputError>(potentials_.traits().inFluid(&points[p]), "The flow point (", points[p], ", ",
                                    points[p + 1], ", ", points[p + 2], ") lies outside the fluid domain of the ",
                                    Kernel::name, " kernel.");
  }
}

template <class Kernel>
std::vector<double> KernelBoundaryIntegralSolver<Kernel>::ownedPointsShare(const std::vector<double>& points) const
{
  const auto [first, end] = distribution_.share(static_cast<int>(points.size() / 3));
  return std::vector<double>(points.begin() + 3 * first, points.begin() + 3 * end);
}

template <class Kernel>
std::vector<double>
KernelBoundaryIntegralSolver<Kernel>::flowVelocity(const std::vector<double>& points, const LoadDensity& load,
                                                   const double* nodeVelocities, const FlowConditions& flow)
{
  Teuchos::TimeMonitor guard(*flowTimer_);
  requireInFluid(points);
  const std::vector<double> mine = ownedPointsShare(points);
  const int n = static_cast<int>(mine.size() / 3);
  std::vector<double> single(mine.size()), velocity(mine.size());
  potentials_.singleLayerAtPoints(mine.data(), n, load, single.data());
  std::vector<double> dbl(mine.size(), 0.0);
  std::vector<double> omega;
  const bool allOne = surfaces_.allViscosityRatiosOne();
  if (!allOne) {
    std::vector<double> density(3 * static_cast<std::size_t>(surfaces_.numNodes()));
    for (std::size_t k = 0; k < density.size(); ++k) {
      density[k] = (1.0 - lambdaOfNode(static_cast<int>(k / 3))) * nodeVelocities[k];
    }
    potentials_.doubleLayerAtPoints(mine.data(), n, density.data(), dbl.data());
    omega.resize(static_cast<std::size_t>(n) * surfaces_.numCells());
    potentials_.solidAnglesAtPoints(mine.data(), n, omega.data());
  }
  for (int p = 0; p < n; ++p) {
    const mesh::Vec3 background = flow.background.at(mesh::nodeAt(mine.data(), p));
    // Inside cell c the representation gives lambda_c u (Pozrikidis 1992, eq 5.3.7).
    double scale = 1.0;
    for (int c = 0; !allOne && c < surfaces_.numCells(); ++c) {
      if (omega[static_cast<std::size_t>(surfaces_.numCells()) * p + c] > 2.0 * M_PI) {
        scale = 1.0 / surfaces_.viscosityRatio(c);
      }
    }
    for (int j = 0; j < 3; ++j) {
      velocity[3 * p + j] = scale * (background[j] - single[3 * p + j] / (8.0 * M_PI * flow.capillaryNumber) +
                                     dbl[3 * p + j] / (8.0 * M_PI));
    }
  }
  return distribution_.gatherShares(velocity, static_cast<int>(points.size() / 3), 3);
}

template <class Kernel>
std::vector<double> KernelBoundaryIntegralSolver<Kernel>::singleLayer(const LoadDensity& load)
{
  std::vector<double> rows(3 * static_cast<std::size_t>(distribution_.numOwnedNodes()));
  potentials_.singleLayerAtNodes(load, rows.data());
  return distribution_.gather(rows);
}

template <class Kernel>
std::vector<double> KernelBoundaryIntegralSolver<Kernel>::singleLayerOfNodalLoad(const double* nodalLoad)
{
  std::vector<double> rows(3 * static_cast<std::size_t>(distribution_.numOwnedNodes()));
  potentials_.singleLayerOfNodalLoadAtNodes(nodalLoad, rows.data());
  return distribution_.gather(rows);
}

template <class Kernel>
std::vector<double> KernelBoundaryIntegralSolver<Kernel>::doubleLayer(const double* density, DoubleLayerForm form)
{
  std::vector<double> rows(3 * static_cast<std::size_t>(distribution_.numOwnedNodes()));
  potentials_.doubleLayerAtNodes(density, form, rows.data());
  return distribution_.gather(rows);
}

template <class Kernel>
std::vector<double> KernelBoundaryIntegralSolver<Kernel>::singleLayerAt(const std::vector<double>& points,
                                                                        const LoadDensity& load)
{
  requireInFluid(points);
  const std::vector<double> mine = ownedPointsShare(points);
  std::vector<double> values(mine.size());
  potentials_.singleLayerAtPoints(mine.data(), static_cast<int>(mine.size() / 3), load, values.data());
  return distribution_.gatherShares(values, static_cast<int>(points.size() / 3), 3);
}

template <class Kernel>
std::vector<double> KernelBoundaryIntegralSolver<Kernel>::doubleLayerAt(const std::vector<double>& points,
                                                                        const double* density)
{
  requireInFluid(points);
  const std::vector<double> mine = ownedPointsShare(points);
  std::vector<double> values(mine.size());
  potentials_.doubleLayerAtPoints(mine.data(), static_cast<int>(mine.size() / 3), density, values.data());
  return distribution_.gatherShares(values, static_cast<int>(points.size() / 3), 3);
}

template <class Kernel>
std::vector<double> KernelBoundaryIntegralSolver<Kernel>::solidAnglesAt(const std::vector<double>& points)
{
  requireInFluid(points);
  const std::vector<double> mine = ownedPointsShare(points);
  const int numCells = surfaces_.numCells();
  std::vector<double> values(mine.size() / 3 * numCells);
  potentials_.solidAnglesAtPoints(mine.data(), static_cast<int>(mine.size() / 3), values.data());
  return distribution_.gatherShares(values, static_cast<int>(points.size() / 3), numCells);
}

} // namespace capsula::operators
