#include "capsula/operators/WarmStartHistory.hpp"

#include <capsula/core/Error.hpp>

#include <Eigen/Dense>

namespace capsula::operators {

WarmStartHistory::WarmStartHistory(int depth) : depth_(depth)
{
  core::require<core::InputError>(depth >= 1, "A warm-start history needs depth >= 1, got ", depth, ".");
}

int WarmStartHistory::size() const
{
  return static_cast<int>(pairs_.size());
}

bool WarmStartHistory::empty() const
{
  return pairs_.empty();
}

std::size_t WarmStartHistory::length() const
{
  return pairs_.empty() ? 0 : pairs_.front().first.size();
}

std::vector<double> WarmStartHistory::initialGuess(const std::vector<double>& rhs) const
{
  if (pairs_.empty()) {
    return rhs;
  }
  const Eigen::Index n = static_cast<Eigen::Index>(rhs.size());
  const Eigen::Index m = static_cast<Eigen::Index>(pairs_.size());
  core::require<core::InputError>(static_cast<Eigen::Index>(pairs_.front().first.size()) == n,
                                  "Warm-start history: a right-hand side of ", n, " entries for pairs of ",
                                  pairs_.front().first.size(), ".");
  Eigen::MatrixXd B(n, m);
  for (Eigen::Index j = 0; j < m; ++j) {
    B.col(j) = Eigen::Map<const Eigen::VectorXd>(pairs_[static_cast<std::size_t>(j)].first.data(), n);
  }
  // Column-pivoted QR: the b_j are nearly parallel (O(step) apart), so the normal
  // equations would square an already large condition number; the rank-revealing QR drops
  // the directions round-off cannot resolve.
  const Eigen::VectorXd c = B.colPivHouseholderQr().solve(Eigen::Map<const Eigen::VectorXd>(rhs.data(), n));
  std::vector<double> guess(rhs.size(), 0.0);
  Eigen::Map<Eigen::VectorXd> u0(guess.data(), n);
  for (Eigen::Index j = 0; j < m; ++j) {
    u0 += c[j] * Eigen::Map<const Eigen::VectorXd>(pairs_[static_cast<std::size_t>(j)].second.data(), n);
  }
  return guess;
}

void WarmStartHistory::add(std::vector<double> rhs, std::vector<double> solution)
{
  core::require<core::InputError>(rhs.size() == solution.size(), "Warm-start history: a right-hand side of ",
                                  rhs.size(), " entries with a solution of ", solution.size(), ".");
  core::require<core::InputError>(pairs_.empty() || pairs_.front().first.size() == rhs.size(),
                                  "Warm-start history: pairs of ", rhs.size(), " entries added to pairs of ",
                                  pairs_.empty() ? 0 : pairs_.front().first.size(), ".");
  pairs_.emplace_back(std::move(rhs), std::move(solution));
  if (static_cast<int>(pairs_.size()) > depth_) {
    pairs_.erase(pairs_.begin());
  }
}

std::vector<double> WarmStartHistory::rightHandSides() const
{
  std::vector<double> all;
  for (const auto& pair : pairs_) {
    all.insert(all.end(), pair.first.begin(), pair.first.end());
  }
  return all;
}

std::vector<double> WarmStartHistory::solutions() const
{
  std::vector<double> all;
  for (const auto& pair : pairs_) {
    all.insert(all.end(), pair.second.begin(), pair.second.end());
  }
  return all;
}

WarmStartHistory WarmStartHistory::fromFlattened(int depth, int length, const std::vector<double>& rightHandSides,
                                                 const std::vector<double>& solutions)
{
  core::require<core::InputError>(
      length > 0 && rightHandSides.size() == solutions.size() &&
          rightHandSides.size() % static_cast<std::size_t>(length) == 0 &&
          rightHandSides.size() / static_cast<std::size_t>(length) <= static_cast<std::size_t>(depth),
      "Warm-start history: ", rightHandSides.size(), " right-hand side and ", solutions.size(),
      " solution entries do not make at most ", depth, " pairs of ", length, ".");
  WarmStartHistory history(depth);
  for (std::size_t first = 0; first < rightHandSides.size(); first += static_cast<std::size_t>(length)) {
    history.add(std::vector<double>(rightHandSides.begin() + static_cast<std::ptrdiff_t>(first),
                                    rightHandSides.begin() + static_cast<std::ptrdiff_t>(first) + length),
                std::vector<double>(solutions.begin() + static_cast<std::ptrdiff_t>(first),
                                    solutions.begin() + static_cast<std::ptrdiff_t>(first) + length));
  }
  return history;
}

} // namespace capsula::operators
