#pragma once
// The strict reading of a deck file's values (internal to capsula::core).
//
// Teuchos reads a Parameter's value attribute with an input stream: "abc" becomes 0,
// "2.5" an int 2, "0.3abc" 0.3, 99999999999 an overflowed int, and of two Parameters with
// the same name the last wins without a word. Decks are therefore read twice:
// checkDeckText() goes over the text first, applying to every value the checks that --set applies (the whole text consumed,
// reals finite, integers without fraction or overflow, arrays element by element) and
// refusing a key given twice in one list, naming the key, the file and the lines; then
// Teuchos builds the list (and reports malformed XML, which this reading passes over).
#include <string>

namespace capsula::core::detail {

/// Throws InputError for the first bad value or duplicate key in a deck's XML text.
/// `sourceName` names the deck in the message.
void checkDeckText(const std::string& xml, const std::string& sourceName);

/// `s` without leading and trailing blanks (spaces, tabs, line ends).
std::string trimmed(const std::string& s);

/// Strict parses shared with --set: true only if the whole trimmed text is the value.
bool parseFiniteReal(const std::string& text, double& value);
bool parseInteger(const std::string& text, int& value);
bool parseBoolean(const std::string& text, bool& value);

} // namespace capsula::core::detail
