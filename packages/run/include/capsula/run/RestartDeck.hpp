#pragma once
// A restart continues the run its checkpoint was written by: the checkpoint must be the
// same application's, and the deck must describe the same run. Only 'Time
// integration/End time' (where to stop) and 'Output/Directory' (where to write) may
// change. Every app reads its checkpoint through readRestartCheckpoint, before it touches
// the output directory, so a refused restart leaves the directory byte for byte.
#include <capsula/io/Checkpoint.hpp>

#include <Teuchos_ParameterList.hpp>

#include <string>

namespace capsula::run {

/// `directory`/checkpoint.h5, the file a run writes and a restart continues.
std::string checkpointPath(const std::string& directory);

/// Reads `restartDirectory`/checkpoint.h5 and checks that a run of `application` with
/// `validatedDeck` continues it (requireSameApplication, requireSameRun). Throws
/// core::InputError naming the directory (an unreadable checkpoint) or the key that differs.
/// Collective in effect: every rank reads the (small) checkpoint and takes the same decision.
io::Checkpoint readRestartCheckpoint(const std::string& restartDirectory, const std::string& application,
                                     const Teuchos::ParameterList& validatedDeck);

/// Throws core::InputError naming the checkpoint, the first key whose value differs (or
/// that only one deck has) between `current` and the deck stored in the checkpoint, and
/// both values ("the run was written with KEY = 0.25 but the deck has 0.05").
void requireSameRun(const Teuchos::ParameterList& current, const std::string& checkpointDeckXml,
                    const std::string& checkpointPath);

/// Throws core::InputError naming the checkpoint and both apps if `checkpoint` was written
/// by another application than `application` (a checkpoint that does not record its
/// application passes).
void requireSameApplication(const io::Checkpoint& checkpoint, const std::string& application,
                            const std::string& checkpointPath);

} // namespace capsula::run
