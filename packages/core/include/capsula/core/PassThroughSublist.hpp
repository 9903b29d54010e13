#pragma once
// A deck sublist whose entries belong to a library that knows them, not to Capsula.
//
// Most deck keys are declared up front (ParameterDeclaration.hpp) and the deck check
// (Deck.hpp) refuses every other key. Some settings are those of a third-party component
// whose valid keys depend on a choice made elsewhere in the deck: the parameters of the
// Belos solver manager 'Solver/Method' names are that solver's alone, and declaring those of
// every solver would fill --print-defaults with keys a run never uses. Such a sublist is
// declared here instead. The deck check requires it to be a sublist and passes its entries
// through unexamined; the component that reads it checks them against the valid list of
// what it chose (checkPassThroughEntries), at start-up, naming each key by its full path:
//
//   <ParameterList name="Belos">                          'Solver/Belos'
//     <Parameter name="Orthogonalization" type="string" value="DGKS"/>
//   </ParameterList>
//
// --set reaches its keys too ("Solver/Belos/Maximum Iterations=40"): a key the deck does
// not hold gets the type its text reads as (integer, real, true/false, otherwise string).
#include <Teuchos_ParameterEntry.hpp>
#include <Teuchos_ParameterList.hpp>

#include <string>

namespace capsula::core {

/// Declares the sublist `name` of `list`, documented by `doc`, whose entries the deck check
/// passes to the component that reads them. It has no defaults. Returns it.
Teuchos::ParameterList& declarePassThroughSublist(Teuchos::ParameterList& list, const std::string& name,
                                                  const std::string& doc);

/// Whether an entry of a valid list was declared by declarePassThroughSublist.
bool isPassThroughSublist(const Teuchos::ParameterEntry& validEntry);

/// Checks the entries of a pass-through sublist against `valid`, the valid parameters of the
/// component that receives them (named by `owner` in messages, e.g. "the Belos solver
/// 'TFQMR'"); `path` is the sublist's key path ("Solver/Belos"). Throws InputError naming
/// "<path>/<key>" for a key `valid` does not have (with the closest one and the keys a deck
/// can set), a sublist given as a value or the reverse, a value of another type, or a value
/// the component's validator refuses. An int where `valid` has a double is converted, as
/// the deck check does.
void checkPassThroughEntries(Teuchos::ParameterList& entries, const Teuchos::ParameterList& valid,
                             const std::string& path, const std::string& owner);

} // namespace capsula::core
