#include "capsula/scene/VelocityJacobian.hpp"

#include "capsula/scene/ExternalLoadStiffness.hpp"
#include "capsula/scene/Scene.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/mesh/Measures.hpp>
#include <capsula/operators/CellSurfaces.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace capsula::scene {

namespace {

// The mass-matrix solves inside J~: far below the Krylov tolerances they feed.
constexpr double kMassSolveTolerance = 1e-11;

} // namespace

VelocityJacobian::VelocityJacobian(Scene& scene, const Teuchos::ParameterList& deck,
                                   const operators::KernelRegistry& kernels)
    : VelocityJacobian(scene, deck, kernels, readStiffSolverSettings(deck.sublist("Solver").sublist("Stiff")))
{}

VelocityJacobian::VelocityJacobian(Scene& scene, const Teuchos::ParameterList& deck,
                                   const operators::KernelRegistry& kernels, const StiffSolverSettings& settings)
    : StageJacobian(settings.stage, "Stiff Jacobian", "Local mobility"), scene_(scene), settings_(settings)
{
  const SceneDescription& description = scene.description();
  for (const CellDescription& cell : description.cells) {
    core::require<core::InputError>(
        cell.membraneForces == "Virtual work",
        "The stiff time integration ('Time integration/Method' ROS34PW2, ROS2 or ",
        "Auto) needs the membranes' tangent stiffness, the second variation of their strain energy; '", cell.path,
        "/Membrane forces' = '", cell.membraneForces,
        "' is not an energy gradient. Set it to 'Virtual work' or "
        "choose an explicit method (RKF45, DormandPrince45, RK4).");
  }
  std::vector<mesh::SurfaceMesh> cells;
  for (int c = 0; c < scene.numCells(); ++c) {
    cells.push_back(scene.cell(c));
  }
  operators::DiscretisationParameters discretisation =
      operators::readDiscretisationParameters(deck.sublist("Discretisation"));
  if (settings_.quadraturePoints > 0) {
    operators::requireTriangleRule(settings_.quadraturePoints, "Solver/Stiff/Quadrature points");
    discretisation.quadraturePoints = settings_.quadraturePoints;
  }
  frozen_ = kernels.create(scene.kernelKey(), scene.comm(),
                           operators::CellSurfaces(std::move(cells), description.viscosityRatios()), discretisation,
                           operators::readSolverParameters(deck.sublist("Solver")), scene.kernelParameters(),
                           description.domain);
  const int numNodes = scene.numNodes();
  const auto map = Teuchos::rcp(
      new Tpetra::Map<>(3 * static_cast<Tpetra::global_size_t>(numNodes), 0, scene.comm(), Tpetra::LocallyReplicated));
  const CellOwnership& ownership = scene.cellOwnership();
  std::vector<int> cellNodeOffsets;
  for (int c = 0; c < scene.numCells(); ++c) {
    cellNodeOffsets.push_back(scene.nodeOffset(c));
    cellUnknownOffsets_.push_back(3 * static_cast<std::size_t>(scene.nodeOffset(c)));
  }
  cellNodeOffsets.push_back(numNodes);
  cellUnknownOffsets_.push_back(3 * static_cast<std::size_t>(numNodes));
  if (settings_.preconditioned) {
    preconditioner_ = Teuchos::rcp(new LocalMobilityPreconditioner(map, ownership, std::move(cellNodeOffsets)));
  }
  // Eq 3.38 per node with the lambda of its cell.
  for (int c = 0; c < scene.numCells(); ++c) {
    const double lambda = description.cells[static_cast<std::size_t>(c)].viscosityRatio;
    coefficient_.insert(coefficient_.end(), static_cast<std::size_t>(scene.cell(c).numNodes()),
                        -1.0 / (4.0 * M_PI * (1.0 + lambda) * scene.flow().capillaryNumber));
    flowFactor_.insert(flowFactor_.end(), static_cast<std::size_t>(scene.cell(c).numNodes()), 2.0 / (1.0 + lambda));
  }
  startSolver(map, preconditioner_);
  stiffness_.resize(static_cast<std::size_t>(scene.numCells()));
  mass_.resize(static_cast<std::size_t>(scene.numCells()));
  for (int c = 0; c < scene.numCells(); ++c) {
    if (ownership.owns(c)) {
      mass_[static_cast<std::size_t>(c)] = std::make_unique<mesh::SurfaceMassMatrix>(scene.cell(c));
    }
  }
  if (hasExternalLoadStiffness(scene)) {
    external_.resize(static_cast<std::size_t>(scene.numCells()));
  }
}

