#include "capsula/scene/Scene.hpp"

#include "capsula/scene/CellPlacement.hpp"
#include "capsula/scene/NodesAboveWall.hpp"
#include "capsula/scene/SceneBounds.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/Timers.hpp>
#include <capsula/elasticity/Prestress.hpp>
#include <capsula/mesh/Adaption.hpp>
#include <capsula/mesh/CellSurfaceParameters.hpp>
#include <capsula/mesh/MeshQuality.hpp>
#include <capsula/mesh/NodeRedistribution.hpp>
#include <capsula/operators/CellSurfaces.hpp>
#include <capsula/operators/KernelChoice.hpp>
#include <capsula/operators/OperatorParameters.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace capsula::scene {

namespace core = capsula::core;

namespace {
// u_inf = k(t) (y + c y^2) e_x (domain/FlowProfile.hpp) as the operators take it.
operators::BackgroundFlow backgroundFlow(const domain::FlowProfile& profile, double shearRate)
{
  operators::BackgroundFlow flow = operators::LinearFlow::simpleShear(shearRate);
  flow.curvature = shearRate * profile.curvature();
  return flow;
}

std::string describeMembrane(const CellDescription& cell, const mesh::SurfaceMesh& surface)
{
  std::ostringstream line;
  line << "membrane " << cell.path << ": " << cell.membraneLaw;
  // The law's own keys, whatever the law: "Skalak (Area dilation C = 2.5)".
  const auto& keys = cell.membraneLawParameters;
  for (auto it = keys.begin(); it != keys.end(); ++it) {
    line << (it == keys.begin() ? " (" : ", ") << keys.name(it) << " = " << keys.entry(it).getAny(false);
  }
  if (keys.begin() != keys.end()) {
    line << ")";
  }
  if (cell.shearModulus != 1.0) {
    line << ", shear modulus " << cell.shearModulus << " G";
  }
  line << ", load by " << cell.membraneForces;
  line << ", " << (cell.prestress > 0.0 ? "prestressed reference, alpha = " : "unstressed at start");
  if (cell.prestress > 0.0) {
    line << cell.prestress;
  }
  if (cell.bendingModulus > 0.0) {
    line << ", Helfrich bending E_b = " << cell.bendingModulus;
    if (cell.bendingReference == "Initial shape") {
      line << " about the reference shape's curvature";
    } else {
      line << ", c0 = " << cell.spontaneousCurvature;
    }
  }
  line << "; mesh level " << cell.meshLevel << " (" << surface.numElements() << " elements, " << surface.numNodes()
       << " nodes)";
  return line.str();
}

// "5", or per cell where they differ: "5 (Cell 0), 1 (Cell 1)".
std::string describeViscosityRatios(const SceneDescription& description)
{
  const std::vector<double> ratios = description.viscosityRatios();
  std::ostringstream line;
  if (std::all_of(ratios.begin(), ratios.end(), [&](double lambda) { return lambda == ratios.front(); })) {
    line << ratios.front();
    return line.str();
  }
  for (std::size_t c = 0; c < ratios.size(); ++c) {
    line << (c > 0 ? ", " : "") << ratios[c] << " (" << description.cells[c].path.substr(6) << ")";
  }
  return line.str();
}

std::vector<int> nodesPerCell(const std::vector<mesh::SurfaceMesh>& cells)
{
  std::vector<int> nodes;
  for (const auto& cell : cells) {
    nodes.push_back(cell.numNodes());
  }
  return nodes;
}

// The cells' surfaces as the deck describes them (the state at t = 0), with room in the
// domain and clear of its walls.
std::vector<mesh::SurfaceMesh> initialSurfaces(const SceneDescription& description)
{
  std::vector<mesh::SurfaceMesh> cells;
  cells.reserve(description.cells.size());
  for (const auto& cell : description.cells) {
    cells.push_back(mesh::buildCellSurface(cell.surface, cell.path));
    // A domain too small for the cell first: no placement could then keep the gaps.
    requireRoomInDomain(cells.back(), cell.path, description.domain, description.minimumWallGap,
                        description.minimumGap);
    requireWallGaps(cells.back(), cell.path, description.domain, description.minimumWallGap);
  }
  requireSceneWithinBounds(description, cells);
  return cells;
}

} // namespace

