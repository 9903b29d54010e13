#include "capsula/scene2d/TetherStages2D.hpp"

#include "capsula/scene2d/TetherRegrid2D.hpp"

#include <capsula/contour/ContourMetrics.hpp>
#include <capsula/core/Error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

namespace capsula::scene2d {

TetherStages2D::TetherStages2D(CapsuleModel2D& model, const TetherSettings2D& tether,
                               const timeint::TimeIntegrator& integrator, timeint::IntegrationState& state,
                               std::ostream* log)
    : model_(model),
      tether_(tether),
      integrator_(integrator),
      state_(state),
      log_(log),
      lambda_(model.flow().conditions.viscosityRatio)
{}

timeint::OutputSchedule TetherStages2D::schedule(double interval, double endTau) const
{
  const double stageEnd = preparing() ? tether_.maximumPreparationTime : endTau;
  const double origin = origin_, lambda = lambda_;
  timeint::OutputSchedule schedule;
  schedule.interval = interval;
  schedule.endTime = origin + lambda * stageEnd;
  // Output k at k * interval of tau; one within a hair of the stage's end is the end (no sliver).
  schedule.times = [origin, lambda, interval, stageEnd](std::int64_t k) {
    double tauOut = static_cast<double>(k) * interval;
    if (tauOut >= stageEnd - 1e-9 * interval) {
      tauOut = stageEnd;
    }
    return origin + lambda * tauOut;
  };
  return schedule;
}

void TetherStages2D::begin(TetherStage stage)
{
  stage_ = stage;
  origin_ = state_.time;
  if (stage != TetherStage::Tethered) {
    previousD12_ = contour::taylorDeformation(model_.contour(state_.y));
  }
}

void TetherStages2D::restartWith(const double* y, std::size_t n, bool newStage)
{
  timeint::IntegrationState fresh = integrator_.start(state_.time, std::vector<double>(y, y + n));
  fresh.proposedStep = state_.proposedStep;
  fresh.statistics = state_.statistics;
  // The stiff methods: Auto's choice and its trials carry over (the membrane is the same).
  fresh.stiffActive = state_.stiffActive;
  fresh.stiffTrialsFailed = state_.stiffTrialsFailed;
  if (!newStage) { // the stage's outputs go on
    fresh.outputOrigin = state_.outputOrigin;
    fresh.nextOutput = state_.nextOutput;
  }
  state_ = std::move(fresh);
}

double TetherStages2D::nextEvent(const timeint::IntegrationState& state)
{
  if (!preparing()) {
    return std::numeric_limits<double>::infinity();
  }
  // The preparation lands on its check times (multiples of the window), on the predicted
  // end, and while placing on the predicted passage of a node through the bottom.
  const double stageEnd = tether_.maximumPreparationTime;
  const double nextCheckTau = placing_ ? stageEnd
                              : preparationEnd_ > 0.0
                                  ? std::min(preparationEnd_, stageEnd)
                                  : std::min(nextPreparationCheck(tether_, tau(state.time)), stageEnd);
  checkTime_ = origin_ + lambda_ * nextCheckTau;
  placementTime_ = placing_ && placeTarget_ > state.time ? placeTarget_ : checkTime_;
  return std::min(checkTime_, placementTime_);
}

// Waiting for a node at the bottom: done when the step landed on the predicted passage or
// the lowest node's tangent turned (TetherProcedure2D.hpp).
bool TetherStages2D::placementDone(const timeint::IntegrationState& state)
{
  const LowestNodeSlope lowest = lowestNodeSlope(model_.contour(state.y));
  const bool sameNode = lowest.node == placeNode_;
  bool done = false;
  if (state.time == placementTime_ || (sameNode && lowest.slope * placeSlope_ <= 0.0)) {
    done = true;
  } else {
    placeTarget_ = sameNode ? predictedZeroCrossing(placeTime_, placeSlope_, state.time, lowest.slope) : -1.0;
  }
  placeNode_ = lowest.node;
  placeSlope_ = lowest.slope;
  placeTime_ = state.time;
  return done;
}

// At a check time: d D12 / d tau over the window since the last check, and whether the
// shape has settled (TetherProcedure2D.hpp).
bool TetherStages2D::windowCheckSettles(double tau)
{
  const double d12 = contour::taylorDeformation(model_.contour(state_.y));
  const double previousRate = preparationRate_;
  preparationRate_ = (d12 - previousD12_) / tether_.preparationWindow;
  previousD12_ = d12;
  if (tau < tether_.minimumPreparationTime) {
    return false;
  }
  bool settled = preparationComplete(tether_, tau, preparationRate_);
  const double end = predictedPreparationEnd(tether_, tau, previousRate, preparationRate_);
  if (!settled && end > tau) {
    preparationEnd_ = end;
  } else if (!settled && end > 0.0) {
    settled = true; // the extrapolated crossing lies inside the last window: now
  }
  return settled;
}

// New markers graded towards the free cell's lowest point (TetherRegrid2D.hpp).
void TetherStages2D::regridFreeCell(double tau)
{
  const TetherRegrid2D regrid = regridTowardsLowestPoint(contour::Contour(model_.freeReferenceNodes()),
                                                         model_.contour(state_.y), tether_.grading);
  model_.regridFree(regrid.referenceNodes);
  restartWith(regrid.currentNodes.data(), static_cast<std::size_t>(regrid.currentNodes.size()), false);
  const double interval = tether_.preparationRegridInterval;
  nextRegrid_ = (std::floor(tau / interval + 1e-9) + 1.0) * interval;
}

// The shape has settled: wait for a node at the bottom; done at once if one is there.
bool TetherStages2D::startPlacement()
{
  const LowestNodeSlope lowest = lowestNodeSlope(model_.contour(state_.y));
  placing_ = true;
  placeNode_ = lowest.node;
  placeSlope_ = lowest.slope;
  placeTime_ = state_.time;
  placeTarget_ = -1.0;
  return lowest.slope == 0.0;
}

timeint::ObserverVerdict TetherStages2D::afterStep(timeint::IntegrationState& state, const timeint::StepReport& report,
                                                   bool atOutputTime)
{
  if (!preparing()) {
    return timeint::ObserverVerdict::Continue;
  }
  lastStepSize_ = report.stepSize;
  stoppedAtOutputTime_ = atOutputTime;
  state.steady = false; // the steady-state criterion applies to the tethered (or free) stage
  const double tau = this->tau(state.time);
  bool done = tau >= tether_.maximumPreparationTime * (1.0 - 1e-12);
  bool settled = false; // the shape criterion holds: wait for a node at the bottom
  if (placing_) {
    done = placementDone(state) || done;
  } else if (state.time == checkTime_ && preparationEnd_ > 0.0) {
    settled = true; // landed on the predicted end (TetherProcedure2D.hpp)
  } else if (state.time == checkTime_) {
    settled = windowCheckSettles(tau);
  }
  if (!done && !settled && state.time == checkTime_ && tether_.preparationRegridInterval > 0.0 &&
      tau >= nextRegrid_ * (1.0 - 1e-12)) {
    regridFreeCell(tau);
  }
  if (settled && !done) {
    done = !tether_.waitForNodeAtBottom || startPlacement();
  }
  return done ? timeint::ObserverVerdict::Stop : timeint::ObserverVerdict::Continue;
}

void TetherStages2D::tether()
{
  // Tether (thesis Section 4.1): lowest node to the anchor, relabelled node 0.
  const int n = model_.numberOfNodes();
  const Eigen::Map<const Eigen::Matrix2Xd> nodes(state_.y.data(), 2, n);
  const Eigen::Vector2d anchor(0.0, tether_.anchorHeight);
  const TetherPlacement2D placement = tetherPlacement(nodes, anchor);
  Eigen::Matrix2Xd tethered;
  preparationTime_ = tau(state_.time);
  if (tether_.regrid) { // new markers graded towards the lowest point (TetherRegrid2D.hpp)
    const TetherRegrid2D regrid = regridAtTether(contour::Contour(model_.freeReferenceNodes()),
                                                 model_.contour(state_.y), tether_.grading, anchor);
    tethered = regrid.currentNodes;
    model_.tether(regrid.referenceNodes);
  } else {
    tethered = tetheredNodes(nodes, placement);
    model_.tether(placement.lowestNode);
  }
  restartWith(tethered.data(), static_cast<std::size_t>(tethered.size()), true);
  if (log_ != nullptr) {
    if (tether_.regrid) {
      *log_ << "Tethered at tau = " << preparationTime_ << " (the lowest point of the spline, moved to (0, "
            << tether_.anchorHeight << "), with " << n << " new markers graded towards it)\n";
    } else {
      *log_ << "Tethered at tau = " << preparationTime_ << " (node " << placement.lowestNode
            << " of the free cell moved by (" << placement.shift.x() << ", " << placement.shift.y() << ") to (0, "
            << tether_.anchorHeight << "))\n";
    }
  }
  begin(TetherStage::Tethered);
}

void TetherStages2D::save(io::Checkpoint& checkpoint) const
{
  checkpoint.integers["run stage"] = static_cast<std::int64_t>(stage_);
  checkpoint.reals["run origin"] = origin_;
  checkpoint.reals["run previous D12"] = previousD12_;
  checkpoint.reals["run preparation rate"] = preparationRate_;
  checkpoint.reals["run preparation end"] = preparationEnd_;
  checkpoint.integers["run placing"] = placing_ ? 1 : 0;
  checkpoint.integers["run place node"] = placeNode_;
  checkpoint.reals["run place slope"] = placeSlope_;
  checkpoint.reals["run place time"] = placeTime_;
  checkpoint.reals["run place target"] = placeTarget_;
  checkpoint.reals["run next regrid"] = nextRegrid_;
  checkpoint.reals["run preparation time"] = preparationTime_;
  checkpoint.integers["run tether offset"] = model_.tetherOffset();
  if (model_.freeCellRegridded()) {
    const Eigen::Matrix2Xd& free = model_.freeReferenceNodes();
    checkpoint.arrays["run free reference nodes"] = std::vector<double>(free.data(), free.data() + free.size());
  }
  if (const Eigen::Matrix2Xd& regridded = model_.regriddedReference(); regridded.size() > 0) {
    checkpoint.arrays["run regridded reference nodes"] =
        std::vector<double>(regridded.data(), regridded.data() + regridded.size());
  }
}

void TetherStages2D::load(const io::Checkpoint& checkpoint, const std::string& source)
{
  const int n = model_.numberOfNodes();
  core::require<core::InputError>(state_.y.size() == 2 * static_cast<std::size_t>(n), "The checkpoint ", source,
                                  " holds ", state_.y.size() / 2,
                                  " nodes but the deck asks for Cell/Number of points = ", n, ".");
  const auto integer = [&](const char* name) { return io::requiredInteger(checkpoint, name, source); };
  const auto real = [&](const char* name) { return io::requiredReal(checkpoint, name, source); };
  stage_ = static_cast<TetherStage>(integer("run stage"));
  origin_ = real("run origin");
  previousD12_ = real("run previous D12");
  preparationRate_ = real("run preparation rate");
  preparationEnd_ = real("run preparation end");
  placing_ = integer("run placing") != 0;
  if (placing_) {
    placeNode_ = static_cast<int>(integer("run place node"));
    placeSlope_ = real("run place slope");
    placeTime_ = real("run place time");
    placeTarget_ = real("run place target");
  }
  nextRegrid_ = real("run next regrid");
  preparationTime_ = real("run preparation time");
  const auto nodesOf = [&](const std::vector<double>& values, const char* what) {
    core::require<core::InputError>(values.size() == 2 * static_cast<std::size_t>(n), "The checkpoint ", source,
                                    " holds ", values.size() / 2, " ", what, " for ", n, " nodes.");
    return Eigen::Map<const Eigen::Matrix2Xd>(values.data(), 2, n);
  };
  if (const auto* free = io::optionalArray(checkpoint, "run free reference nodes")) {
    model_.regridFree(nodesOf(*free, "free reference nodes"));
  }
  if (stage_ == TetherStage::Tethered) {
    if (const auto* regridded = io::optionalArray(checkpoint, "run regridded reference nodes")) {
      model_.tether(nodesOf(*regridded, "regridded reference nodes"));
    } else {
      model_.tether(static_cast<int>(integer("run tether offset")));
    }
  }
}

} // namespace capsula::scene2d
