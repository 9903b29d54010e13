#include "capsula/core/MpiSessionDirectory.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <vector>

namespace capsula::core {

bool needsPrivateMpiSessionDirectory(const EnvironmentLookup& environment)
{
  // Set by mpiexec (Open MPI), by PMIx launchers (srun, prterun) and by PMI-1/2 launchers.
  for (const char* launcherVariable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"}) {
    if (environment(launcherVariable) != nullptr) {
      return false;
    }
  }
  return environment("OMPI_MCA_orte_tmpdir_base") == nullptr;
}

MpiSessionDirectory::MpiSessionDirectory()
{
  if (!needsPrivateMpiSessionDirectory([](const char* name) { return std::getenv(name); })) {
    return;
  }
  std::error_code error;
  const std::filesystem::path base = std::filesystem::temp_directory_path(error);
  if (error) {
    return;
  }
  std::string pattern = (base / "capsula-mpi-XXXXXX").string();
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  if (mkdtemp(buffer.data()) == nullptr) {
    return;
  }
  path_ = buffer.data();
  setenv("OMPI_MCA_orte_tmpdir_base", path_.c_str(), 1);
}

MpiSessionDirectory::~MpiSessionDirectory()
{
  remove();
}

void MpiSessionDirectory::remove()
{
  if (!path_.empty()) {
    std::error_code ignored; // a directory that cannot be removed costs nothing to the run
    std::filesystem::remove_all(path_, ignored);
    path_.clear();
  }
}

} // namespace capsula::core