Scene::Scene(const SceneDescription& description, const Teuchos::ParameterList& deck,
             const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const operators::KernelRegistry& kernels)
    : Scene(description, deck, comm, kernels, initialSurfaces(description), {})
{}

Scene::Scene(const SceneDescription& description, const Teuchos::ParameterList& deck,
             const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const operators::KernelRegistry& kernels,
             std::vector<mesh::SurfaceMesh> cells, std::vector<std::vector<double>> references)
    : description_(description),
      comm_(comm),
      cells_(std::move(cells)),
      ownership_(comm, nodesPerCell(cells_)),
      membraneTimer_(core::timer("Membrane tensions and loads")),
      velocityTimer_(core::timer("Boundary-integral velocity")),
      constraintTimer_(core::timer("Stage constraints"))
{
  const int n = description_.numCells();
  core::require<core::InputError>(n >= 1, "The scene has no cell: add 'Cells/Cell 0'.");
  core::require<core::InputError>(description_.capillaryNumber > 0.0 && std::isfinite(description_.capillaryNumber),
                                  "'Flow/Capillary number' = ", description_.capillaryNumber,
                                  " must be a finite number > 0.");
  core::require<core::InputError>(description_.viscosityRatio > 0.0 && std::isfinite(description_.viscosityRatio),
                                  "'Flow/Viscosity ratio' = ", description_.viscosityRatio,
                                  " must be a finite number > 0.");
  core::require(cells_.size() == static_cast<std::size_t>(n), "Scene: ", cells_.size(), " surfaces for ", n, " cells");
  core::require(references.empty() || references.size() == cells_.size(), "Scene: ", references.size(),
                " reference shapes for ", n, " cells");

  // Nothing inside anything else.
  std::vector<const mesh::SurfaceMesh*> placed;
  std::vector<std::string> paths;
  for (int c = 0; c < n; ++c) {
    const auto& path = description_.cells[static_cast<std::size_t>(c)].path;
    requireInFluid(cells_[static_cast<std::size_t>(c)], path, description_.domain);
    requireRoomInDomain(cells_[static_cast<std::size_t>(c)], path, description_.domain, description_.minimumWallGap,
                        description_.minimumGap);
    placed.push_back(&cells_[static_cast<std::size_t>(c)]);
    paths.push_back(path);
  }
  requireNoOverlap(placed, paths, description_.minimumGap, description_.domain);

  // Membranes.
  const auto discretisation = operators::readDiscretisationParameters(deck.sublist("Discretisation"));
  auto solverParameters = operators::readSolverParameters(deck.sublist("Solver"));
  solverParameters.preconditionerRefresh = operators::SolverParameters::PreconditionerRefresh::OnRequest; // startStep
  elasticity::MembraneDiscretisation membraneDiscretisation;
  membraneDiscretisation.numQuadraturePoints = discretisation.quadraturePoints;
  for (int c = 0; c < n; ++c) {
    const CellDescription& cell = description_.cells[static_cast<std::size_t>(c)];
    core::require(cell.law != nullptr, "Scene: '", cell.path, "' has no membrane law (describeScene builds it)");
    const mesh::SurfaceMesh& surface = cells_[static_cast<std::size_t>(c)];
    references_.push_back(!references.empty()    ? std::move(references[static_cast<std::size_t>(c)])
                          : cell.prestress > 0.0 ? elasticity::prestressedReference(surface, cell.prestress)
                                                 : surface.positions());
    terms_.push_back(describeMembrane(cell, surface));
  }
  membranes_.resize(static_cast<std::size_t>(n));
  ownership_.forEachOwnedCell([&](int c) {
    const CellDescription& cell = description_.cells[static_cast<std::size_t>(c)];
    membraneDiscretisation.forceMethod = elasticity::membraneForceMethod(cell.membraneForces);
    elasticity::BendingParameters bending;
    bending.modulus = cell.bendingModulus;
    bending.spontaneousCurvature = cell.spontaneousCurvature;
    bending.reference = elasticity::bendingReference(cell.bendingReference);
    try {
      membranes_[static_cast<std::size_t>(c)] = std::make_unique<elasticity::MembraneMechanics>(
          cells_[static_cast<std::size_t>(c)], references_[static_cast<std::size_t>(c)], cell.law,
          membraneDiscretisation, bending);
    } catch (const core::InputError& e) {
      throw core::InputError(core::message("'", cell.path, "': ", e.what()));
    }
  });

  buildExternalForces();

  // The boundary-integral operator for the kernel the geometry needs.
  operators::CellSurfaces surfaces(cells_, description_.viscosityRatios());
  initialPositions_ = surfaces.positions();
  // Decks of the scene tests carry no "Operator" list: Auto, as in a validated deck.
  const Teuchos::ParameterList noOperatorList;
  kernel_ = operators::readKernelChoice(deck.isSublist("Operator") ? deck.sublist("Operator") : noOperatorList,
                                        kernels.infos(), description_.domain);
  const std::string& kernel = kernel_.name;
  solver_ = kernels.create(kernel, comm_, std::move(surfaces), discretisation, solverParameters, kernel_.parameters,
                           description_.domain);
  if (solverParameters.warmStart) {
    warmStart_.emplace();
  }
  {
    std::ostringstream line;
    line << "kernel: " << kernel << " (" << solver_->kernelName()
         << "), single layer with N_Q = " << discretisation.quadraturePoints
         << ", N_GL = " << discretisation.singularQuadraturePoints;
    terms_.push_back(line.str());
  }
  {
    std::ostringstream line;
    if (description_.allViscosityRatiosOne()) {
      line << "viscosity ratio 1: explicit velocity (no double layer, no linear solve)";
    } else {
      line << "viscosity ratio " << describeViscosityRatios(description_) << ": double layer and Belos "
           << (solverParameters.cellBlockPreconditioner ? "Flexible GMRES on each cell's block"
                                                        : solverParameters.method)
           << " (tolerance " << solverParameters.tolerance << (solverParameters.warmStart ? ", warm start" : "") << ")";
    }
    terms_.push_back(line.str());
  }
  flow_.capillaryNumber = description_.capillaryNumber;
  flow_.background = backgroundFlow(description_.flowProfile, 1.0);
  {
    std::ostringstream line;
    line << "flow: " << description_.flowProfile.describe() << ", Ca = " << description_.capillaryNumber;
    if (description_.shearRate.periodic()) {
      line << " at the mean k; k(t) " << description_.shearRate.describe();
    } else {
      line << " (k = 1)";
    }
    terms_.push_back(line.str());
  }

  // Constraints, only if asked for.
  std::vector<mesh::SurfaceMesh> fixed;
  std::vector<int> offsets;
  for (int c = 0; c < n; ++c) {
    if (description_.cells[static_cast<std::size_t>(c)].fixedHeight) {
      fixed.push_back(cells_[static_cast<std::size_t>(c)]);
      offsets.push_back(nodeOffset(c));
      terms_.push_back("constraint: fixed centroid height of " + description_.cells[static_cast<std::size_t>(c)].path);
    }
  }
  if (!fixed.empty()) {
    fixedHeight_.emplace(std::move(fixed), std::move(offsets));
  }
  std::vector<mesh::SurfaceMesh> conserved;
  std::vector<int> conservedOffsets;
  for (int c = 0; c < n; ++c) {
    if (description_.cells[static_cast<std::size_t>(c)].conserveVolume) {
      conserved.push_back(cells_[static_cast<std::size_t>(c)]);
      conservedOffsets.push_back(nodeOffset(c));
      terms_.push_back("constraint: no net normal flux through the surface of " +
                       description_.cells[static_cast<std::size_t>(c)].path + " (volume conserved)");
    }
  }
  if (!conserved.empty()) {
    volume_.emplace(std::move(conserved), std::move(conservedOffsets));
  }
  if (description_.meshRegularisation.enabled) {
    std::ostringstream line;
    const auto& settings = description_.meshRegularisation;
    line << "mesh regularisation: tangential node redistribution below " << settings.triggerAngle << " degrees (up to "
         << settings.options.passes << " passes, relaxation " << settings.options.relaxation
         << (settings.options.preserveVolume ? ", volume kept" : "") << "), reference positions carried along";
    terms_.push_back(line.str());
  }
  if (description_.meshAdaption.enabled) {
    std::ostringstream line;
    const auto& settings = description_.meshAdaption;
    line << "mesh adaption: refine where kappa^2 A >= " << settings.options.threshold << " (curvature by "
         << mesh::curvatureMethodName(settings.options.curvature) << "), checked every " << settings.checkInterval
         << " steps, at most " << settings.maxElements << " elements per cell";
    terms_.push_back(line.str());
  }
  loads_.assign(3 * static_cast<std::size_t>(numElements()), 0.0);
  loadDensity_.assign(18 * static_cast<std::size_t>(numElements()), 0.0);
}

