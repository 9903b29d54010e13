#pragma once
// Makes an in-place modification of an HDF5 file undoable after a crash: an HDF5 file
// driver (a minimal POSIX driver, like HDF5's default "sec2") that, before it overwrites
// any byte that existed when the file was opened, saves the old bytes to the journal
// <file>.undo and forces them to disk. Bytes past the old end of the file (where HDF5
// puts everything new) are written at once and not journalled. Writes into the old part
// are held in memory (reads see them) until HDF5 flushes or closes the file; then their
// originals are journalled and synced in one go, and only then are they written. A clean
// close forces the file to disk and only then deletes the journal.
//
// So at every instant either the journal holds the original of every byte changed so far
// (the writer may die at any point: undoInterruptedWrite() restores the file exactly as it
// was before the open, and cuts what was appended), or there is no journal and the file
// is complete. The file itself stays a plain HDF5 file (the driver writes no driver
// information into it), so any reader opens it with the default driver.
//
// Journal layout: "CAPUNDO1", the file size at open (uint64); then records: offset,
// length (uint64), the old bytes, an FNV-1a checksum of the three (uint64). A record cut
// short by a crash fails its checksum; its bytes were not yet overwritten (a record is
// synced before the write it protects), so it is ignored.
#include "Hdf5Support.hpp"

#include <string>

namespace capsula::io::hdf5 {

/// "<path>.undo".
std::string undoJournalPathFor(const std::string& path);

/// Opens an existing file for reading and writing through the journalling driver. Call
/// undoInterruptedWrite() first: a journal left by an earlier writer must be applied
/// before the file is opened again. Throws core::IoError naming the file.
Handle openFileWithUndoJournal(const std::string& path, const std::string& role);

/// If a writer died with `path` open (its journal exists), restores the file to its state
/// before that writer opened it and removes the journal; returns whether it did. Throws
/// core::IoError naming the file if it cannot be restored.
bool undoInterruptedWrite(const std::string& path);

/// Removes a journal of `path` without applying it (the file is about to be replaced).
void discardUndoJournal(const std::string& path);

} // namespace capsula::io::hdf5
