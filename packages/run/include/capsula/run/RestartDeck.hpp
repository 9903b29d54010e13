#pragma once
// A restart continues the run its checkpoint was written by: the deck must describe the
// same run. Only 'Time integration/End time' (where to stop) and 'Output/Directory'
// (where to write) may change.
#include <capsula/io/Checkpoint.hpp>

#include <Teuchos_ParameterList.hpp>

#include <string>

namespace capsula::run {

/// Throws core::InputError naming the checkpoint and the first key whose value differs
/// (or that only one deck has) between `current` and the deck stored in the checkpoint.
void requireSameRun(const Teuchos::ParameterList& current, const std::string& checkpointDeckXml,
                    const std::string& checkpointPath);

/// Throws core::InputError naming the checkpoint and both apps if `checkpoint` was written
/// by another application than `application` (a checkpoint that does not record its
/// application passes).
void requireSameApplication(const io::Checkpoint& checkpoint, const std::string& application,
                            const std::string& checkpointPath);

} // namespace capsula::run