// The likely cause of a non-finite state at time t, and what to change.
std::string Scene::nonFiniteCause(double t) const
{
  // The membrane loads scale as 1/Ca: many orders below the smallest Ca the stiff methods
  // are run at (5e-4, docs/stiff-integration.md) the first loads overflow, and no tolerance helps.
  constexpr double kSmallCa = 1e-8;
  if (description_.capillaryNumber < kSmallCa) {
    return core::message("'Flow/Capillary number' = ", description_.capillaryNumber,
                         " is the cause: the membrane loads scale as 1/Ca and overflow. Raise it; small Ca needs a "
                         "stiff 'Time integration/Method' (ROS34PW2, run down to Ca = 5e-4 in "
                         "docs/stiff-integration.md).");
  }
  if (t == 0.0) {
    return "the first step already fails, which a tolerance does not cause: check the deck's moduli, Ca and the "
           "initial shape.";
  }
  return "the run has become unstable. Reduce 'Time integration/Tolerance' or refine the mesh.";
}

void Scene::setPositions(double t, const std::vector<double>& positions)
{
  core::require(positions.size() == 3 * static_cast<std::size_t>(numNodes()), "Scene: a state of ", positions.size(),
                " numbers for ", numNodes(), " nodes");
  for (int c = 0; c < numCells(); ++c) {
    const double* x = positions.data() + 3 * static_cast<std::size_t>(nodeOffset(c));
    mesh::SurfaceMesh& surface = cells_[static_cast<std::size_t>(c)];
    for (int i = 0; i < surface.numNodes(); ++i) {
      const double* p = x + 3 * i;
      if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) {
        throw core::NumericalError(core::message("At t = ", t, " node ", i, " of '",
                                                 description_.cells[static_cast<std::size_t>(c)].path,
                                                 "' has a non-finite position: ", nonFiniteCause(t)));
      }
      core::require<core::NumericalError>(description_.domain.inFluid(p), "At t = ", t, " node ", i, " of '",
                                          description_.cells[static_cast<std::size_t>(c)].path, "' reached ",
                                          description_.domain.nearestWallName(p[1]), " (y = ", p[1],
                                          description_.contact.enabled
                                              ? "). The contact repulsion did not hold it: raise 'Contact/Strength'."
                                              : "). Without 'Contact/Enabled' the model has no contact force.");
    }
    surface.setPositions(x);
  }
  solver_->setPositions(positions.data());
}