void VelocityJacobian::freeze(double t, const std::vector<double>& y)
{
  // grad u_inf at each node as it is at the step's start (Poiseuille's varies with y).
  const operators::BackgroundFlow background = scene_.flowAt(t).background;
  flowGradients_.resize(y.size() / 3);
  for (std::size_t g = 0; g < flowGradients_.size(); ++g) {
    flowGradients_[g] = background.gradientAt(mesh::nodeAt(y.data(), static_cast<int>(g)));
  }
  frozenPositions_ = y;
  frozen_->setPositions(y.data());
  const SceneDescription& description = scene_.description();
  scene_.cellOwnership().forEachOwnedCell([&](int c) {
    const double* positions = y.data() + 3 * static_cast<std::size_t>(scene_.nodeOffset(c));
    auto& stiffness = stiffness_[static_cast<std::size_t>(c)];
    stiffness.reset();
    try {
      stiffness.emplace(scene_.membrane(c).tangentStiffness(positions));
    } catch (const core::NumericalError& e) {
      throw core::NumericalError(core::message("The membrane of '", description.cells[static_cast<std::size_t>(c)].path,
                                               "' failed: ", e.what()));
    }
    const adhesion::LoadStiffness* external = nullptr;
    if (!external_.empty()) { // the bonds as they are over the step (they change between steps)
      externalLoadStiffness(scene_, c, positions, external_[static_cast<std::size_t>(c)]);
      external = &external_[static_cast<std::size_t>(c)];
    }
    mass_[static_cast<std::size_t>(c)]->assemble(positions);
    if (preconditioner_.is_null()) {
      return;
    }
    // Node i's share of the area, A_i = sum of its elements' areas / 6 (the shares add up
    // to the area), and its local mobility c beta / sqrt(A_i / pi).
    const mesh::SurfaceMesh& cell = scene_.cell(c);
    const std::vector<double> areas = mesh::elementAreas(cell, positions);
    std::vector<double> share(static_cast<std::size_t>(cell.numNodes()), 0.0);
    for (int e = 0; e < cell.numElements(); ++e) {
      for (const int node : cell.element(e)) {
        share[static_cast<std::size_t>(node)] += areas[static_cast<std::size_t>(e)] / 6.0;
      }
    }
    const double c0 = -coefficient_[static_cast<std::size_t>(scene_.nodeOffset(c))];
    std::vector<double> mobility(share.size());
    for (std::size_t i = 0; i < share.size(); ++i) {
      mobility[i] = c0 * settings_.mobilityFactor / std::sqrt(share[i] / M_PI);
    }
    preconditioner_->setCell(c, scene_.nodeOffset(c), *stiffness, std::move(mobility), external);
  });
}

void VelocityJacobian::applyFrozen(const double* x, double* y)
{
  const std::size_t n = 3 * static_cast<std::size_t>(scene_.numNodes());
  forces_.resize(n);
  loads_.resize(n);
  for (int c = 0; c < scene_.numCells(); ++c) {
    if (!scene_.cellOwnership().owns(c)) {
      continue;
    }
    const std::size_t first = 3 * static_cast<std::size_t>(scene_.nodeOffset(c));
    const elasticity::TangentStiffness& stiffness = *stiffness_[static_cast<std::size_t>(c)];
    stiffness.apply(x + first, forces_.data() + first); // strain and bending, as the membrane adds them
    if (!external_.empty()) {
      external_[static_cast<std::size_t>(c)].addProduct(x + first, forces_.data() + first);
    }
    mass_[static_cast<std::size_t>(c)]->solve(forces_.data() + first, loads_.data() + first, kMassSolveTolerance);
  }
  scene_.cellOwnership().share(loads_, cellUnknownOffsets_); // the other owners' cells
  const std::vector<double> single = frozen_->singleLayerOfNodalLoad(loads_.data());
  operators::combineWithFlowGradient<3>([this](std::size_t g) -> const mesh::Mat3& { return flowGradients_[g]; },
                                        [this](std::size_t g) { return coefficient_[g]; },
                                        [this](std::size_t g) { return flowFactor_[g]; }, n / 3, x, single, y);
  if (scene_.hasConstraints()) {
    product_.assign(y, y + n);
    scene_.constrain(frozenPositions_, product_);
    std::copy(product_.begin(), product_.end(), y);
  }
}

std::string VelocityJacobian::describe() const
{
  std::ostringstream line;
  line << "stiff Jacobian: single layer of the membranes' tangent stiffness";
  const auto& cells = scene_.description().cells;
  if (std::any_of(cells.begin(), cells.end(), [](const CellDescription& cell) {
        return cell.bendingModulus != 0.0 || cell.spontaneousCurvature != 0.0; // as MembraneMechanics builds it
      })) {
    line << " (with the bending stiffness on the normal modes)";
  }
  if (!external_.empty()) {
    line << (scene_.hasBonds() ? " and of the bonds" : "") << (scene_.hasTether() ? " and of the tether" : "")
         << (scene_.description().contact.enabled && scene_.description().wall ? " and of the wall contact" : "");
  }
  line << ", frozen each step";
  if (!scene_.description().allViscosityRatiosOne()) {
    line << " (double layer left out)";
  }
  if (scene_.hasConstraints()) {
    line << ", stage constraints";
  }
  line << "; " << operators::describe(stageSettings());
  if (settings_.preconditioned) {
    line << " with the local-mobility preconditioner (beta = " << settings_.mobilityFactor << ")";
  } else {
    line << " without preconditioner";
  }
  return line.str();
}

} // namespace capsula::scene
