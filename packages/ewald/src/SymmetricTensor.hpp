#pragma once
// Symmetric 3 x 3 tensors as the spectral Ewald kernels carry them: 6 numbers (xx, yy, zz, xy,
// xz, yz), the layout of the stresslet's and the wall double layer's source densities.
namespace capsula::ewald::detail {

/// The slot of S_ij in the 6-number layout.
constexpr int symmetricIndex[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};

/// out = S v for S in the 6-number layout (Number real or complex).
template <class Number, class Vector>
void symmetricTimes(const Number* S, const Vector& v, Number out[3])
{
  for (int i = 0; i < 3; ++i) {
    out[i] = S[symmetricIndex[i][0]] * v[0] + S[symmetricIndex[i][1]] * v[1] + S[symmetricIndex[i][2]] * v[2];
  }
}

} // namespace capsula::ewald::detail
