#include "capsula/run/IntegrationStateSection.hpp"

namespace capsula::run {

namespace {

template <typename Map>
void copyPrefixed(const Map& from, Map& to, const std::string& prefix)
{
  for (const auto& [name, value] : from) {
    to[prefix + name] = value;
  }
}

template <typename Map>
void copyUnprefixed(const Map& from, Map& to, const std::string& prefix)
{
  for (const auto& [name, value] : from) {
    if (name.compare(0, prefix.size(), prefix) == 0) {
      to[name.substr(prefix.size())] = value;
    }
  }
}

} // namespace

void IntegrationStateSection::save(io::Checkpoint& checkpoint) const
{
  const timeint::StateRecord record = timeint::toRecord(state_);
  copyPrefixed(record.reals, checkpoint.reals, prefix_);
  copyPrefixed(record.integers, checkpoint.integers, prefix_);
  copyPrefixed(record.arrays, checkpoint.arrays, prefix_);
}

void IntegrationStateSection::load(const io::Checkpoint& checkpoint, const std::string& source)
{
  timeint::StateRecord record;
  copyUnprefixed(checkpoint.reals, record.reals, prefix_);
  copyUnprefixed(checkpoint.integers, record.integers, prefix_);
  copyUnprefixed(checkpoint.arrays, record.arrays, prefix_);
  state_ = timeint::fromRecord(record, source);
}

} // namespace capsula::run
