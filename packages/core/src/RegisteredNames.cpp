#include "capsula/core/RegisteredNames.hpp"

#include "capsula/core/DeckValidators.hpp"
#include "capsula/core/Error.hpp"

#include <algorithm>
#include <sstream>

namespace capsula::core {

void requireRegistered(const std::string& kind, const std::string& name, const std::vector<std::string>& registered)
{
  if (std::find(registered.begin(), registered.end(), name) != registered.end()) {
    return;
  }
  std::ostringstream known;
  for (const auto& entry : registered) {
    known << (known.tellp() > 0 ? ", " : "") << entry;
  }
  const auto closest = closestMatch(name, registered);
  throw InputError(message("There is no ", kind, " named '", name, "'; registered: ", known.str(), ".",
                           closest ? " Did you mean '" + *closest + "'?" : ""));
}

} // namespace capsula::core
