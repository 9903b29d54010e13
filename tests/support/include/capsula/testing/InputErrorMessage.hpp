#pragma once
// The message a deck mistake produces, for tests that check what it names.
#include <capsula/core/Error.hpp>

#include <functional>
#include <string>

namespace capsula::testing {

/// The what() of the core::InputError `action` throws, or "no InputError" if it throws none.
inline std::string inputErrorMessage(const std::function<void()>& action)
{
  try {
    action();
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "no InputError";
}

} // namespace capsula::testing
