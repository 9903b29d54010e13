#include "capsula/scene/CellOwnership.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace capsula::scene {

namespace {

// The error types a failure keeps across the ranks (Failure::kind).
enum ErrorKind : int { kOtherError = 0, kInputError, kNumericalError, kIoError, kStateOutsideDomain };

[[noreturn]] void throwOfKind(int kind, const std::string& message)
{
  switch (kind) {
  case kInputError:
    throw core::InputError(message);
  case kNumericalError:
    throw core::NumericalError(message);
  case kIoError:
    throw core::IoError(message);
  case kStateOutsideDomain:
    throw timeint::StateOutsideDomain(message);
  default:
    throw core::Error(message);
  }
}

} // namespace

CellOwnership::CellOwnership(Teuchos::RCP<const Teuchos::Comm<int>> comm, const std::vector<int>& nodesPerCell)
    : comm_(std::move(comm)), rank_(comm_->getRank())
{
  const std::int64_t total = std::accumulate(nodesPerCell.begin(), nodesPerCell.end(), std::int64_t{0});
  const std::int64_t ranks = comm_->getSize();
  std::int64_t first = 0;
  for (const int n : nodesPerCell) {
    core::require<core::InputError>(n > 0, "CellOwnership: a cell without nodes");
    const std::int64_t middle = first + n / 2;
    owners_.push_back(static_cast<int>(std::min(ranks - 1, ranks * middle / std::max<std::int64_t>(total, 1))));
    first += n;
  }
}

int CellOwnership::numOwned() const
{
  return static_cast<int>(std::count(owners_.begin(), owners_.end(), rank_));
}

void CellOwnership::share(std::vector<double>& values, const std::vector<std::size_t>& offsets) const
{
  core::require(offsets.size() == owners_.size() + 1 && offsets.back() <= values.size(),
                "CellOwnership::share: offsets for ", offsets.size() - 1, " cells, ", values.size(), " values");
  if (comm_->getSize() == 1) {
    return;
  }
  // Zero where other ranks' cells lie, then sum: each entry is one rank's value plus zeros,
  // which is that value exactly.
  std::vector<double> mine(values);
  for (int c = 0; c < numCells(); ++c) {
    if (!owns(c)) {
      std::fill(mine.begin() + static_cast<std::ptrdiff_t>(offsets[static_cast<std::size_t>(c)]),
                mine.begin() + static_cast<std::ptrdiff_t>(offsets[static_cast<std::size_t>(c) + 1]), 0.0);
    }
  }
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(mine.size()), mine.data(), values.data());
}

CellOwnership::Failure CellOwnership::describeCurrentException(int cell)
{
  Failure failure;
  failure.cell = cell;
  failure.error = std::current_exception();
  try {
    throw;
  } catch (const timeint::StateOutsideDomain& e) {
    failure.kind = kStateOutsideDomain;
    failure.message = e.what();
  } catch (const core::InputError& e) {
    failure.kind = kInputError;
    failure.message = e.what();
  } catch (const core::NumericalError& e) {
    failure.kind = kNumericalError;
    failure.message = e.what();
  } catch (const core::IoError& e) {
    failure.kind = kIoError;
    failure.message = e.what();
  } catch (const std::exception& e) {
    failure.message = e.what();
  } catch (...) {
    failure.message = "an unknown error";
  }
  return failure;
}

void CellOwnership::raiseLowestFailure(const Failure& failure) const
{
  if (comm_->getSize() > 1) {
    const int none = numCells();
    const int mine = failure.cell < 0 ? none : failure.cell;
    int lowest = none;
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(lowest));
    if (lowest == none) {
      return;
    }
    if (lowest != mine) { // another rank's cell failed first: its owner sends the error
      int header[2] = {0, 0};
      Teuchos::broadcast(*comm_, owner(lowest), 2, header);
      std::string message(static_cast<std::size_t>(header[1]), '\0');
      Teuchos::broadcast(*comm_, owner(lowest), header[1], message.data());
      throwOfKind(header[0], message);
    }
    int header[2] = {failure.kind, static_cast<int>(failure.message.size())};
    Teuchos::broadcast(*comm_, rank_, 2, header);
    std::string message = failure.message;
    Teuchos::broadcast(*comm_, rank_, header[1], message.data());
  }
  if (failure.error) {
    std::rethrow_exception(failure.error);
  }
}

} // namespace capsula::scene
