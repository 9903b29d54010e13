#pragma once
// Output files are written atomically: to a temporary file in the same
// directory, then renamed over the target, so a run that dies mid-write never
// leaves a truncated file and never destroys the previous good version.
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace capsula::core {

/// Creates `directory` (and parents) if needed and checks that a file can be
/// created in it. Throws IoError naming the directory and the reason.
void ensureWritableDirectory(const std::string& directory);

/// Writes `path` atomically with the content `write` streams out. Throws IoError
/// (the previous file, if any, is left untouched).
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

/// Renames a finished temporary file over `path` (for writers that produce their
/// own temporary file, such as HDF5). Throws IoError.
void replaceFileAtomically(const std::string& temporaryPath, const std::string& path);

/// A temporary name next to `path`, unique to this process: `path`.tmp.<process id>.
std::string temporaryPathFor(const std::string& path);

/// For a failed write with errno `errorNumber`: if it says the disk (or the quota) is full,
/// the sentence that says so and what to do; otherwise "".
std::string diskFullAdvice(int errorNumber);

/// Replaces the content of the existing file `path` in place with `text` if it fits in the
/// space the file already has (no new blocks are needed, so this works on a full disk).
/// Returns whether it did. For the one file that must say how a run ended when nothing
/// new can be written.
bool overwriteInPlace(const std::string& path, const std::string& text) noexcept;

/// Removes the temporary files (temporaryPathFor) in `directory` of processes that no
/// longer run: what a writer killed mid-write (SIGKILL, a crash) leaves. Those of a live
/// process on this machine are kept. Returns the names removed.
std::vector<std::string> removeStaleTemporaryFiles(const std::string& directory);

} // namespace capsula::core
