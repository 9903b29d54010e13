#include "capsula/run/RestartDeck.hpp"

#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>

namespace capsula::run {

namespace {

// The keys that may change on restart: where to stop and where to write.
void removeRestartFreeKeys(Teuchos::ParameterList& deck)
{
  if (deck.isSublist("Time integration")) {
    deck.sublist("Time integration").remove("End time", false);
  }
  if (deck.isSublist("Output")) {
    deck.sublist("Output").remove("Directory", false);
  }
}

// The first key whose value differs (or that only one list has), "" if none.
std::string firstDifference(const Teuchos::ParameterList& a, const Teuchos::ParameterList& b, const std::string& prefix)
{
  for (auto it = a.begin(); it != a.end(); ++it) {
    const std::string& name = a.name(it);
    const std::string path = prefix.empty() ? name : prefix + "/" + name;
    if (!b.isParameter(name)) {
      return path;
    }
    if (a.isSublist(name) != b.isSublist(name)) {
      return path;
    }
    if (a.isSublist(name)) {
      const std::string inner = firstDifference(a.sublist(name), b.sublist(name), path);
      if (!inner.empty()) {
        return inner;
      }
    } else if (!a.getEntry(name).getAny(false).same(b.getEntry(name).getAny(false))) {
      return path;
    }
  }
  for (auto it = b.begin(); it != b.end(); ++it) {
    if (!a.isParameter(b.name(it))) {
      return prefix.empty() ? b.name(it) : prefix + "/" + b.name(it);
    }
  }
  return "";
}

} // namespace

void requireSameRun(const Teuchos::ParameterList& current, const std::string& checkpointDeckXml,
                    const std::string& checkpointPath)
{
  // Both decks pass through the same XML text, so equal values compare equal.
  auto now = core::readDeckFromString(core::deckToXml(current, false), "the current deck");
  auto then = core::readDeckFromString(checkpointDeckXml, checkpointPath);
  removeRestartFreeKeys(*now);
  removeRestartFreeKeys(*then);
  const std::string key = firstDifference(*then, *now, "");
  core::require<core::InputError>(key.empty(), "Cannot restart from '", checkpointPath,
                                  "': the deck differs from the one the run was ", "started with at '", key,
                                  "'. Only 'Time integration/End time' and 'Output/Directory' may change on ",
                                  "restart (use the deck.xml written next to the checkpoint).");
}

void requireSameApplication(const io::Checkpoint& checkpoint, const std::string& application,
                            const std::string& checkpointPath)
{
  core::require<core::InputError>(checkpoint.application.empty() || checkpoint.application == application,
                                  "Cannot restart from '", checkpointPath, "': it is a checkpoint of ",
                                  checkpoint.application, ", not of ", application, ". Continue it with ",
                                  checkpoint.application, " --restart, or start ", application,
                                  " without --restart (or with the directory of a ", application, " run).");
}

} // namespace capsula::run
