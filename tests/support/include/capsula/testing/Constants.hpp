#pragma once
// Constants the tests share (one definition, so that a package's tests compile together).

namespace capsula::testing {

/// The double nearest to pi (equal to std::acos(-1.0)).
inline constexpr double pi = 3.14159265358979323846;

} // namespace capsula::testing
