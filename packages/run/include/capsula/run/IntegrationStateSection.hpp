#pragma once
// The integration state's part of a checkpoint: timeint::toRecord / fromRecord under a
// prefix of the run's choosing ("timeint." in the scene runs; none in tether2d's
// checkpoints, whose names predate the prefix).
#include <capsula/io/CheckpointSection.hpp>
#include <capsula/timeint/IntegrationState.hpp>

#include <string>

namespace capsula::run {

class IntegrationStateSection final : public io::CheckpointSection {
public:
  IntegrationStateSection(timeint::IntegrationState& state, std::string prefix)
      : state_(state), prefix_(std::move(prefix))
  {}

  void save(io::Checkpoint& checkpoint) const override;
  void load(const io::Checkpoint& checkpoint, const std::string& source) override;

private:
  timeint::IntegrationState& state_;
  std::string prefix_;
};

} // namespace capsula::run
