#pragma once
// The built-in Green's functions with the contracted inner-loop terms of KernelTraits.hpp.
//
// The integral sums need G_ij f_i and T_ijk v_i a_k, and the special rules of the double
// layer need the matrix T_ijk a_k, not the tensors: contracting the formulas by hand costs
// ~6x fewer operations than building G[3][3] and T[3][3][3] and contracting (the compiler
// may not reorder floating-point sums to find this itself).
// These policies ARE greens::FreeSpace3D and greens::Wall3D (they inherit stokeslet,
// stresslet, pressure and name, used everywhere else) plus the three contractions written
// from the same formulas (thesis eqs 3.11-3.12, App. B.2 as in greens/Wall3D.hpp). The
// unit tests pin each contraction to the greens tensors at random points to round-off.
// If greens grows these functions, these adapters can go.
#include <capsula/greens/FreeSpace3D.hpp>
#include <capsula/greens/PlaneWall.hpp>
#include <capsula/greens/Wall3D.hpp>
#include <capsula/operators/KernelTraits.hpp>

#include <cmath>

namespace capsula::operators {

struct FreeSpace3DKernel : greens::FreeSpace3D {
  /// u_j += G_ij f_i = f_j / r + xh_j (xh . f) / r^3, xh = x - x0.
  static void addSingleLayerTerm(const double x[3], const double x0[3], const double f[3], double u[3])
  {
    const double d[3] = {x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
    const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    const double invR = 1.0 / std::sqrt(r2);
    const double df = (d[0] * f[0] + d[1] * f[1] + d[2] * f[2]) * invR / r2;
    for (int j = 0; j < 3; ++j) {
      u[j] += f[j] * invR + d[j] * df;
    }
  }

  /// u_j += T_ijk v_i a_k = -6 (xh . v)(xh . a) xh_j / r^5.
  static void addDoubleLayerTerm(const double x[3], const double x0[3], const double v[3], const double a[3],
                                 double u[3])
  {
    const double d[3] = {x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
    const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    const double scale = -6.0 * (d[0] * v[0] + d[1] * v[1] + d[2] * v[2]) * (d[0] * a[0] + d[1] * a[1] + d[2] * a[2]) /
                         (r2 * r2 * std::sqrt(r2));
    for (int j = 0; j < 3; ++j) {
      u[j] += scale * d[j];
    }
  }

  /// M[3 i + j] += T_ijk a_k = -6 xh_i xh_j (xh . a) / r^5: the double-layer matrix of one
  /// source point, for the special rules (one 3x3 block instead of the 27 entries of T).
  static void addDoubleLayerMatrix(const double x[3], const double x0[3], const double a[3], double M[9])
  {
    const double d[3] = {x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
    const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    const double scale = -6.0 * (d[0] * a[0] + d[1] * a[1] + d[2] * a[2]) / (r2 * r2 * std::sqrt(r2));
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        M[3 * i + j] += scale * d[i] * d[j];
      }
    }
  }
};

struct Wall3DKernel : greens::Wall3D {
  /// What the double-layer terms share: h = the pole's height, xh = x - x0, X = x - x0'
  /// (x0' the image of the pole below the wall) and the powers 1/r^5, 1/R^5, 1/R^7.
  struct StressletGeometry {
    double h, d[3], X[3], invr5, invR5, invR7;
    StressletGeometry(const double x[3], const double x0[3])
    {
      constexpr int n = greens::wallNormalAxis;
      h = x0[n];
      for (int i = 0; i < 3; ++i) {
        d[i] = x[i] - x0[i];
        X[i] = d[i];
      }
      X[n] = x[n] + x0[n];
      const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      const double R2 = X[0] * X[0] + X[1] * X[1] + X[2] * X[2];
      invr5 = 1.0 / (r2 * r2 * std::sqrt(r2));
      invR5 = 1.0 / (R2 * R2 * std::sqrt(R2));
      invR7 = invR5 / R2;
    }
  };