std::vector<MeshRegularisation> Scene::regulariseMeshes(double t, std::vector<double>& positions)
{
  std::vector<MeshRegularisation> done;
  if (!regularisesMeshes()) {
    return done;
  }
  const auto& settings = description_.meshRegularisation;
  for (int c = 0; c < numCells(); ++c) {
    mesh::SurfaceMesh& surface = cells_[static_cast<std::size_t>(c)];
    double* x = positions.data() + 3 * static_cast<std::size_t>(nodeOffset(c));
    surface.setPositions(x);
    if (mesh::meshQuality(surface).minAngle >= settings.triggerAngle) {
      continue;
    }
    mesh::RedistributionOptions options = settings.options;
    // Work on the elements near the bound only: every node moved is re-interpolated, which
    // costs shape (O(h^3) per move); 10 degrees above the trigger gives the passes room.
    options.improveBelow = std::min(60.0, settings.triggerAngle + 10.0);
    const mesh::RedistributedNodes moved =
        mesh::redistributeNodes(surface, surface.positions(), referencePositions(c), options);
    if (moved.passes == 0) { // no pass improved the smallest angle: leave the cell as it is
      continue;
    }
    std::copy(moved.positions.begin(), moved.positions.end(), x);
    surface.setPositions(x);
    try {
      replaceReference(c, moved.reference);
    } catch (const core::InputError& e) {
      throw core::NumericalError(core::message("At t = ", t, ", redistributing the nodes of '",
                                               description_.cells[static_cast<std::size_t>(c)].path,
                                               "' left a degenerate reference shape: ", e.what()));
    }
    done.push_back({c, moved.minAngleBefore, moved.minAngleAfter, moved.referenceMinAngle, moved.passes,
                    moved.maxDisplacement, moved.volumeOffset});
  }
  if (!done.empty()) {
    solver_->setPositions(positions.data());
  }
  return done;
}

