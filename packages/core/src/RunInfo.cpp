#include "capsula/core/RunInfo.hpp"

#include <Trilinos_version.h>

namespace capsula::core {
namespace generated {
// Defined in the file cmake/WriteVersion.cmake generates at build time.
const char* gitSha();
const char* capsulaVersion();
} // namespace generated

std::string gitSha()
{
  return generated::gitSha();
}
std::string capsulaVersion()
{
  return generated::capsulaVersion();
}
std::string trilinosVersion()
{
  return TRILINOS_VERSION_STRING;
}

std::string versionLine()
{
  return "Capsula " + capsulaVersion() + " (git " + gitSha() + ", Trilinos " + trilinosVersion() + ")";
}

} // namespace capsula::core
