#pragma once

#include <functional>
#include <string>

namespace capsula::core {

/// Looks up an environment variable; returns nullptr when it is not set.
using EnvironmentLookup = std::function<const char*(const char*)>;

/// Whether a process should give Open MPI a session directory of its own: true for a
/// singleton (a process started without mpiexec or another launcher) whose user has not
/// chosen the session directory (OMPI_MCA_orte_tmpdir_base) themselves.
bool needsPrivateMpiSessionDirectory(const EnvironmentLookup& environment);

/// A private Open MPI session directory for a singleton process.
///
/// Open MPI 4.1 keeps one session directory per user and host under the temporary folder.
/// A singleton that ends removes that shared directory when it looks empty; a singleton
/// starting at the same moment can then fail to create its own entry inside it, and
/// MPI_Init aborts with "A call to mkdir was unable to create the desired directory".
/// Several runs started side by side (a parameter sweep, a parallel test suite) hit this at
/// random. Constructed before MPI_Init, this object points OMPI_MCA_orte_tmpdir_base at a
/// fresh directory of this process's own (inherited by the daemon Open MPI forks for a
/// singleton) and removes it on destruction, after MPI_Finalize. Processes started by a
/// launcher share the launcher's directory and are left alone.
class MpiSessionDirectory final {
public:
  MpiSessionDirectory();
  ~MpiSessionDirectory();
  MpiSessionDirectory(const MpiSessionDirectory&) = delete;
  MpiSessionDirectory& operator=(const MpiSessionDirectory&) = delete;

  /// The private directory, empty when the process did not need one (or the temporary
  /// folder was not writable, in which case Open MPI's default is kept).
  const std::string& path() const { return path_; }

  /// Removes the directory now, for a process that leaves without MPI_Finalize (and so
  /// without running this object's destructor).
  void remove();

private:
  std::string path_;
};

} // namespace capsula::core
