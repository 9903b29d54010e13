#include "capsula/scene2d/RegularSums2D.hpp"

#include <algorithm>

namespace capsula::scene2d {

namespace {

// Clones of a function declared in a header need their definition in every caller's
// translation unit; these are local and the public functions forward to them. The pair
// formula is a template argument, not a function pointer, so that it inlines into the
// loop: one loop serves the wall and the free-space kernels.
using StokesletPair2D = void (*)(double, double, double, double, double, double, double&, double&);

template <StokesletPair2D addPair>
CAPSULA_KERNEL_CLONES void stokesletSums(const double* px, const double* py, const double* fx, const double* fy,
                                         int pointsPerSegment, int numSegments, const double* tx, const double* ty,
                                         int paddedTargets, const double* mask, double* ux, double* uy)
{
  for (int k = 0; k < numSegments; ++k) {
    const double* use = mask + static_cast<long>(k) * paddedTargets;
    for (int p = k * pointsPerSegment; p < (k + 1) * pointsPerSegment; ++p) {
      const double x = px[p], y = py[p], f0 = fx[p], f1 = fy[p];
      for (int t = 0; t < paddedTargets; ++t) {
        double u0 = 0.0, u1 = 0.0;
        addPair(x, y, f0, f1, tx[t], ty[t], u0, u1);
        ux[t] += use[t] * u0;
        uy[t] += use[t] * u1;
      }
    }
  }
}

template <StokesletPair2D addPair>
CAPSULA_KERNEL_CLONES void stokesletPairs(const double* __restrict x, const double* __restrict y,
                                          const double* __restrict fx, const double* __restrict fy,
                                          const double* __restrict x0, const double* __restrict y0, int count,
                                          double* __restrict ux, double* __restrict uy)
{
  for (int i = 0; i < count; ++i) {
    double u0 = 0.0, u1 = 0.0;
    addPair(x[i], y[i], fx[i], fy[i], x0[i], y0[i], u0, u1);
    ux[i] = u0;
    uy[i] = u1;
  }
}

CAPSULA_KERNEL_CLONES void markNear(const double* segments, const double* reach2, int numSegments, const double* tx,
                                    const double* ty, int paddedTargets, bool withImage, double* mask)
{
  const double imageSign = withImage ? -1.0 : 1.0;
  for (int k = 0; k < numSegments; ++k) {
    const double ax = segments[6 * k], ay = segments[6 * k + 1], mx = segments[6 * k + 2];
    const double my = segments[6 * k + 3], bx = segments[6 * k + 4], by = segments[6 * k + 5];
    const double r2 = reach2[k];
    double* use = mask + static_cast<long>(k) * paddedTargets;
    for (int t = 0; t < paddedTargets; ++t) {
      const double x0 = tx[t], y0 = ty[t], yi = imageSign * ty[t];
      const double da = (x0 - ax) * (x0 - ax), dm = (x0 - mx) * (x0 - mx), db = (x0 - bx) * (x0 - bx);
      const double pa = da + (y0 - ay) * (y0 - ay), pm = dm + (y0 - my) * (y0 - my), pb = db + (y0 - by) * (y0 - by);
      const double ia = da + (yi - ay) * (yi - ay), im = dm + (yi - my) * (yi - my), ib = db + (yi - by) * (yi - by);
      // Branch-free (the vectorised loop has no early exits); without an image, yi = y0.
      const double pole = std::min(std::min(pa, pm), pb);
      const double image = std::min(std::min(ia, im), ib);
      use[t] = std::min(pole, image) < r2 ? 0.0 : 1.0;
    }
  }
}

} // namespace

void wallStokesletPairs2D(const double* x, const double* y, const double* fx, const double* fy, const double* x0,
                          const double* y0, int count, double* ux, double* uy)
{
  stokesletPairs<addWallStokesletPair2D>(x, y, fx, fy, x0, y0, count, ux, uy);
}

void freeSpaceStokesletPairs2D(const double* x, const double* y, const double* fx, const double* fy, const double* x0,
                               const double* y0, int count, double* ux, double* uy)
{
  stokesletPairs<addFreeSpaceStokesletPair2D>(x, y, fx, fy, x0, y0, count, ux, uy);
}

void markNearSegments2D(const double* segments, const double* reach2, int numSegments, const double* tx,
                        const double* ty, int paddedTargets, bool withImage, double* mask)
{
  markNear(segments, reach2, numSegments, tx, ty, paddedTargets, withImage, mask);
}

void addWallStokesletSums2D(const double* px, const double* py, const double* fx, const double* fy,
                            int pointsPerSegment, int numSegments, const double* tx, const double* ty,
                            int paddedTargets, const double* mask, double* ux, double* uy)
{
  stokesletSums<addWallStokesletPair2D>(px, py, fx, fy, pointsPerSegment, numSegments, tx, ty, paddedTargets, mask, ux,
                                        uy);
}

void addFreeSpaceStokesletSums2D(const double* px, const double* py, const double* fx, const double* fy,
                                 int pointsPerSegment, int numSegments, const double* tx, const double* ty,
                                 int paddedTargets, const double* mask, double* ux, double* uy)
{
  stokesletSums<addFreeSpaceStokesletPair2D>(px, py, fx, fy, pointsPerSegment, numSegments, tx, ty, paddedTargets, mask,
                                             ux, uy);
}

} // namespace capsula::scene2d
