#include "capsula/run/RestartDeck.hpp"

#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>

#include <filesystem>
#include <sstream>

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

// A key that differs between the checkpoint's deck and the current one.
struct DeckDifference {
  std::string path; ///< "" if none
  std::string then, now;
};

std::string valueText(const Teuchos::ParameterList& list, const std::string& name)
{
  if (!list.isParameter(name)) {
    return "(absent)";
  }
  if (list.isSublist(name)) {
    return "(a sublist)";
  }
  std::ostringstream text;
  text << list.getEntry(name).getAny(false);
  return text.str();
}

// The first key whose value differs (or that only one list has) between `then` and `now`.
DeckDifference firstDifference(const Teuchos::ParameterList& then, const Teuchos::ParameterList& now,
                               const std::string& prefix)
{
  const auto differs = [&](const std::string& name) {
    return DeckDifference{prefix.empty() ? name : prefix + "/" + name, valueText(then, name), valueText(now, name)};
  };
  for (auto it = then.begin(); it != then.end(); ++it) {
    const std::string& name = then.name(it);
    if (!now.isParameter(name) || then.isSublist(name) != now.isSublist(name)) {
      return differs(name);
    }
    if (then.isSublist(name)) {
      DeckDifference inner = firstDifference(then.sublist(name), now.sublist(name), differs(name).path);
      if (!inner.path.empty()) {
        return inner;
      }
    } else if (!then.getEntry(name).getAny(false).same(now.getEntry(name).getAny(false))) {
      return differs(name);
    }
  }
  for (auto it = now.begin(); it != now.end(); ++it) {
    if (!then.isParameter(now.name(it))) {
      return differs(now.name(it));
    }
  }
  return {};
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
  const DeckDifference difference = firstDifference(*then, *now, "");
  core::require<core::InputError>(difference.path.empty(), "Cannot restart from '", checkpointPath,
                                  "': the deck differs from the one the run was started with at '", difference.path,
                                  "': the run was written with ", difference.path, " = ", difference.then,
                                  " but the deck has ", difference.now,
                                  ". Only 'Time integration/End time' and 'Output/Directory' may change on ",
                                  "restart (use the deck.xml written next to the checkpoint, or start a new run in "
                                  "another output directory).");
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

std::string checkpointPath(const std::string& directory)
{
  return (std::filesystem::path(directory) / "checkpoint.h5").string();
}

io::Checkpoint readRestartCheckpoint(const std::string& restartDirectory, const std::string& application,
                                     const Teuchos::ParameterList& validatedDeck)
{
  const std::string path = checkpointPath(restartDirectory);
  io::Checkpoint checkpoint;
  try {
    checkpoint = io::readCheckpoint(path);
  } catch (const core::IoError& e) {
    throw core::InputError(core::message("--restart ", restartDirectory, ": ", e.what()));
  }
  requireSameApplication(checkpoint, application, path);
  requireSameRun(validatedDeck, checkpoint.deckXml, path);
  return checkpoint;
}

} // namespace capsula::run
