#pragma once
// The doubly periodic Green's functions as operator policies (operators/KernelTraits.hpp):
// PeriodicFreeSpaceKernel, the Stokeslet of a fluid periodic in x and z and unbounded in y
// (ewald/Ewald2PReference.hpp); PeriodicWallKernel, the same above the no-slip plane y = 0
// (ewald/WallStokeslet2P.hpp); PeriodicChannelKernel, the same between the no-slip planes
// y = 0 and y = H (ewald/ChannelStokeslet2P.hpp). A policy instance carries the periods, the
// channel's height and the tolerance of its Ewald sums.
//
// The two halves of the operators get two different kernels:
//  - the regular (far-field) sums over every quadrature point are the periodic Green's
//    function itself, summed by the spectral Ewald method (PeriodicFarField.hpp,
//    farFieldSummation());
//  - the pointwise kernel (stokeslet, stresslet and their contractions), which only the
//    singular and near-singular corrections "special rule minus regular rule" evaluate, is
//    the free-space (Blake's, above the wall; in the channel Blake's of the wall nearer to
//    the pole, NearestWallKernel.hpp) kernel of the periodic image of the field point
//    NEAREST to the pole.
// Why that is right: the periodic Green's function minus the nearest-image local kernel
// solves the homogeneous Stokes equations wherever no other image of the pole lies, so it
// is smooth within half a period of the pole; the special rules integrate that smooth
// remainder to the accuracy of the regular rule, and its correction (special - regular)
// is at the level of the regular rule's error. The corrected element integrals are thus
// those of the periodic kernel, as the element's own singular part is integrated exactly.
// The images (KernelTraits) are the pole's images in the eight neighbouring boxes (and,
// above a wall, the mirror points of all nine in the wall of the local kernel), so that a target near a cell across the
// periodic boundary gets its near-singular treatment; nearestImage shifts the pole next
// to each cell first, so cell positions are never folded into the box.
#include <capsula/operators/ContractedKernels.hpp>
#include <capsula/operators/FarFieldSummation.hpp>
#include <capsula/operators/KernelTraits.hpp>
#include <capsula/periodic/NearestWallKernel.hpp>

#include <cmath>
#include <memory>

namespace capsula::periodic {

/// The periods L_x, L_z (both > 0) of the box [0, L_x) x R x [0, L_z) and the lattice's
/// nearest-image arithmetic (vectorisable: no branch).
struct PeriodicBox {
  double lengthX = 0.0;
  double lengthZ = 0.0;

  /// d minus the lattice vector that brings it into [-L/2, L/2] along x and z.
  void wrap(double d[3]) const
  {
    d[0] -= lengthX * std::nearbyint(d[0] / lengthX);
    d[2] -= lengthZ * std::nearbyint(d[2] / lengthZ);
  }
  /// The image of the field point x nearest to the pole x0 (its height unchanged).
  void nearestField(const double x[3], const double x0[3], double image[3]) const
  {
    double d[3] = {x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
    wrap(d);
    image[0] = x0[0] + d[0];
    image[1] = x[1];
    image[2] = x0[2] + d[2];
  }
  /// x moved by a lattice vector into [0, L_x) x R x [0, L_z).
  void fold(const double x[3], double folded[3]) const
  {
    folded[0] = x[0] - lengthX * std::floor(x[0] / lengthX);
    folded[1] = x[1];
    folded[2] = x[2] - lengthZ * std::floor(x[2] / lengthZ);
  }
};

/// What the periodic policies share, over the local (non-periodic) policy `Local`.
template <class Local>
struct PeriodicKernel {
  PeriodicBox box;
  Local local{};
  /// Of the spectral Ewald sums, relative to the largest velocity ('Operator/<name>/Tolerance').
  double tolerance = 1e-6;

  void stokeslet(const double x[3], const double x0[3], double G[3][3]) const
  {
    double image[3];
    box.nearestField(x, x0, image);
    local.stokeslet(image, x0, G);
  }
  void stresslet(const double x[3], const double x0[3], double T[3][3][3]) const
  {
    double image[3];
    box.nearestField(x, x0, image);
    local.stresslet(image, x0, T);
  }
  void addSingleLayerTerm(const double x[3], const double x0[3], const double f[3], double u[3]) const
  {
    double image[3];
    box.nearestField(x, x0, image);
    local.addSingleLayerTerm(image, x0, f, u);
  }
  void addDoubleLayerTerm(const double x[3], const double x0[3], const double v[3], const double a[3],
                          double u[3]) const
  {
    double image[3];
    box.nearestField(x, x0, image);
    local.addDoubleLayerTerm(image, x0, v, a, u);
  }
  void addDoubleLayerMatrix(const double x[3], const double x0[3], const double a[3], double M[9]) const
  {
    double image[3];
    box.nearestField(x, x0, image);
    local.addDoubleLayerMatrix(image, x0, a, M);
  }
};

/// The Stokeslet of a fluid periodic in x and z, unbounded in y ('Operator/Kernel' = Periodic).
struct PeriodicFreeSpaceKernel : PeriodicKernel<operators::FreeSpace3DKernel> {
  static constexpr const char* name = "periodic free space";
  /// The spectral Ewald sums of the Stokeslet and the stresslet (PeriodicFarField.hpp).
  std::unique_ptr<operators::FarFieldSummation> farFieldSummation() const;
};

/// The Stokeslet above the no-slip plane y = 0, periodic in x and z ('Operator/Kernel' =
/// PeriodicWall).
struct PeriodicWallKernel : PeriodicKernel<operators::Wall3DKernel> {
  static constexpr const char* name = "periodic lower wall";
  /// The spectral Ewald sums of the wall's Stokeslet and stresslet (PeriodicFarField.hpp).
  std::unique_ptr<operators::FarFieldSummation> farFieldSummation() const;
};

/// The Stokeslet of the channel 0 < y < H between no-slip planes, periodic in x and z
/// ('Operator/Kernel' = PeriodicChannel); `local.height` is H.
struct PeriodicChannelKernel : PeriodicKernel<NearestWallKernel> {
  static constexpr const char* name = "periodic channel";
  /// The spectral Ewald sums of the channel's Stokeslet and stresslet (PeriodicFarField.hpp).
  std::unique_ptr<operators::FarFieldSummation> farFieldSummation() const;
};

/// The images of a pole in the eight boxes around its own, and the nearest image.
class PeriodicImages {
public:
  explicit PeriodicImages(const PeriodicBox& box) : box_(box) {}

