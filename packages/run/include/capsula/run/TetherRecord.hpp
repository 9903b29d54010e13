#pragma once
// What a scene run records of its tether (adhesion/Tether.hpp) beyond the metrics rows: the
// largest tether force over every accepted step, not only at the outputs, and when it
// happened; the force at the last two outputs, for how steady it is at the end. An observer
// of the time loop (after every step and at every output) and a checkpoint section
// ("tether.peak", "tether.outputs"), so that a restarted run reports the peak of the whole
// run. A scene without a tether records nothing and writes nothing.
//
// summary.json, "tether": the cell, anchor, rest length and spring constant; "peak force"
// |F|_max (G a) and "peak force / Ca" (the same in mu k a^2, a the cell radius, k the mean
// shear rate), "time of peak force"; "final force" (G a, and / Ca) and "final force change
// rate", (|F|(t_n) - |F|(t_n-1)) / ((t_n - t_n-1) |F|(t_n)) over the last two outputs (per
// unit k t); with a steady end, "steady force" (G a, and / Ca).
#include "capsula/run/RunScene.hpp"

#include <capsula/io/CheckpointSection.hpp>
#include <capsula/io/Json.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

#include <string>
#include <vector>

namespace capsula::run {

class TetherRecord final : public timeint::IntegrationObserver, public io::CheckpointSection {
public:
  /// For the scene `live` runs, at capillary number `capillaryNumber`.
  TetherRecord(const RunScene& live, double capillaryNumber);

  timeint::ObserverVerdict afterStep(timeint::IntegrationState& state, const timeint::StepReport& report,
                                     bool atOutputTime) override;
  timeint::ObserverVerdict atOutput(const timeint::IntegrationState& state, timeint::OutputReason reason) override;

  double peakForce() const { return peakForce_; }
  double peakTime() const { return peakTime_; }
  /// Adds "tether" to `summary` (nothing without a tether); `steady`: the run ended steady.
  void addResults(io::JsonValue& summary, bool steady) const;

  void save(io::Checkpoint& checkpoint) const override;
  void load(const io::Checkpoint& checkpoint, const std::string& source) override;

private:
  double forceAt(const std::vector<double>& y) const;
  void consider(double t, double force);

  const RunScene& live_;
  double capillaryNumber_;
  double peakForce_ = -1.0; // none yet
  double peakTime_ = 0.0;
  std::vector<double> outputs_; // (t, |F|) of the last two outputs
};

} // namespace capsula::run
