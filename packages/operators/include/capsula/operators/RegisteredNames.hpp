#pragma once
// The registries of this package answer an unregistered name as every registry does
// (core/RegisteredNames.hpp).
#include <capsula/core/RegisteredNames.hpp>

namespace capsula::operators {

using core::requireRegistered;

} // namespace capsula::operators
