#pragma once
// Blake's kernel of the channel wall nearer to the pole: the local kernel of the periodic
// channel (PeriodicKernels.hpp). For a pole x0 in the lower half of the channel 0 < y < H
// it is the lower wall's (operators::Wall3DKernel); in the upper half it is the upper wall's,
// Blake's kernel in the frame reflected about the mid-plane, y -> H - y:
//   G^U(x, x0) = R G^W(R x, R x0) R,   T^U_ijk(x, x0) = R_ii' R_jj' R_kk' T^W_i'j'k'(R x, R x0),
// R = diag(1, -1, 1) acting on vectors. A reflection maps a Stokes flow and its stress onto a
// Stokes flow, the velocity and the stress transforming as a vector and a tensor, so G^U has
// no slip on y = H as G^W has on y = 0.
// The channel's Green's function minus this kernel is a Stokes flow whose nearest singularity
// is the pole's image in the FAR wall, at least H away from the pole's half, so the special
// rules integrate it as smoothly as the periodic box's remainder.
#include <capsula/operators/ContractedKernels.hpp>

namespace capsula::periodic {

struct NearestWallKernel {
  double height = 0.0; ///< H, the channel's height

  /// true: the pole lies in the upper half, where the upper wall's kernel serves.
  bool upperHalf(const double x0[3]) const { return x0[1] > 0.5 * height; }

  void stokeslet(const double x[3], const double x0[3], double G[3][3]) const
  {
    if (!upperHalf(x0)) {
      operators::Wall3DKernel::stokeslet(x, x0, G);
      return;
    }
    const Frame f(height, x, x0);
    operators::Wall3DKernel::stokeslet(f.x, f.x0, G);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        G[i][j] *= sign(i) * sign(j);
      }
    }
  }
  void stresslet(const double x[3], const double x0[3], double T[3][3][3]) const
  {
    if (!upperHalf(x0)) {
      operators::Wall3DKernel::stresslet(x, x0, T);
      return;
    }
    const Frame f(height, x, x0);
    operators::Wall3DKernel::stresslet(f.x, f.x0, T);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        for (int k = 0; k < 3; ++k) {
          T[i][j][k] *= sign(i) * sign(j) * sign(k);
        }
      }
    }
  }
  void addSingleLayerTerm(const double x[3], const double x0[3], const double f[3], double u[3]) const
  {
    if (!upperHalf(x0)) {
      operators::Wall3DKernel::addSingleLayerTerm(x, x0, f, u);
      return;
    }
    const Frame frame(height, x, x0);
    const double rf[3] = {f[0], -f[1], f[2]};
    double term[3] = {0.0, 0.0, 0.0};
    operators::Wall3DKernel::addSingleLayerTerm(frame.x, frame.x0, rf, term);
    addReflected(term, u);
  }
  void addDoubleLayerTerm(const double x[3], const double x0[3], const double v[3], const double a[3],
                          double u[3]) const
  {
    if (!upperHalf(x0)) {
      operators::Wall3DKernel::addDoubleLayerTerm(x, x0, v, a, u);
      return;
    }
    const Frame frame(height, x, x0);
    const double rv[3] = {v[0], -v[1], v[2]};
    const double ra[3] = {a[0], -a[1], a[2]};
    double term[3] = {0.0, 0.0, 0.0};
    operators::Wall3DKernel::addDoubleLayerTerm(frame.x, frame.x0, rv, ra, term);
    addReflected(term, u);
  }
  void addDoubleLayerMatrix(const double x[3], const double x0[3], const double a[3], double M[9]) const
  {
    if (!upperHalf(x0)) {
      operators::Wall3DKernel::addDoubleLayerMatrix(x, x0, a, M);
      return;
    }
    const Frame frame(height, x, x0);
    const double ra[3] = {a[0], -a[1], a[2]};
    double term[9] = {};
    operators::Wall3DKernel::addDoubleLayerMatrix(frame.x, frame.x0, ra, term);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        M[3 * i + j] += sign(i) * sign(j) * term[3 * i + j];
      }
    }
  }

private:
  /// The field point and the pole in the reflected frame, where the upper wall is y = 0.
  struct Frame {
    double x[3], x0[3];
    Frame(double height, const double field[3], const double pole[3])
        : x{field[0], height - field[1], field[2]}, x0{pole[0], height - pole[1], pole[2]}
    {}
  };
  static double sign(int i) { return i == 1 ? -1.0 : 1.0; }
  static void addReflected(const double term[3], double u[3])
  {
    u[0] += term[0];
    u[1] -= term[1];
    u[2] += term[2];
  }
};

} // namespace capsula::periodic