  /// u_j += G^W_ij f_i with G^W = G(xh) - G(X) + 2 h^2 G^D(X) - 2 h G^SD(X) (Wall3D.hpp):
  ///   G^D_ij f_i  = s_j (f_j / R^3 - 3 X_j (X . f) / R^5) =: D_j
  ///   G^SD_ij f_i = X_n D_j + s_j (delta_jn (X . f) - f_n X_j) / R^3.
  static void addSingleLayerTerm(const double x[3], const double x0[3], const double f[3], double u[3])
  {
    constexpr int n = greens::wallNormalAxis;
    const double h = x0[n];
    const double d[3] = {x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
    double X[3] = {d[0], d[1], d[2]};
    X[n] = x[n] + x0[n];
    const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    const double R2 = X[0] * X[0] + X[1] * X[1] + X[2] * X[2];
    const double invr = 1.0 / std::sqrt(r2);
    const double invR = 1.0 / std::sqrt(R2);
    const double invr3 = invr / r2;
    const double invR3 = invR / R2;
    const double invR5 = invR3 / R2;
    const double Xf = X[0] * f[0] + X[1] * f[1] + X[2] * f[2];
    // The free and image Stokeslets are evaluated with the same association, so that they
    // cancel exactly for a pole on the wall (h = 0, X = xh): G^W = 0 there to the last bit.
    const double free = (d[0] * f[0] + d[1] * f[1] + d[2] * f[2]) * invr3;
    const double image = Xf * invR3;
    for (int j = 0; j < 3; ++j) {
      const double s = greens::imageSign(j);
      const double dipole = s * (f[j] * invR3 - 3.0 * X[j] * Xf * invR5);
      const double doublet = X[n] * dipole + s * ((j == n ? Xf : 0.0) - f[n] * X[j]) * invR3;
      u[j] += (f[j] * invr + d[j] * free) - (f[j] * invR + X[j] * image) + 2.0 * h * h * dipole - 2.0 * h * doublet;
    }
  }

  /// u_j += T^W_ijk v_i a_k with T^W = T(xh) - T(X) + 2 h^2 T^D(X) - 2 h T^SD(X) (Wall3D.hpp):
  ///   T^D_ijk v_i a_k  = 6 s_j (-((v.a) X_j + v_j (X.a) + a_j (X.v)) / R^5 + 5 (X.v)(X.a) X_j / R^7) =: D_j
  ///   T^SD_ijk v_i a_k = X_n D_j + 6 s_j ((v.a) X_j X_n - delta_jn (X.v)(X.a)) / R^5.
  static void addDoubleLayerTerm(const double x[3], const double x0[3], const double v[3], const double a[3],
                                 double u[3])
  {
    constexpr int n = greens::wallNormalAxis;
    const StressletGeometry g(x, x0);
    const double h = g.h, invr5 = g.invr5, invR5 = g.invR5, invR7 = g.invR7;
    const double* d = g.d;
    const double* X = g.X;
    const double dv = d[0] * v[0] + d[1] * v[1] + d[2] * v[2];
    const double da = d[0] * a[0] + d[1] * a[1] + d[2] * a[2];
    const double Xv = X[0] * v[0] + X[1] * v[1] + X[2] * v[2];
    const double Xa = X[0] * a[0] + X[1] * a[1] + X[2] * a[2];
    const double va = v[0] * a[0] + v[1] * a[1] + v[2] * a[2];
    // Same association for the free and image stresslets: exact cancellation at h = 0.
    const double free = -6.0 * dv * da * invr5;
    const double image = 6.0 * Xv * Xa * invR5;
    for (int j = 0; j < 3; ++j) {
      const double s6 = 6.0 * greens::imageSign(j);
      const double dipole = s6 * (-(va * X[j] + v[j] * Xa + a[j] * Xv) * invR5 + 5.0 * Xv * Xa * X[j] * invR7);
      const double doublet = X[n] * dipole + s6 * (va * X[j] * X[n] - (j == n ? Xv * Xa : 0.0)) * invR5;
      u[j] += free * d[j] + image * X[j] + 2.0 * h * h * dipole - 2.0 * h * doublet;
    }
  }

  /// M[3 i + j] += T^W_ijk a_k: the derivative of addDoubleLayerTerm with respect to v_i,
  ///   free  -6 xh_i xh_j (xh.a) / r^5,  image  6 X_i X_j (X.a) / R^5,
  ///   D_ij  = s_j 6 (-(a_i X_j + delta_ij (X.a) + a_j X_i) / R^5 + 5 X_i X_j (X.a) / R^7),
  ///   SD_ij = X_n D_ij + s_j 6 (a_i X_j X_n - delta_jn X_i (X.a)) / R^5.
  static void addDoubleLayerMatrix(const double x[3], const double x0[3], const double a[3], double M[9])
  {
    constexpr int n = greens::wallNormalAxis;
    const StressletGeometry g(x, x0);
    const double h = g.h, invr5 = g.invr5, invR5 = g.invR5, invR7 = g.invR7;
    const double* d = g.d;
    const double* X = g.X;
    const double da = d[0] * a[0] + d[1] * a[1] + d[2] * a[2];
    const double Xa = X[0] * a[0] + X[1] * a[1] + X[2] * a[2];
    // Same association for the free and image stresslets: exact cancellation at h = 0.
    const double free = -6.0 * da * invr5;
    const double image = 6.0 * Xa * invR5;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const double s6 = 6.0 * greens::imageSign(j);
        const double delta = i == j ? Xa : 0.0;
        const double dipole = s6 * (-(a[i] * X[j] + delta + a[j] * X[i]) * invR5 + 5.0 * X[i] * Xa * X[j] * invR7);
        const double doublet = X[n] * dipole + s6 * (a[i] * X[j] * X[n] - (j == n ? X[i] * Xa : 0.0)) * invR5;
        M[3 * i + j] += free * d[i] * d[j] + image * X[i] * X[j] + 2.0 * h * h * dipole - 2.0 * h * doublet;
      }
    }
  }
};

/// The wall's image and fluid domain, as for greens::Wall3D.
template <>
struct KernelTraits<Wall3DKernel> : KernelTraits<greens::Wall3D> {};

} // namespace capsula::operators