std::optional<AdaptedCells> Scene::adaptedCells(const std::vector<double>& positions) const
{
  if (!adaptsMeshes()) {
    return std::nullopt;
  }
  const auto& settings = description_.meshAdaption;
  AdaptedCells adapted;
  bool any = false;
  for (int c = 0; c < numCells(); ++c) {
    mesh::SurfaceMesh current = cells_[static_cast<std::size_t>(c)];
    current.setPositions(positions.data() + 3 * static_cast<std::size_t>(nodeOffset(c)));
    mesh::AdaptedMembraneMesh refined =
        mesh::adaptMembraneMesh(current, referencePositions(c), settings.options, settings.maxElements);
    any = any || refined.markedElements > 0;
    adapted.cells.push_back(std::move(refined.current));
    adapted.references.push_back(std::move(refined.reference));
    adapted.markedElements.push_back(refined.markedElements);
  }
  if (!any) {
    return std::nullopt;
  }
  return adapted;
}

const elasticity::MembraneMechanics& Scene::membrane(int c) const
{
  core::require(ownership_.owns(c), "Scene: the membrane of '", description_.cells[static_cast<std::size_t>(c)].path,
                "' is held by rank ", ownership_.owner(c), ", not by rank ", comm_->getRank());
  return *membranes_[static_cast<std::size_t>(c)];
}

void Scene::setReferencePositions(int c, std::vector<double> reference)
{
  replaceReference(c, std::move(reference));
}

// Collective: the owner rebuilds the membrane on the new reference (an InputError for a
// degenerate one reaches every rank).
void Scene::replaceReference(int c, std::vector<double> reference)
{
  references_[static_cast<std::size_t>(c)] = std::move(reference);
  ownership_.onOwner(c, [&] {
    auto& membrane = membranes_[static_cast<std::size_t>(c)];
    membrane = std::make_unique<elasticity::MembraneMechanics>(
        membrane->withReference(references_[static_cast<std::size_t>(c)]));
  });
}

std::vector<std::size_t> Scene::perElementOffsets(std::size_t width) const
{
  std::vector<std::size_t> offsets;
  for (int c = 0; c < numCells(); ++c) {
    offsets.push_back(width * static_cast<std::size_t>(elementOffset(c)));
  }
  offsets.push_back(width * static_cast<std::size_t>(numElements()));
  return offsets;
}

