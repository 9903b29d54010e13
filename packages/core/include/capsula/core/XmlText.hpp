#pragma once
// Text placed in a double-quoted XML attribute or in an element (decks written back, the
// XDMF index of the snapshots), with the characters XML reserves there escaped.
#include <string>

namespace capsula::core {

/// `text` with &, <, > and " replaced by their entities.
std::string xmlEscaped(const std::string& text);

} // namespace capsula::core
