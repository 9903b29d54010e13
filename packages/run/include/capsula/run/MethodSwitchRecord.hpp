#pragma once
// Method Auto's switches between its explicit and stiff methods (time and reason), for
// summary.json's "time integration/switches": a checkpoint section, so that a restarted
// run's summary lists the switches before the checkpoint as the uninterrupted run's does.
#include <capsula/io/CheckpointSection.hpp>

#include <string>
#include <utility>
#include <vector>

namespace capsula::run {

class MethodSwitchRecord final : public io::CheckpointSection {
public:
  using Switch = std::pair<double, std::string>; ///< time, reason

  void add(double time, std::string reason) { switches_.emplace_back(time, std::move(reason)); }
  const std::vector<Switch>& switches() const { return switches_; }

  /// "run.methodSwitches.times" and, the checkpoint holding numbers only, the reasons as
  /// their character codes, each ended by a 0, in "run.methodSwitches.reasons". A run
  /// without switches saves nothing.
  void save(io::Checkpoint& checkpoint) const override;
  /// The switches saved, or none where the checkpoint has no entries.
  void load(const io::Checkpoint& checkpoint, const std::string& source) override;

private:
  std::vector<Switch> switches_;
};

} // namespace capsula::run