std::vector<std::size_t> Scene::perNodeOffsets(std::size_t width) const
{
  std::vector<std::size_t> offsets;
  for (int c = 0; c < numCells(); ++c) {
    offsets.push_back(width * static_cast<std::size_t>(nodeOffset(c)));
  }
  offsets.push_back(width * static_cast<std::size_t>(numNodes()));
  return offsets;
}

// The forces from outside the membranes, only those the deck enables (ExternalForces.hpp).
void Scene::buildExternalForces()
{
  external_.emplace(description_, cells_, references_);
  terms_.insert(terms_.end(), external_->terms().begin(), external_->terms().end());
}

void Scene::computeLoads(double t, elasticity::MembraneEvaluation what)
{
  Teuchos::TimeMonitor guard(*membraneTimer_);
  if (external_->any()) {
    external_->compute(cells_);
  }
  ownership_.forEachOwnedCell([&](int c) {
    auto& membrane = *membranes_[static_cast<std::size_t>(c)];
    try {
      membrane.evaluate(cells_[static_cast<std::size_t>(c)].positionData(), what,
                        external_->any() ? external_->forces(c)->data() : nullptr);
    } catch (const core::NumericalError& e) {
      throw core::NumericalError(core::message("At t = ", t, ", the membrane of '",
                                               description_.cells[static_cast<std::size_t>(c)].path,
                                               "' failed: ", e.what()));
    }
    // Delta f at the six nodes of each element (operators/LoadDensity.hpp), and its
    // element averages for the outputs.
    const std::size_t first = static_cast<std::size_t>(elementOffset(c));
    membrane.writeElementNodeLoads(loadDensity_.data() + 18 * first);
    const auto& averages = membrane.elementLoads();
    for (std::size_t e = 0; e < averages.size(); ++e) {
      for (int d = 0; d < 3; ++d) {
        loads_[3 * (first + e) + static_cast<std::size_t>(d)] = averages[e][d];
      }
    }
  });
  ownership_.share(loadDensity_, perElementOffsets(18));
  ownership_.share(loads_, perElementOffsets(3));
}

void Scene::velocity(double t, const std::vector<double>& positions, std::vector<double>& velocities)
{
  setPositions(t, positions);
  try {
    computeLoads(t, elasticity::MembraneEvaluation::LoadOnly); // no output reads the tensions of a stage
  } catch (const core::NumericalError& e) {
    // A stage state of a step too large for the membrane's fastest mode can fold it although
    // smaller steps do not: outside the model, so the attempt is rejected (NodesAboveWall.hpp).
    throw timeint::StateOutsideDomain(e.what());
  }
  Teuchos::TimeMonitor guard(*velocityTimer_);
  // Warm start: the Krylov solve begins at a combination of the last solutions (O(step) away).
  const operators::LoadDensity load(loadDensity_.data());
  const operators::FlowConditions flow = flowAt(t);
  operators::VelocitySolution solution =
      warmStart_ ? solver_->nodeVelocities(load, flow, *warmStart_) : solver_->nodeVelocities(load, flow);
  velocities = std::move(solution.velocities);
}

adhesion::BondEvents Scene::updateBonds(const std::vector<double>& positions, double dt, std::uint64_t step)
{
  core::require(hasBonds(), "Scene::updateBonds: the scene has no bonds");
  core::require(positions.size() == 3 * static_cast<std::size_t>(numNodes()), "Scene: a state of ", positions.size(),
                " numbers for ", numNodes(), " nodes");
  adhesion::BondEvents events;
  for (int c = 0; c < numCells(); ++c) {
    const double* x = positions.data() + 3 * static_cast<std::size_t>(nodeOffset(c));
    const adhesion::BondEvents cell =
        external_->bonds().update(c, cells_[static_cast<std::size_t>(c)], x, dt, step, *comm_);
    events.formed += cell.formed;
    events.broken += cell.broken;
  }
  return events;
}

operators::FlowConditions Scene::flowAt(double t) const
{
  operators::FlowConditions flow = flow_;
  flow.background = backgroundFlow(description_.flowProfile, description_.shearRate.factor(t));
  return flow;
}

