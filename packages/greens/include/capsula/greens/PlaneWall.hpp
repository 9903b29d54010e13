#pragma once
// The plane wall of the wall-bounded kernels: the plane y = 0, fluid in y > 0
// (thesis App. B with w = 0). Coordinate axis 1 (y) is the wall normal in 2D and 3D.

namespace capsula::greens {

inline constexpr int wallNormalAxis = 1;

/// The "+-" of thesis eqs B.3-B.4, B.11-B.12, B.15-B.16: +1 when the force index j is
/// tangential to the wall, -1 when it is normal.
inline constexpr double imageSign(int j) { return j == wallNormalAxis ? -1.0 : 1.0; }

} // namespace capsula::greens
