#pragma once
// The deck's choice of a membrane law in a cell's sublist: 'Membrane law' (a registered
// name) and the keys of every registered law, declared beside it (Skalak's 'Area dilation
// C'). The same for 2D and 3D: only the registry's MembraneLawInfo is needed.
//
// A law's keys sit in the cell's sublist itself, not in a sublist of their own, so that
// 'Cells/Cell k/Area dilation C' keeps its place; every law's keys are declared whichever
// law the cell chooses, and two laws cannot declare the same key.
#include "capsula/elasticity/MembraneLawCatalogue.hpp"

#include <Teuchos_ParameterList.hpp>

#include <map>
#include <string>

namespace capsula::elasticity {

/// The law a cell's sublist selects, with its keys (defaults filled in; empty if it has none).
struct MembraneLawChoice {
  std::string name;
  Teuchos::ParameterList parameters;
};

/// Declares 'Membrane law' in `cell` (default `defaultLaw`; choices the names of `laws`,
/// each described in the doc string after `purpose`) and the keys of every law. Throws
/// core::InputError if `defaultLaw` is not registered or a law's key would replace a key
/// `cell` already has.
void declareMembraneLawParameters(Teuchos::ParameterList& cell, const std::map<std::string, MembraneLawInfo>& laws,
                                  const std::string& defaultLaw, const std::string& purpose);

/// The law the validated `cell` selects with its keys. `path` is the cell's deck path
/// ("Cells/Cell 0", "Cell") for the message: an unknown name is a core::InputError naming
/// '<path>/Membrane law', the registered laws and the closest one.
MembraneLawChoice readMembraneLawChoice(const Teuchos::ParameterList& cell,
                                        const std::map<std::string, MembraneLawInfo>& laws, const std::string& path);

} // namespace capsula::elasticity
