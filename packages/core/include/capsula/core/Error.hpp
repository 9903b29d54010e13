#pragma once
// Capsula's error convention.
//
// Every error a user can cause or meet names what went wrong and where:
//   - InputError:     a deck key, a command-line option, a file (the message
//                     names the key path / option / file and the offending value);
//   - NumericalError: the computation itself failed (non-finite state, step-size
//                     collapse, solver breakdown); names the cause and the time;
//   - IoError:        a file or directory could not be read or written.
// All derive from capsula::core::Error so apps catch one type, print what() and
// exit non-zero. Messages are complete sentences that say what to change.
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace capsula::core {

class Error : public std::runtime_error {
public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

class InputError final : public Error {
public:
  explicit InputError(const std::string& message) : Error(message) {}
};

class NumericalError final : public Error {
public:
  explicit NumericalError(const std::string& message) : Error(message) {}
};

class IoError final : public Error {
public:
  explicit IoError(const std::string& message) : Error(message) {}
};

/// Builds a message from streamable pieces: message("level ", n, " is out of range").
template <typename... Parts>
std::string message(Parts&&... parts)
{
  std::ostringstream out;
  (out << ... << std::forward<Parts>(parts));
  return out.str();
}

/// Throws ErrorType(message(parts...)) unless `condition` holds.
template <typename ErrorType = Error, typename... Parts>
void require(bool condition, Parts&&... parts)
{
  if (!condition) {
    throw ErrorType(message(std::forward<Parts>(parts)...));
  }
}

/// The last non-empty line of a library's exception message: Teuchos and Belos put the
/// source location and the failed test above the sentence meant for the user.
inline std::string lastLineOf(const std::string& what)
{
  const std::size_t end = what.find_last_not_of(" \n\t");
  if (end == std::string::npos) {
    return what;
  }
  const std::size_t newline = what.find_last_of('\n', end);
  const std::size_t start = newline == std::string::npos ? 0 : newline + 1;
  return what.substr(start, end - start + 1);
}

} // namespace capsula::core
