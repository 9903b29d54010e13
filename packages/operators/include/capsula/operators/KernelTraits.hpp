#pragma once
// What the operators ask of a Green's function policy (a struct like greens::FreeSpace3D
// with stokeslet(x, x0, G[3][3]) and stresslet(x, x0, T[3][3][3]); x the field point, here
// the integration point, x0 the pole, here the target) beyond those two. The operators hold
// a policy INSTANCE and call every function through it, so a policy may carry run-time
// state (the periods of a periodic box); the built-in policies are empty structs whose
// static members are called through the instance:
//
//  - contracted evaluation in the inner loops: u_j += G_ij(x, x0) f_i (single layer) and
//    u_j += T_ijk(x, x0) v_i a_k (double layer). A policy may provide them as
//        void addSingleLayerTerm(const double x[3], const double x0[3],
//                                const double f[3], double u[3]) const;
//        void addDoubleLayerTerm(const double x[3], const double x0[3],
//                                const double v[3], const double a[3], double u[3]) const;
//    (static or const members) and they are used; otherwise the full tensors are
//    contracted here. Likewise the double-layer matrix of one source point,
//    M_ij += T_ijk(x, x0) a_k, for the special rules (ElementIntegrals.hpp):
//        void addDoubleLayerMatrix(const double x[3], const double x0[3],
//                                  const double a[3], double M[9]) const;
//  - images: points outside the fluid, or in the neighbouring periodic boxes, where the
//    kernel is singular too (Blake's image of the pole below the wall, the pole's periodic
//    images); the near-singular test measures from them as well.
//  - the nearest image of a point to a reference point (the point itself unless the kernel
//    is periodic): the near-singular test shifts the pole next to each cell first, so cells
//    whose positions were never folded into the box are still found.
//  - the fluid domain: where a pole (a target) may lie, and where the kernel vanishes
//    identically (a pole on a no-slip wall), which needs no near-singular treatment.
//
// These are KernelTraits<Policy>, made from the policy instance by kernelTraits(policy).
// A new kernel specialises KernelTraits only if it has images, a bounded domain or periods;
// a specialisation with state is constructible from `const Policy&`.
#include <capsula/greens/Wall3D.hpp>

#include <type_traits>
#include <utility>

namespace capsula::operators {

namespace detail {

template <class Kernel, class = void>
struct HasSingleLayerTerm : std::false_type {};
template <class Kernel>
struct HasSingleLayerTerm<Kernel, std::void_t<decltype(std::declval<const Kernel&>().addSingleLayerTerm(
                                      std::declval<const double*>(), std::declval<const double*>(),
                                      std::declval<const double*>(), std::declval<double*>()))>> : std::true_type {};

template <class Kernel, class = void>
struct HasDoubleLayerTerm : std::false_type {};
template <class Kernel>
struct HasDoubleLayerTerm<Kernel,
                          std::void_t<decltype(std::declval<const Kernel&>().addDoubleLayerTerm(
                              std::declval<const double*>(), std::declval<const double*>(),
                              std::declval<const double*>(), std::declval<const double*>(), std::declval<double*>()))>>
    : std::true_type {};

template <class Kernel, class = void>
struct HasDoubleLayerMatrix : std::false_type {};
template <class Kernel>
struct HasDoubleLayerMatrix<Kernel, std::void_t<decltype(std::declval<const Kernel&>().addDoubleLayerMatrix(
                                        std::declval<const double*>(), std::declval<const double*>(),
                                        std::declval<const double*>(), std::declval<double*>()))>> : std::true_type {};

} // namespace detail

/// u_j += G_ij(x, x0) f_i: the velocity at the pole x0 of the force f at x (reciprocity).
template <class Kernel>
inline void addSingleLayerTerm(const Kernel& kernel, const double x[3], const double x0[3], const double f[3],
                               double u[3])
{
  if constexpr (detail::HasSingleLayerTerm<Kernel>::value) {
    kernel.addSingleLayerTerm(x, x0, f, u);
  } else {
    double G[3][3];
    kernel.stokeslet(x, x0, G);
    for (int j = 0; j < 3; ++j) {
      u[j] += G[0][j] * f[0] + G[1][j] * f[1] + G[2][j] * f[2];
    }
  }
}

/// u_j += T_ijk(x, x0) v_i a_k, with a = n dS the weighted normal at x.
template <class Kernel>
inline void addDoubleLayerTerm(const Kernel& kernel, const double x[3], const double x0[3], const double v[3],
                               const double a[3], double u[3])
{
  if constexpr (detail::HasDoubleLayerTerm<Kernel>::value) {
    kernel.addDoubleLayerTerm(x, x0, v, a, u);
  } else {
    double T[3][3][3];
    kernel.stresslet(x, x0, T);
    for (int j = 0; j < 3; ++j) {
      double sum = 0.0;
      for (int i = 0; i < 3; ++i) {
        sum += v[i] * (T[i][j][0] * a[0] + T[i][j][1] * a[1] + T[i][j][2] * a[2]);
      }
      u[j] += sum;
    }
  }
}

/// M[3 i + j] += T_ijk(x, x0) a_k, with a = n dS the weighted normal at x.
template <class Kernel>
inline void addDoubleLayerMatrix(const Kernel& kernel, const double x[3], const double x0[3], const double a[3],
                                 double M[9])
{
  if constexpr (detail::HasDoubleLayerMatrix<Kernel>::value) {
    kernel.addDoubleLayerMatrix(x, x0, a, M);
  } else {
    double T[3][3][3];
    kernel.stresslet(x, x0, T);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        M[3 * i + j] += T[i][j][0] * a[0] + T[i][j][1] * a[1] + T[i][j][2] * a[2];
      }
    }
  }
}

