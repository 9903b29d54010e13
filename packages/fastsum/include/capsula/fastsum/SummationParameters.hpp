#pragma once
// The deck's choice of the far-field back-end of the 3D operators, in the sublist
// "Operator": 'Summation' (Direct or Treecode) and the treecode's own sublist 'Treecode'
// (Tolerance, Leaf size). Declared here, next to the back-end that reads them, because the
// operators package does not know the treecode.
#include <capsula/operators/FarFieldBackEnd.hpp>

#include <Teuchos_ParameterList.hpp>

#include <memory>

namespace capsula::fastsum {

/// Declares Summation and the sublist Treecode in `operatorList` (the deck's "Operator").
void declareSummationParameters(Teuchos::ParameterList& operatorList);

/// The back-end a validated "Operator" list selects: null for Direct (the operators' own
/// direct sums), a TreecodeBackEnd for Treecode.
std::shared_ptr<const operators::FarFieldBackEnd> readFarFieldBackEnd(const Teuchos::ParameterList& operatorList);

} // namespace capsula::fastsum
