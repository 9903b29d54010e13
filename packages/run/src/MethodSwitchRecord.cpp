#include "capsula/run/MethodSwitchRecord.hpp"

#include <capsula/core/Error.hpp>

namespace capsula::run {

namespace {

const char* const timesEntry = "run.methodSwitches.times";
const char* const reasonsEntry = "run.methodSwitches.reasons";

} // namespace

void MethodSwitchRecord::save(io::Checkpoint& checkpoint) const
{
  if (switches_.empty()) {
    return;
  }
  std::vector<double> times, reasons;
  for (const auto& [time, reason] : switches_) {
    times.push_back(time);
    for (const char c : reason) {
      reasons.push_back(static_cast<double>(static_cast<unsigned char>(c)));
    }
    reasons.push_back(0.0);
  }
  checkpoint.arrays[timesEntry] = std::move(times);
  checkpoint.arrays[reasonsEntry] = std::move(reasons);
}

void MethodSwitchRecord::load(const io::Checkpoint& checkpoint, const std::string& source)
{
  switches_.clear();
  const std::vector<double>* times = io::optionalArray(checkpoint, timesEntry);
  const std::vector<double>* reasons = io::optionalArray(checkpoint, reasonsEntry);
  if (times == nullptr && reasons == nullptr) {
    return;
  }
  core::require<core::InputError>(times != nullptr && reasons != nullptr, "The checkpoint '", source,
                                  "' holds only one of '", timesEntry, "' and '", reasonsEntry, "'.");
  std::string reason;
  std::size_t next = 0;
  for (const double code : *reasons) {
    if (code != 0.0) {
      reason.push_back(static_cast<char>(static_cast<unsigned char>(code)));
      continue;
    }
    core::require<core::InputError>(next < times->size(), "The checkpoint '", source, "' holds more reasons in '",
                                    reasonsEntry, "' than times in '", timesEntry, "'.");
    switches_.emplace_back((*times)[next++], reason);
    reason.clear();
  }
  core::require<core::InputError>(next == times->size() && reason.empty(), "The checkpoint '", source, "' holds ",
                                  times->size(), " switch times in '", timesEntry, "' but ", next, " reasons.");
}

} // namespace capsula::run
