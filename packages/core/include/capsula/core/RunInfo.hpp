#pragma once
// What produced a result: recorded in every run's output next to the validated deck.
#include <string>

namespace capsula::core {

/// The git commit the build was made from ("<sha>-dirty" for uncommitted changes,
/// "unknown" outside a git checkout).
std::string gitSha();
/// Capsula's own version (the CMake project version).
std::string capsulaVersion();
/// The Trilinos release the build links against (TRILINOS_VERSION_STRING).
std::string trilinosVersion();
/// One line for logs: "Capsula 0.1.0 (git abc123, Trilinos 13.2)".
std::string versionLine();

} // namespace capsula::core
