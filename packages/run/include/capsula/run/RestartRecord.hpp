#pragma once
// A restart continues the record a run left in its directory (metrics.csv and the like): a
// table that is missing, or holds another number of rows up to the checkpoint than the run
// wrote, is a damaged directory, refused as bad input before anything is written.
#include <cstdint>
#include <string>

namespace capsula::run {

/// Throws core::InputError naming `directory`/`file` if the table is missing or unreadable, or
/// if its rows at or before `checkpointTime` are not `rowsWritten` (the outputs the checkpoint
/// counts).
void requireTableUpToCheckpoint(const std::string& directory, const std::string& file, double checkpointTime,
                                std::int64_t rowsWritten);

} // namespace capsula::run
