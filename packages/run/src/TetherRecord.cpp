#include "capsula/run/TetherRecord.hpp"

#include <capsula/core/Error.hpp>

namespace capsula::run {

namespace core = capsula::core;

TetherRecord::TetherRecord(const RunScene& live, double capillaryNumber)
    : live_(live), capillaryNumber_(capillaryNumber)
{}

double TetherRecord::forceAt(const std::vector<double>& y) const
{
  const scene::Scene& scene = live_.scene();
  const int c = scene.tether().cell();
  const double* x = y.data() + 3 * static_cast<std::size_t>(scene.nodeOffset(c));
  return scene.tether().state(scene.cell(c), x).force.norm();
}

void TetherRecord::consider(double t, double force)
{
  if (force > peakForce_) {
    peakForce_ = force;
    peakTime_ = t;
  }
}

timeint::ObserverVerdict TetherRecord::afterStep(timeint::IntegrationState& state, const timeint::StepReport&, bool)
{
  if (live_.scene().hasTether()) {
    consider(state.time, forceAt(state.y));
  }
  return timeint::ObserverVerdict::Continue;
}

timeint::ObserverVerdict TetherRecord::atOutput(const timeint::IntegrationState& state, timeint::OutputReason)
{
  if (!live_.scene().hasTether()) {
    return timeint::ObserverVerdict::Continue;
  }
  const double force = forceAt(state.y);
  consider(state.time, force); // the start, which no step precedes
  if (outputs_.size() == 4) {
    outputs_.erase(outputs_.begin(), outputs_.begin() + 2);
  }
  outputs_.insert(outputs_.end(), {state.time, force});
  return timeint::ObserverVerdict::Continue;
}

void TetherRecord::addResults(io::JsonValue& summary, bool steady) const
{
  const scene::Scene& scene = live_.scene();
  if (!scene.hasTether() || outputs_.empty()) {
    return;
  }
  const adhesion::Tether& tether = scene.tether();
  io::JsonValue& t = summary["tether"];
  t["cell"] = scene.description().cells[static_cast<std::size_t>(tether.cell())].path;
  t["anchor"] = io::JsonValue::array({tether.anchor()[0], tether.anchor()[1], tether.anchor()[2]});
  t["rest length"] = tether.restLength();
  t["spring constant"] = tether.settings().springConstant;
  t["patch points"] = tether.points().size();
  t["peak force"] = peakForce_;
  t["peak force / Ca"] = peakForce_ / capillaryNumber_;
  t["time of peak force"] = peakTime_;
  const double last = outputs_[outputs_.size() - 1];
  t["final force"] = last;
  t["final force / Ca"] = last / capillaryNumber_;
  if (outputs_.size() == 4 && last > 0.0) {
    t["final force change rate"] = (last - outputs_[1]) / ((outputs_[2] - outputs_[0]) * last);
  }
  if (steady) {
    t["steady force"] = last;
    t["steady force / Ca"] = last / capillaryNumber_;
  }
}

void TetherRecord::save(io::Checkpoint& checkpoint) const
{
  if (live_.scene().hasTether()) {
    checkpoint.arrays["tether.peak"] = {peakForce_, peakTime_};
    checkpoint.arrays["tether.outputs"] = outputs_;
  }
}

void TetherRecord::load(const io::Checkpoint& checkpoint, const std::string& source)
{
  if (!live_.scene().hasTether()) {
    return;
  }
  const std::vector<double>& peak = io::requiredArray(checkpoint, "tether.peak", source);
  core::require<core::InputError>(peak.size() == 2, "The checkpoint '", source,
                                  "' has a malformed 'tether.peak': it is damaged.");
  peakForce_ = peak[0];
  peakTime_ = peak[1];
  outputs_ = io::requiredArray(checkpoint, "tether.outputs", source);
}

} // namespace capsula::run