void Scene::restoreGmresWarmStart(const std::vector<double>& rightHandSides, const std::vector<double>& solutions)
{
  const int depth = warmStart_ ? warmStart_->depth() : operators::WarmStartHistory().depth();
  warmStart_ = operators::WarmStartHistory::fromFlattened(depth, 3 * numNodes(), rightHandSides, solutions);
}

void Scene::constrain(const std::vector<double>& positions, std::vector<double>& velocities)
{
  if (!hasConstraints()) {
    return;
  }
  Teuchos::TimeMonitor guard(*constraintTimer_);
  if (volume_) { // a uniform rise carries no net flux, so the order does not matter to O(rule)
    volume_->apply(positions, velocities);
  }
  if (fixedHeight_) {
    fixedHeight_->apply(positions, velocities);
  }
}

SceneFields Scene::evaluate(double t, const std::vector<double>& positions)
{
  SceneFields fields;
  fields.positions = positions;
  setPositions(t, positions);
  computeLoads(t, elasticity::MembraneEvaluation::Everything);
  {
    Teuchos::TimeMonitor guard(*velocityTimer_);
    operators::VelocitySolution solution =
        solver_->nodeVelocities(operators::LoadDensity(loadDensity_.data()), flowAt(t));
    fields.solverVelocities = std::move(solution.velocities);
    fields.gmresIterations = solution.iterations;
  }
  fields.velocities = fields.solverVelocities;
  constrain(positions, fields.velocities);
  fields.elementLoads = loads_;
  fields.loadDensity = loadDensity_;
  // Each owner writes its cells' nodal values; share() completes them on every rank.
  fields.principalTensions.assign(2 * static_cast<std::size_t>(numNodes()), 0.0);
  fields.stretches.assign(2 * static_cast<std::size_t>(numNodes()), 0.0);
  fields.nodeNormals.assign(3 * static_cast<std::size_t>(numNodes()), 0.0);
  std::vector<double> extremes(2 * static_cast<std::size_t>(numCells()), 0.0);
  for (int c = 0; c < numCells(); ++c) {
    if (!ownership_.owns(c)) {
      continue;
    }
    const auto& membrane = *membranes_[static_cast<std::size_t>(c)];
    const std::size_t first = static_cast<std::size_t>(nodeOffset(c));
    const auto& tensions = membrane.nodalPrincipalTensions();
    const auto& stretches = membrane.nodalStretches();
    const auto& normals = membrane.nodeNormals();
    for (std::size_t i = 0; i < tensions.size(); ++i) {
      fields.principalTensions[2 * (first + i)] = tensions[i].major;
      fields.principalTensions[2 * (first + i) + 1] = tensions[i].minor;
      fields.stretches[2 * (first + i)] = stretches[i].major;
      fields.stretches[2 * (first + i) + 1] = stretches[i].minor;
      for (int d = 0; d < 3; ++d) {
        fields.nodeNormals[3 * (first + i) + static_cast<std::size_t>(d)] = normals[i][d];
      }
    }
    const MembraneExtremes cellExtremes = membraneExtremes(membrane);
    extremes[2 * static_cast<std::size_t>(c)] = cellExtremes.mostCompressiveTension;
    extremes[2 * static_cast<std::size_t>(c) + 1] = cellExtremes.leastPrincipalStiffness;
  }
  ownership_.share(fields.principalTensions, perNodeOffsets(2));
  ownership_.share(fields.stretches, perNodeOffsets(2));
  ownership_.share(fields.nodeNormals, perNodeOffsets(3));
  std::vector<std::size_t> cellOffsets;
  for (int c = 0; c <= numCells(); ++c) {
    cellOffsets.push_back(2 * static_cast<std::size_t>(c));
  }
  ownership_.share(extremes, cellOffsets);
  for (int c = 0; c < numCells(); ++c) {
    fields.membraneExtremes.push_back(
        {extremes[2 * static_cast<std::size_t>(c)], extremes[2 * static_cast<std::size_t>(c) + 1]});
  }
  return fields;
}

} // namespace capsula::scene
