#pragma once
// The stages of a tether2d run (thesis Section 4.1; the criteria in
// scene2d/TetherProcedure2D.hpp) as an observer of the time loop:
//
//   Preparation  the free cell deforms; the steps land on the check times of the window
//                rate of D12 (and on the predicted end, and while waiting for a node at
//                the bottom on its predicted passage); with 'Preparation regrid interval'
//                the free cell gets new markers at the checks. It ends (afterStep says
//                Stop) when the rate criterion holds, a node has reached the bottom, or at
//                the maximum preparation time.
//   Tethered     after tether(): the lowest node (or the spline's lowest point, with
//                'Regrid at tethering') moved to the anchor and held there.
//   Free         without a tether, the only stage.
// Each stage has its own time tau = k (t - t0) / lambda from its origin t0, outputs at
// multiples of 'Output/Interval' of tau (schedule()), and its own tables.
//
// Its checkpoint section ("run stage", "run origin", the preparation's window rates and
// placement, "run next regrid", the preparation time, the model's regridded markers and
// tether) rebuilds the model's markers and tether on load; the model's own section (warm
// start) must load after it, since tethering drops the warm start.
#include "capsula/scene2d/CapsuleModel2D.hpp"
#include "capsula/scene2d/TetherProcedure2D.hpp"

#include <capsula/io/CheckpointSection.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

#include <iosfwd>
#include <string>

namespace capsula::scene2d {

enum class TetherStage : int { Preparation = 0, Tethered = 1, Free = 2 };

class TetherStages2D final : public timeint::IntegrationObserver, public io::CheckpointSection {
public:
  TetherStages2D(CapsuleModel2D& model, const TetherSettings2D& tether, const timeint::TimeIntegrator& integrator,
                 timeint::IntegrationState& state, std::ostream* log);

  TetherStage stage() const { return stage_; }
  bool preparing() const { return stage_ == TetherStage::Preparation; }
  /// tau of the current stage at time t.
  double tau(double t) const { return (t - origin_) / lambda_; }
  /// The stage's outputs at origin + lambda tau_k, tau_k = k `interval` (tau_k within 1e-9
  /// intervals of the stage's end is the end), and its end: the maximum preparation time
  /// for the preparation, `endTau` for the others.
  timeint::OutputSchedule schedule(double interval, double endTau) const;

  /// Starts `stage` at the state (its origin).
  void begin(TetherStage stage);
  /// After the preparation stopped: whether its last step landed on an output time, and
  /// that step's size.
  bool stoppedAtOutputTime() const { return stoppedAtOutputTime_; }
  double lastStepSize() const { return lastStepSize_; }
  /// Tethers the cell where the preparation left it and starts the tethered stage.
  void tether();

  bool tethered() const { return stage_ == TetherStage::Tethered; }
  /// tau of the preparation when the cell was tethered.
  double preparationTime() const { return preparationTime_; }
  /// The preparation's last window rate d D12 / d tau.
  double preparationRate() const { return preparationRate_; }

  double nextEvent(const timeint::IntegrationState& state) override;
  timeint::ObserverVerdict afterStep(timeint::IntegrationState& state, const timeint::StepReport& report,
                                     bool atOutputTime) override;

  void save(io::Checkpoint& checkpoint) const override;
  void load(const io::Checkpoint& checkpoint, const std::string& source) override;

private:
  bool placementDone(const timeint::IntegrationState& state);
  bool windowCheckSettles(double tau);
  void regridFreeCell(double tau);
  bool startPlacement();
  /// `y` as the state from now on, as a fresh start would take it (new slopes, PI memory
  /// and stability estimate) but keeping the step proposal and the statistics.
  void restartWith(const double* y, std::size_t n, bool newStage);

  CapsuleModel2D& model_;
  const TetherSettings2D& tether_;
  const timeint::TimeIntegrator& integrator_;
  timeint::IntegrationState& state_;
  std::ostream* log_;
  double lambda_;

  TetherStage stage_ = TetherStage::Free;
  double origin_ = 0.0;          // t0, the start of the current stage in k t
  double previousD12_ = 0.0;     // preparation: D12 at the last check (a multiple of the window)
  double preparationRate_ = 0.0; // preparation: d D12 / d tau over the last window
  double preparationEnd_ = -1.0; // preparation: predicted tau of its end (< 0: none yet)
  bool placing_ = false;         // preparation: shape settled, waiting for a node at the bottom
  int placeNode_ = -1;           // placing: the lowest node after the last step
  double placeSlope_ = 0.0;      // placing: its tangent's y-component then
  double placeTime_ = 0.0;       // placing: k t of that sample
  double placeTarget_ = -1.0;    // placing: predicted k t of the crossing (< 0: none)
  double nextRegrid_ = 0.0;      // preparation: tau of the next regrid of the free cell
  double preparationTime_ = 0.0;
  // The event times of the step under way (nextEvent), which afterStep compares with.
  double checkTime_ = 0.0;
  double placementTime_ = 0.0;
  bool stoppedAtOutputTime_ = false;
  double lastStepSize_ = 0.0;
};

} // namespace capsula::scene2d
