#pragma once
// Input decks: Teuchos XML parameter lists, read, checked and written.
//
// Reading a deck file checks its text (DeckText.hpp): every value must be exactly what
// its type attribute says (the whole text read, reals finite, integers without fraction or
// overflow, arrays element by element), and no key may appear twice in one list; the
// message names the key, the file and the line.
//
// A deck is checked against the "valid parameter list" that the components
// declare (ParameterDeclaration.hpp). Checking rejects, with a message that
// names the deck file and the full key path ("Flow/Capillary number"):
//   - unknown keys (with a "did you mean" suggestion),
//   - a sublist given as a value or a value given as a sublist,
//   - wrong types (an int where a double is expected is converted, not rejected),
//   - values a validator refuses (out of range, not one of the choices).
// Then Teuchos's validateParametersAndSetDefaults fills in every default, so the
// validated deck is complete and can be written into a run's output as a record.
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <functional>
#include <iosfwd>
#include <string>

namespace capsula::core {

/// Builds the valid parameter list for a given (possibly partial) deck. Most
/// components ignore the deck; a scene uses it to declare one sublist per cell.
using ValidParameterBuilder =
    std::function<Teuchos::RCP<const Teuchos::ParameterList>(const Teuchos::ParameterList& deck)>;

/// Reads an XML deck. Throws IoError if the file cannot be read, InputError if
/// it is not a Teuchos XML parameter list (the message names the file).
Teuchos::RCP<Teuchos::ParameterList> readDeck(const std::string& path);

/// Parses a deck from an XML string (tests, restart records), with the checks of its
/// text described above. `sourceName` names it in messages.
Teuchos::RCP<Teuchos::ParameterList> readDeckFromString(const std::string& xml, const std::string& sourceName);

/// Checks `deck` against `valid` as described above and fills in defaults.
/// `deckName` (usually the file path) is named in every message.
void validateDeck(Teuchos::ParameterList& deck, const Teuchos::ParameterList& valid, const std::string& deckName);

/// Applies one `--set` override, "List/Sub/Key=value". The key path must exist
/// in `valid` (or already in `deck`); the value is parsed as that key's type:
/// double, int, bool (true/false/1/0/yes/no/on/off), string, or Array(double)
/// ("{1, 2, 3}" or "1,2,3"). Throws InputError naming the override.
void applyOverride(Teuchos::ParameterList& deck, const Teuchos::ParameterList& valid, const std::string& assignment);

/// Writes `list` as Teuchos XML that readDeck() reads back. With `withDocs`,
/// each parameter is preceded by an XML comment holding its doc string and
/// requirement (the form `--print-defaults` prints).
void writeDeckXml(std::ostream& out, const Teuchos::ParameterList& list, bool withDocs);

/// writeDeckXml into a string.
std::string deckToXml(const Teuchos::ParameterList& list, bool withDocs);

} // namespace capsula::core
