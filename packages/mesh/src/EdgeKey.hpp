#pragma once
// The key of an unordered node pair (an edge) in a hash map: both orders give the same key.
#include <algorithm>
#include <cstdint>

namespace capsula::mesh::detail {

inline std::uint64_t edgeKey(int a, int b)
{
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return (hi << 32) | lo;
}

} // namespace capsula::mesh::detail
