#pragma once
// A run's output directory and the record of what produced it:
//
//   <dir>/deck.xml   the validated deck with every default filled in (readDeck reads it
//                    back, so a run can be repeated exactly)
//   <dir>/run.json   application, deck source, Capsula version, git SHA, Trilinos
//                    version, number of ranks, start time (UTC)
//
// Serial: call from one rank.
#include <Teuchos_ParameterList.hpp>

#include <string>

namespace capsula::io {

struct RunMetadata {
  std::string application; ///< e.g. "cell3d"
  std::string deckSource;  ///< the deck file the run was started from
  int ranks = 1;
};

class OutputDirectory {
public:
  /// Creates the directory if needed; throws core::IoError naming it if it cannot be
  /// created or written.
  explicit OutputDirectory(std::string path);

  const std::string& path() const { return path_; }
  /// `name` inside the directory.
  std::string file(const std::string& name) const;

  /// Writes deck.xml and run.json atomically.
  void writeRunMetadata(const Teuchos::ParameterList& validatedDeck, const RunMetadata& run) const;

private:
  std::string path_;
};

} // namespace capsula::io
