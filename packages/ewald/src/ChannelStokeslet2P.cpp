// The reference Fourier series of the channel Stokeslet (ChannelStokeslet2P.hpp).
#include "capsula/ewald/ChannelStokeslet2P.hpp"

#include "capsula/ewald/LatticeSums2P.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace capsula::ewald {

namespace {

constexpr double channelPi = 3.14159265358979323846;

/// W and W' at one height (header comment).
struct ProfileValue {
  double value = 0.0;
  double slope = 0.0;
};

/// The free parts F(t) and F'(t) of W_l (Phi') and W_y (Phi), t = y - h.
void freeParts(double a, double t, ProfileValue& longitudinal, ProfileValue& normal)
{
  const double e = std::exp(-a * std::fabs(t));
  longitudinal = {-t * e / (4.0 * a), -(1.0 - a * std::fabs(t)) * e / (4.0 * a)};
  normal = {(1.0 + a * std::fabs(t)) * e / (4.0 * a * a * a), -t * e / (4.0 * a)};
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

/// W_l, W_y and their slopes at height y for a source at h (header comment): the free part
/// plus the wall modes (c1 + c2 y) e^{-a y} + (c3 + c4 (H - y)) e^{-a (H - y)} that make
/// W = W' = 0 on both walls.
void modeProfiles(double a, double height, double h, double y, ProfileValue& longitudinal, ProfileValue& normal)
{
  const double E = std::exp(-a * height);
  const double H = height;
  // Rows: W(0), W'(0), W(H), W'(H) of the four wall modes.
  double M[4][4] = {{1.0, 0.0, E, E * H},
                    {-a, 1.0, a * E, E * (a * H - 1.0)},
                    {E, E * H, 1.0, 0.0},
                    {-a * E, E * (1.0 - a * H), a, -1.0}};
  ProfileValue l0, n0, lH, nH;
  freeParts(a, -h, l0, n0);
  freeParts(a, H - h, lH, nH);
  double c[4][2] = {{-l0.value, -n0.value}, {-l0.slope, -n0.slope}, {-lH.value, -nH.value}, {-lH.slope, -nH.slope}};
  solve4(M, c);
  freeParts(a, y - h, longitudinal, normal);
  const double lower = std::exp(-a * y);
  const double upper = std::exp(-a * (H - y));
  ProfileValue* profiles[2] = {&longitudinal, &normal};
  for (int p = 0; p < 2; ++p) {
    const double lowerMode = c[0][p] + c[1][p] * y;
    const double upperMode = c[2][p] + c[3][p] * (H - y);
    profiles[p]->value += lowerMode * lower + upperMode * upper;
    profiles[p]->slope += (c[1][p] - a * lowerMode) * lower + (a * upperMode - c[3][p]) * upper;
  }
}

/// T(y): the Dirichlet Green's function of d^2 - a^2 on [0, H] (header comment).
double transverseProfile(double a, double height, double h, double y)
{
  const double images = std::exp(-a * std::fabs(y - h)) - std::exp(-a * (y + h)) -
                        std::exp(-a * (2.0 * height - y - h)) + std::exp(-a * (2.0 * height - std::fabs(y - h)));
  return images / (2.0 * a * (1.0 - std::exp(-2.0 * a * height)));
}

} // namespace

double channelZeroModeProfile(double y, double h, double height)
{
  return 8.0 * channelPi * std::min(y, h) * (height - std::max(y, h)) / height;
}

double channelSeriesCutoff(double distance, double tolerance)
{
  double ad = std::log(1.0 / tolerance);
  for (int iteration = 0; iteration < 30; ++iteration) {
    ad = std::log(1.0 / tolerance) + 3.0 * std::log(1.0 + ad);
  }
  return ad / distance;
}

void periodicChannelStokeslet2P(const PeriodicLayer& layer, double height, const double x[3], const double x0[3],
                                double G[3][3], double tolerance)
{
  const double y = x[1], h = x0[1];
  if (!(height > 0.0) || !(h > 0.0) || !(h < height) || !(y >= 0.0) || !(y <= height) || y == h) {
    throw std::invalid_argument("ewald: the channel series needs 0 < h < H, 0 <= y <= H and y != h");
  }
  double sum[3][3] = {{0.0}};
  forEachModeWithin(layer, channelSeriesCutoff(std::fabs(y - h), tolerance), true, [&](double kx, double kz) {
    const double a = std::sqrt(kx * kx + kz * kz);
    const double kHat[3] = {kx / a, 0.0, kz / a};
    const double tHat[3] = {-kz / a, 0.0, kx / a};
    ProfileValue wl, wy;
    modeProfiles(a, height, h, y, wl, wy);
    const double T = transverseProfile(a, height, h, y);
    const double theta = kx * (x[0] - x0[0]) + kz * (x[2] - x0[2]);
    const double c = 2.0 * std::cos(theta), s = 2.0 * std::sin(theta);
    for (int j : {0, 2}) {
      for (int i : {0, 2}) {
        sum[i][j] += c * (tHat[j] * T * tHat[i] - kHat[j] * wl.slope * kHat[i]); // real
      }
      sum[1][j] -= s * a * kHat[j] * wl.value; // imaginary
    }
    for (int i : {0, 2}) {
      sum[i][1] -= s * a * wy.slope * kHat[i]; // imaginary
    }
    sum[1][1] += c * a * a * wy.value; // real
  });
  const double area = layer.lengthX * layer.lengthZ;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      G[i][j] = 8.0 * channelPi * sum[i][j] / area;
    }
  }
  const double mean = channelZeroModeProfile(y, h, height) / area;
  G[0][0] += mean;
  G[2][2] += mean;
}

} // namespace capsula::ewald
