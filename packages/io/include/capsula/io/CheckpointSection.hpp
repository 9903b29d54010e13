#pragma once
// A part of a run that goes into its checkpoint: each stateful part (the integration state,
// the scene or model, the tether procedure, the output bookkeeping) saves and loads its own
// entries, under names of its own, instead of one writer knowing them all. A run lists its
// sections once and hands the list to saveSections / loadSections.
//
// The entries of one section must not clash with another's: each prefixes its names
// ("timeint.", "scene.", "metrics.", "run ...").
#include "capsula/io/Checkpoint.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace capsula::io {

class CheckpointSection {
public:
  virtual ~CheckpointSection() = default;
  /// Adds this part's entries to `checkpoint`.
  virtual void save(Checkpoint& checkpoint) const = 0;
  /// Restores this part from `checkpoint` (read from `source`, for messages). Throws
  /// core::InputError naming the source and the entry if one is missing or does not fit.
  virtual void load(const Checkpoint& checkpoint, const std::string& source) = 0;
};

/// Every section's entries, in order.
void saveSections(Checkpoint& checkpoint, const std::vector<const CheckpointSection*>& sections);
/// Every section restored, in order (a later section may rely on an earlier one).
void loadSections(const Checkpoint& checkpoint, const std::string& source,
                  const std::vector<CheckpointSection*>& sections);

/// The entry `name`; throws core::InputError naming `source` and the entry if it is
/// missing (a checkpoint written by another application or an older version).
double requiredReal(const Checkpoint& checkpoint, const std::string& name, const std::string& source);
std::int64_t requiredInteger(const Checkpoint& checkpoint, const std::string& name, const std::string& source);
const std::vector<double>& requiredArray(const Checkpoint& checkpoint, const std::string& name,
                                         const std::string& source);
/// The entry `name`, or null if the checkpoint has none.
const std::vector<double>* optionalArray(const Checkpoint& checkpoint, const std::string& name);

} // namespace capsula::io
