// The mode profiles of the channel Stokeslet's reference series (ChannelModes.hpp).
#include "ChannelModes.hpp"

#include <cmath>
#include <utility>

namespace capsula::ewald::detail {

namespace {

/// The free parts, t = y - h, e = e^{-a|t|}: Phi = (1 + a|t|) e / (4 a^3) for W_y, and its
/// derivative Phi' = -t e / (4a) for W_l, with Phi'' = -(1 - a|t|) e / (4a),
/// Phi''' = sgn(t) (2 - a|t|) e / 4 and Phi'''' = -a (3 - a|t|) e / 4 off t = 0.
void freeParts(double a, double t, ChannelProfile& longitudinal, ChannelProfile& normal)
{
  const double r = std::fabs(t), e = std::exp(-a * r), sign = t > 0.0 ? 1.0 : -1.0;
  const double phi[5] = {(1.0 + a * r) * e / (4.0 * a * a * a), -t * e / (4.0 * a), -(1.0 - a * r) * e / (4.0 * a),
                         sign * (2.0 - a * r) * e / 4.0, -a * (3.0 - a * r) * e / 4.0};
  for (int n = 0; n < 4; ++n) {
    normal.d[n] = phi[n];
    longitudinal.d[n] = phi[n + 1];
  }
}

/// Solves M c = b for the 4 x 4 system (Gaussian elimination with partial pivoting), two
/// right-hand sides at once (the columns of b).
void solve4(double M[4][4], double b[4][2])
{
  for (int col = 0; col < 4; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 4; ++r) {
      if (std::fabs(M[r][col]) > std::fabs(M[pivot][col])) {
        pivot = r;
      }
    }
    std::swap(M[col], M[pivot]);
    std::swap(b[col], b[pivot]);
    for (int r = col + 1; r < 4; ++r) {
      const double f = M[r][col] / M[col][col];
      for (int c = col; c < 4; ++c) {
        M[r][c] -= f * M[col][c];
      }
      b[r][0] -= f * b[col][0];
      b[r][1] -= f * b[col][1];
    }
  }
  for (int row = 3; row >= 0; --row) {
    for (int rhs = 0; rhs < 2; ++rhs) {
      double s = b[row][rhs];
      for (int c = row + 1; c < 4; ++c) {
        s -= M[row][c] * b[c][rhs];
      }
      b[row][rhs] = s / M[row][row];
    }
  }
}

} // namespace

void channelPlaneProfiles(double a, double height, double h, double y, ChannelProfile& longitudinal,
                          ChannelProfile& normal)
{
  const double E = std::exp(-a * height);
  const double H = height;
  // Rows: W(0), W'(0), W(H), W'(H) of the wall modes (c1 + c2 y) e^{-a y} and
  // (c3 + c4 (H - y)) e^{-a (H - y)}.
  double M[4][4] = {{1.0, 0.0, E, E * H},
                    {-a, 1.0, a * E, E * (a * H - 1.0)},
                    {E, E * H, 1.0, 0.0},
                    {-a * E, E * (1.0 - a * H), a, -1.0}};
  ChannelProfile l0, n0, lH, nH;
  freeParts(a, -h, l0, n0);
  freeParts(a, H - h, lH, nH);
  double c[4][2] = {{-l0.d[0], -n0.d[0]}, {-l0.d[1], -n0.d[1]}, {-lH.d[0], -nH.d[0]}, {-lH.d[1], -nH.d[1]}};
  solve4(M, c);
  freeParts(a, y - h, longitudinal, normal);
  const double lower = std::exp(-a * y);
  const double upper = std::exp(-a * (H - y));
  ChannelProfile* profiles[2] = {&longitudinal, &normal};
  for (int p = 0; p < 2; ++p) {
    const double lowerMode = c[0][p] + c[1][p] * y;
    const double upperMode = c[2][p] + c[3][p] * (H - y);
    // n-th derivatives: (-a)^n (c1 + c2 y) + n (-a)^{n-1} c2 below, and with s = H - y,
    // d/dy = -d/ds, (-1)^n [(-a)^n (c3 + c4 s) + n (-a)^{n-1} c4] above.
    double power = 1.0, previous = 0.0; // (-a)^n and n (-a)^{n-1}
    for (int n = 0; n < 4; ++n) {
      const double sign = n % 2 == 0 ? 1.0 : -1.0;
      profiles[p]->d[n] +=
          (power * lowerMode + previous * c[1][p]) * lower + sign * (power * upperMode + previous * c[3][p]) * upper;
      previous = (n + 1) * power;
      power *= -a;
    }
  }
}

void channelTransverseProfile(double a, double height, double h, double y, double& value, double& slope)
{
  // The Dirichlet Green's function of d^2 - a^2 on [0, H] by its four exponential images.
  const double sign = y > h ? 1.0 : -1.0;
  const double direct = std::exp(-a * std::fabs(y - h)), lower = std::exp(-a * (y + h));
  const double upper = std::exp(-a * (2.0 * height - y - h)), far = std::exp(-a * (2.0 * height - std::fabs(y - h)));
  const double scale = 1.0 / (2.0 * a * (1.0 - std::exp(-2.0 * a * height)));
  value = (direct - lower - upper + far) * scale;
  slope = a * (-sign * direct + lower - upper + sign * far) * scale;
}

} // namespace capsula::ewald::detail
