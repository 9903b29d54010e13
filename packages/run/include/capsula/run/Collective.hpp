#pragma once
// Work that one rank does for all: the output files are written on rank 0, and a failure
// there must stop every rank, not leave the others waiting in the next collective.
#include <Teuchos_Comm.hpp>

#include <functional>

namespace capsula::run {

/// Runs `action` on rank 0 only; if it throws, every rank throws the same error
/// (core::InputError, core::IoError or core::Error with the message). Collective.
void onRoot(const Teuchos::Comm<int>& comm, const std::function<void()>& action);

} // namespace capsula::run
