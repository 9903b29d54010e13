#pragma once
// The treecode as the summation back-end "Treecode" of an operators::SummationRegistry:
// 'Operator/Summation' = Treecode, with its own sublist 'Operator/Treecode' (Tolerance,
// Leaf size). The keys are declared here, next to the back-end that reads them, because
// the operators package does not know the treecode.
#include <capsula/operators/SummationRegistry.hpp>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

namespace capsula::fastsum {

/// The keys of 'Operator/Treecode' with their defaults, validators and doc strings.
Teuchos::RCP<const Teuchos::ParameterList> validTreecodeParameters();

/// Registers "Treecode": a TreecodeBackEnd built from the sublist's Tolerance and Leaf size.
void registerTreecodeSummation(operators::SummationRegistry& summations);

} // namespace capsula::fastsum
