#include "capsula/io/OutputDirectory.hpp"

#include "capsula/core/Deck.hpp"
#include "capsula/core/Files.hpp"
#include "capsula/core/RunInfo.hpp"
#include "capsula/io/Json.hpp"

#include <ctime>
#include <filesystem>
#include <utility>

namespace capsula::io {

namespace {

std::string utcNow()
{
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

} // namespace

OutputDirectory::OutputDirectory(std::string path) : path_(std::move(path))
{
  core::ensureWritableDirectory(path_);
}

std::string OutputDirectory::file(const std::string& name) const
{
  return (std::filesystem::path(path_) / name).string();
}

void OutputDirectory::writeRunMetadata(const Teuchos::ParameterList& validatedDeck, const RunMetadata& run) const
{
  const std::string xml = core::deckToXml(validatedDeck, false);
  core::writeFileAtomically(file("deck.xml"), [&](std::ostream& out) { out << xml; });

  JsonValue info = JsonValue::object();
  info["application"] = run.application;
  info["deck"] = run.deckSource;
  info["capsula version"] = core::capsulaVersion();
  info["git sha"] = core::gitSha();
  info["trilinos version"] = core::trilinosVersion();
  info["ranks"] = run.ranks;
  info["started (UTC)"] = utcNow();
  writeJsonFile(file("run.json"), info);
}

} // namespace capsula::io