/// The three contractions for a policy without state (the built-in ones): called through a
/// default instance.
template <class Kernel>
inline void addSingleLayerTerm(const double x[3], const double x0[3], const double f[3], double u[3])
{
  static_assert(std::is_empty_v<Kernel>, "a policy with state is called through its instance");
  addSingleLayerTerm(Kernel{}, x, x0, f, u);
}
template <class Kernel>
inline void addDoubleLayerTerm(const double x[3], const double x0[3], const double v[3], const double a[3], double u[3])
{
  static_assert(std::is_empty_v<Kernel>, "a policy with state is called through its instance");
  addDoubleLayerTerm(Kernel{}, x, x0, v, a, u);
}
template <class Kernel>
inline void addDoubleLayerMatrix(const double x[3], const double x0[3], const double a[3], double M[9])
{
  static_assert(std::is_empty_v<Kernel>, "a policy with state is called through its instance");
  addDoubleLayerMatrix(Kernel{}, x, x0, a, M);
}

/// What every kernel without periods shares: a point is its own nearest image.
struct AperiodicKernelTraits {
  /// Writes to `image` the periodic image of x nearest to `reference` (x itself here).
  static void nearestImage(const double* x, const double* /*reference*/, double* image)
  {
    for (int i = 0; i < 3; ++i) {
      image[i] = x[i];
    }
  }
};

/// Defaults: no images, the fluid fills space.
template <class Kernel>
struct KernelTraits : AperiodicKernelTraits {
  static constexpr int maxImages = 0;
  /// Writes the image points of pole x0 to `images` and returns how many.
  static int images(const double* /*x0*/, double (* /*images*/)[3]) { return 0; }
  /// Whether x0 lies in the fluid domain of the kernel (closure included).
  static bool inFluid(const double* /*x0*/) { return true; }
  /// Whether the kernel vanishes identically for the pole x0 (no near-singular treatment).
  static bool vanishesAt(const double* /*x0*/) { return false; }
};

/// Blake's wall y = 0, fluid y > 0: one image, the mirror point of the pole.
template <>
struct KernelTraits<greens::Wall3D> : AperiodicKernelTraits {
  static constexpr int maxImages = 1;
  static int images(const double* x0, double (*images)[3])
  {
    for (int i = 0; i < 3; ++i) {
      images[0][i] = x0[i];
    }
    images[0][greens::wallNormalAxis] = -x0[greens::wallNormalAxis];
    return 1;
  }
  static bool inFluid(const double* x0) { return x0[greens::wallNormalAxis] >= 0.0; }
  /// A pole on the wall: every image cancels its source (no-slip), G = T = 0.
  static bool vanishesAt(const double* x0) { return x0[greens::wallNormalAxis] == 0.0; }
};

/// The traits of the policy instance `kernel`: made from it when KernelTraits<Kernel> keeps
/// state of the kernel (a periodic box), default-constructed otherwise.
template <class Kernel>
KernelTraits<Kernel> kernelTraits(const Kernel& kernel)
{
  if constexpr (std::is_constructible_v<KernelTraits<Kernel>, const Kernel&>) {
    return KernelTraits<Kernel>(kernel);
  } else {
    (void)kernel;
    return KernelTraits<Kernel>{};
  }
}

} // namespace capsula::operators
