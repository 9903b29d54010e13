#pragma once
// The message of a deck name that no registry entry has: what kind of thing was asked for,
// every registered name and the closest one, so a typo or a missing library is obvious.
// The registries of kernels, summation back-ends and membrane laws share it.
#include <string>
#include <vector>

namespace capsula::core {

/// Throws InputError "There is no <kind> named '<name>'; registered: A, B. Did you
/// mean 'A'?" unless `name` is one of `registered`.
void requireRegistered(const std::string& kind, const std::string& name, const std::vector<std::string>& registered);

} // namespace capsula::core