  static constexpr int count = 8;
  /// Writes x0 + (i L_x, 0, k L_z), (i, k) in {-1, 0, 1}^2 \ (0, 0), to images; returns 8.
  int images(const double* x0, double (*images)[3]) const
  {
    int n = 0;
    for (int i = -1; i <= 1; ++i) {
      for (int k = -1; k <= 1; ++k) {
        if (i == 0 && k == 0) {
          continue;
        }
        images[n][0] = x0[0] + i * box_.lengthX;
        images[n][1] = x0[1];
        images[n][2] = x0[2] + k * box_.lengthZ;
        ++n;
      }
    }
    return n;
  }
  void nearestImage(const double* x, const double* reference, double* image) const
  {
    box_.nearestField(x, reference, image);
  }

private:
  PeriodicBox box_;
};

} // namespace capsula::periodic

namespace capsula::operators {

/// The periodic fluid: the pole's images in the neighbouring boxes; the fluid fills space.
template <>
struct KernelTraits<periodic::PeriodicFreeSpaceKernel> : periodic::PeriodicImages {
  explicit KernelTraits(const periodic::PeriodicFreeSpaceKernel& kernel) : PeriodicImages(kernel.box) {}
  static constexpr int maxImages = periodic::PeriodicImages::count;
  static bool inFluid(const double* /*x0*/) { return true; }
  static bool vanishesAt(const double* /*x0*/) { return false; }
};

/// Above the periodic wall: the pole's images in the neighbouring boxes and the mirror
/// points of all nine below the wall.
template <>
struct KernelTraits<periodic::PeriodicWallKernel> : periodic::PeriodicImages {
  explicit KernelTraits(const periodic::PeriodicWallKernel& kernel) : PeriodicImages(kernel.box) {}
  static constexpr int maxImages = 2 * periodic::PeriodicImages::count + 1;
  int images(const double* x0, double (*out)[3]) const
  {
    const int n = PeriodicImages::images(x0, out);
    for (int p = 0; p <= n; ++p) {
      const double* source = p == 0 ? x0 : out[p - 1];
      KernelTraits<greens::Wall3D>::images(source, out + n + p);
    }
    return 2 * n + 1;
  }
  static bool inFluid(const double* x0) { return KernelTraits<greens::Wall3D>::inFluid(x0); }
  static bool vanishesAt(const double* x0) { return KernelTraits<greens::Wall3D>::vanishesAt(x0); }
};

/// In the periodic channel: the pole's images in the neighbouring boxes and the mirror points
/// of all nine in the wall whose kernel serves the pole (NearestWallKernel.hpp).
template <>
struct KernelTraits<periodic::PeriodicChannelKernel> : periodic::PeriodicImages {
  explicit KernelTraits(const periodic::PeriodicChannelKernel& kernel)
      : PeriodicImages(kernel.box), walls_(kernel.local)
  {}
  static constexpr int maxImages = 2 * periodic::PeriodicImages::count + 1;
  int images(const double* x0, double (*out)[3]) const
  {
    const int n = PeriodicImages::images(x0, out);
    const double mirror = walls_.upperHalf(x0) ? 2.0 * walls_.height : 0.0;
    for (int p = 0; p <= n; ++p) {
      const double* source = p == 0 ? x0 : out[p - 1];
      out[n + p][0] = source[0];
      out[n + p][1] = mirror - source[1];
      out[n + p][2] = source[2];
    }
    return 2 * n + 1;
  }
  bool inFluid(const double* x0) const { return x0[1] >= 0.0 && x0[1] <= walls_.height; }
  /// A pole on either wall: the channel's G and T vanish there (no slip).
  bool vanishesAt(const double* x0) const { return x0[1] == 0.0 || x0[1] == walls_.height; }

private:
  periodic::NearestWallKernel walls_;
};

} // namespace capsula::operators
