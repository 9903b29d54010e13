#include "capsula/scene2d/CapsuleModel2D.hpp"

#include "capsula/scene2d/TetherProcedure2D.hpp"

#include <capsula/contour/ContourMetrics.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/core/Timers.hpp>
#include <capsula/elasticity/BendingLoadBound.hpp>
#include <capsula/elasticity/Prestress.hpp>

#include <cmath>
#include <optional>
#include <sstream>

namespace capsula::scene2d {

namespace {

contour::ContourOptions optionsFor(contour::Closure closure, contour::TetherEnds tetherEnds)
{
  contour::ContourOptions options;
  options.closure = closure;
  options.tetherEnds = tetherEnds;
  return options;
}

} // namespace

std::unique_ptr<ElasticMembrane2D> CapsuleModel2D::makeMembrane(const contour::Contour& reference) const
{
  // The deck's tension law, with bending only when the deck asks for it.
  if (cell_.bendingModulus > 0.0) {
    return std::make_unique<ElasticMembrane2D>(reference, cell_.membraneLaw,
                                               BendingLaw2D{cell_.bendingModulus, cell_.bendingReference});
  }
  return std::make_unique<ElasticMembrane2D>(reference, cell_.membraneLaw);
}

CapsuleModel2D::CapsuleModel2D(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const CellSettings2D& cell,
                               const FlowSettings2D& flow, const ContourDiscretisation2D& discretisation,
                               const operators::SolverParameters& solver, KernelRegistry2D kernels)
    : cell_(cell),
      flow_(flow),
      discretisation_(discretisation),
      krylovMethod_(solver.method),
      referenceNodes_(initialCellNodes(cell)),
      freeReference_(elasticity::prestressedReference(referenceNodes_, cell.prestress))
{
  core::require<core::InputError>(!flow.domain.hasLowerWall() || cell.lowestPointHeight > 0.0,
                                  "Cell/Lowest point height must be > 0 above the wall, got ", cell.lowestPointHeight,
                                  ": raise it or set Wall/Enabled to false.");
  elasticity::BendingBoundInput bending; // the ellipse's sharpest curvature a / b^2 = AR^(3/2)
  bending.modulus = cell.bendingModulus;
  bending.shapeCurvature = std::pow(cell.aspectRatio, 1.5);
  bending.capillaryNumber = flow.conditions.capillaryNumber;
  bending.modulusKey = "Cell/Bending modulus";
  bending.capillaryKey = "Flow/Capillary number";
  elasticity::requireRepresentableBending(bending);
  const contour::Contour initial(referenceNodes_);
  referenceLength_ = initial.length();
  referenceArea_ = contour::enclosedArea(initial);
  membrane_ = makeMembrane(contour::Contour(freeReference_));
  kernels_ = std::move(kernels);
  velocity_ = makeInterfaceVelocity(comm, numberOfNodes(), discretisation, solver);
  if (solver.warmStart && flow.conditions.viscosityRatio != 1.0) {
    warmStart_.emplace();
  }
}

std::unique_ptr<InterfaceVelocity2D>
CapsuleModel2D::makeInterfaceVelocity(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int numNodes,
                                      const ContourDiscretisation2D& discretisation,
                                      const operators::SolverParameters& solver) const
{
  return kernels_.create(flow_.kernel.name, comm, numNodes, discretisation, solver, flow_.kernel.parameters);
}

void CapsuleModel2D::restoreGmresWarmStart(const std::vector<double>& rightHandSides,
                                           const std::vector<double>& solutions)
{
  core::require<core::InputError>(warmStart_.has_value(), "A checkpoint holds a GMRES warm start but this run has "
                                                          "none (lambda = 1 or 'Solver/Warm start' = false).");
  warmStart_ =
      operators::WarmStartHistory::fromFlattened(warmStart_->depth(), 2 * numberOfNodes(), rightHandSides, solutions);
}

std::vector<std::string> CapsuleModel2D::terms() const
{
  std::vector<std::string> terms{"single layer, " + kernelName() + " Green's function, log-singular rule"};
  if (flow_.conditions.viscosityRatio != 1.0) {
    terms.emplace_back("double layer (subtracted) with Belos " + krylovMethod_ + ", lambda != 1");
  }
  if (cell_.bendingModulus > 0.0) {
    std::ostringstream line;
    line << "membrane bending, k_b/(E L^2) = " << cell_.bendingModulus << ", reference curvature "
         << (cell_.bendingReference == BendingReference2D::Flat ? "0 (flat)" : "of the initial shape");
    terms.push_back(line.str());
  }
  if (discretisation_.nearSingularDistance > 0.0) {
    terms.emplace_back("near-singular subdivision");
  }
  if (flow_.shearRate.periodic()) {
    terms.emplace_back("flow: u = (k(t) y, 0), Ca at the mean k; k(t) " + flow_.shearRate.describe());
  }
  return terms;
}

void CapsuleModel2D::save(io::Checkpoint& checkpoint) const
{
  checkpoint.reals["run cell prestress"] = cell_.prestress;
  if (auto waveform = flow_.shearRate.waveformSamples(); !waveform.empty()) {
    checkpoint.arrays["run shear rate waveform"] = std::move(waveform);
  }
  if (warmStart_ && !warmStart_->empty()) { // the next solve's start
    checkpoint.arrays["run gmres warm start rhs"] = warmStart_->rightHandSides();
    checkpoint.arrays["run gmres warm start solutions"] = warmStart_->solutions();
  }
}

void CapsuleModel2D::load(const io::Checkpoint& checkpoint, const std::string& source)
{
  const double prestress = io::requiredReal(checkpoint, "run cell prestress", source);
  core::require<core::InputError>(
      prestress == cell_.prestress, "The checkpoint ", source, " was written with Cell/Prestress = ", prestress,
      " but the deck has ", cell_.prestress, ": the membrane's reference would change; restart with the run's deck.");
  const auto* waveform = io::optionalArray(checkpoint, "run shear rate waveform");
  core::require<core::InputError>(waveform ? *waveform == flow_.shearRate.waveformSamples()
                                           : flow_.shearRate.waveformSamples().empty(),
                                  "The checkpoint ", source,
                                  " was written with another waveform than 'Flow/Shear rate/Waveform file' holds "
                                  "now: restart with the run's waveform file.");
  const auto* rhs = io::optionalArray(checkpoint, "run gmres warm start rhs");
  const auto* solutions = io::optionalArray(checkpoint, "run gmres warm start solutions");
  if (rhs && solutions) { // the next solve starts where it would have
    restoreGmresWarmStart(*rhs, *solutions);
  }
}

std::vector<double> CapsuleModel2D::initialState() const
{
  return std::vector<double>(referenceNodes_.data(), referenceNodes_.data() + referenceNodes_.size());
}

void CapsuleModel2D::tether(int offset)
{
  const contour::Contour reference(relabelNodes(freeReference_, offset),
                                   optionsFor(contour::Closure::Tethered, cell_.tetherEnds));
  membrane_ = makeMembrane(reference);
  tetherOffset_ = offset;
  if (warmStart_) { // relabelled nodes and a fixed row: the old solutions do not apply
    warmStart_.emplace(warmStart_->depth());
  }
}

void CapsuleModel2D::regridFree(const Eigen::Matrix2Xd& referenceNodes)
{
  core::require<core::InputError>(!tethered() && referenceNodes.cols() == numberOfNodes(),
                                  "CapsuleModel2D::regridFree: ", referenceNodes.cols(), " reference nodes for a ",
                                  tethered() ? "tethered" : "free", " cell of ", numberOfNodes());
  membrane_ = makeMembrane(contour::Contour(referenceNodes));
  freeReference_ = referenceNodes;
  freeRegridded_ = true;
  if (warmStart_) { // new markers: the old solutions do not apply
    warmStart_.emplace(warmStart_->depth());
  }
}

void CapsuleModel2D::tether(const Eigen::Matrix2Xd& referenceNodes)
{
  core::require<core::InputError>(referenceNodes.cols() == numberOfNodes(),
                                  "CapsuleModel2D::tether: ", referenceNodes.cols(), " reference nodes for a cell of ",
                                  numberOfNodes());
  const contour::Contour reference(referenceNodes, optionsFor(contour::Closure::Tethered, cell_.tetherEnds));
  membrane_ = makeMembrane(reference);
  tetherOffset_ = 0;
  regriddedReference_ = referenceNodes;
  if (warmStart_) { // new markers and a fixed row: the old solutions do not apply
    warmStart_.emplace(warmStart_->depth());
  }
}

contour::Contour CapsuleModel2D::contour(const std::vector<double>& state) const
{
  core::require(state.size() == 2 * static_cast<std::size_t>(numberOfNodes()), "CapsuleModel2D: the state has ",
                state.size(), " entries, expected ", 2 * numberOfNodes());
  Eigen::Matrix2Xd nodes = Eigen::Map<const Eigen::Matrix2Xd>(state.data(), 2, numberOfNodes());
  return contour::Contour(
      std::move(nodes),
      optionsFor(tethered() ? contour::Closure::Tethered : contour::Closure::Periodic, cell_.tetherEnds));
}

MembraneState2D CapsuleModel2D::membrane(const contour::Contour& contour) const
{
  return membrane_->evaluate(contour);
}

FlowConditions2D CapsuleModel2D::flowAt(double t) const
{
  FlowConditions2D conditions = flow_.conditions;
  conditions.background = LinearFlow2D::simpleShear(flow_.shearRate.factor(t));
  return conditions;
}

VelocitySolution2D CapsuleModel2D::velocities(double t, const contour::Contour& contour,
                                              const MembraneState2D& membrane)
{
  const ContourLoad2D load = [&membrane](const contour::ContourPoint& point, int segment, double s) {
    return membrane.loadAt(point, segment, s);
  };
  const std::vector<int> fixed = tethered() ? std::vector<int>{0} : std::vector<int>{};
  VelocitySolution2D solution =
      velocity_->nodeVelocities(contour, load, flowAt(t), fixed, warmStart_ ? &*warmStart_ : nullptr);
  lastIterations_ = solution.iterations;
  return solution;
}

void CapsuleModel2D::rightHandSide(double t, const std::vector<double>& state, std::vector<double>& derivative)
{
  // The cost of one evaluation, broken down (the app prints the timers at the end;
  // the single layer's own parts are timed in scene2d/LayerPotentials2D.hpp).
  static const Teuchos::RCP<Teuchos::Time> total = core::timer("2D right-hand side");
  static const Teuchos::RCP<Teuchos::Time> splines = core::timer("2D right-hand side: contour splines");
  static const Teuchos::RCP<Teuchos::Time> loads = core::timer("2D right-hand side: membrane load");
  static const Teuchos::RCP<Teuchos::Time> velocity = core::timer("2D right-hand side: boundary-integral velocity");
  Teuchos::TimeMonitor totalGuard(*total);
  std::optional<contour::Contour> current;
  {
    Teuchos::TimeMonitor guard(*splines);
    current.emplace(contour(state));
  }
  std::optional<MembraneState2D> load;
  {
    Teuchos::TimeMonitor guard(*loads);
    load.emplace(membrane(*current));
  }
  Teuchos::TimeMonitor guard(*velocity);
  derivative = velocities(t, *current, *load).velocities;
}

} // namespace capsula::scene2d
