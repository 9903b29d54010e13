#include "capsula/run/Collective.hpp"

#include <capsula/core/Error.hpp>

#include <Teuchos_CommHelpers.hpp>

#include <exception>
#include <string>

namespace capsula::run {

namespace {

enum class ErrorKind : int { None = 0, Input = 1, Io = 2, Other = 3 };

} // namespace

void onRoot(const Teuchos::Comm<int>& comm, const std::function<void()>& action)
{
  int kind = 0;
  std::string message;
  if (comm.getRank() == 0) {
    try {
      action();
    } catch (const core::InputError& e) {
      kind = static_cast<int>(ErrorKind::Input);
      message = e.what();
    } catch (const core::IoError& e) {
      kind = static_cast<int>(ErrorKind::Io);
      message = e.what();
    } catch (const std::exception& e) {
      kind = static_cast<int>(ErrorKind::Other);
      message = e.what();
    }
  }
  Teuchos::broadcast(comm, 0, &kind);
  if (kind == 0) {
    return;
  }
  int length = static_cast<int>(message.size());
  Teuchos::broadcast(comm, 0, &length);
  message.resize(static_cast<std::size_t>(length));
  if (length > 0) {
    Teuchos::broadcast(comm, 0, length, message.data());
  }
  switch (static_cast<ErrorKind>(kind)) {
  case ErrorKind::Input:
    throw core::InputError(message);
  case ErrorKind::Io:
    throw core::IoError(message);
  default:
    throw core::Error(message);
  }
}

} // namespace capsula::run
