#pragma once
// The regular (far-field) sums of the periodic kernels (PeriodicKernels.hpp) by the spectral
// Ewald method of capsula::ewald, to the kernel's tolerance (relative to the largest
// velocity):
//  - single layer: u_t = sum_q G(x_t, x_q) f_q over every quadrature point of every cell,
//    G the periodic Stokeslet (SpectralEwald2P), the periodic wall's (SpectralEwaldWall2P)
//    or the periodic channel's (SpectralEwaldChannel2P);
//  - double layer: u_t,j = sum_q T_ijk(x_q, x_t) v_q,i a_q,k, T the stress at x_q of a force at
//    the target: in the periodic fluid -sum_q T_jik(x_t - x_q) (v_q a_q)_ik (T odd and
//    symmetric), one stresslet sum (SpectralEwaldStresslet2P) with the source tensors
//    S_q = v_q a_q^T; above the wall and in the channel the fast double layers of their
//    stresslets (SpectralEwaldWallStresslet2P, SpectralEwaldChannelStresslet2P) with the same
//    tensors. The singularity subtraction on a target's own cell (FarFieldSummation.hpp) is then
//      - s_t sum_{q in own cell} T(x_q, x_t) a_q,
//    summed directly per cell with the LOCAL kernel (free space, Blake's, the nearer wall's
//    Blake) in the cell's own, unfolded coordinates: the periodic T minus the local one is
//    the stress of a Stokes flow without a singularity inside the cell, whose integral of
//    T n over the closed surface is zero, so the difference is the regular rule's error on a
//    smooth integrand.
//    It is linear in s_t with a 3x3 matrix per target that depends on the geometry alone,
//    B_t,ij = sum_{q in own cell} T_ijk(x_q, x_t) a_q,k, so B is summed once per geometry and
//    set of targets (three direct passes, s_t = e_1, e_2, e_3) and each later application
//    (the iterations of a GMRES solve) costs 9 products per target instead of a sum over the
//    cell's points: with 16 level-2 cells at lambda = 5 the direct pass took 18% of the
//    evaluation's samples (perf) when it ran at every application.
// Every rank sums all sources for its own targets, as the direct sums and the treecode do;
// positions are folded into the box first (the sums are periodic).
#include <capsula/operators/FarFieldSummation.hpp>
#include <capsula/periodic/PeriodicKernels.hpp>

#include <string>
#include <vector>

namespace capsula::periodic {

/// The walls of the periodic fluid whose Green's function the sums use.
enum class PeriodicFluid {
  Unbounded, ///< no wall
  AboveWall, ///< the wall y = 0
  Channel    ///< the walls y = 0 and y = H
};

class PeriodicFarField final : public operators::FarFieldSummation {
public:
  /// `channelHeight`: H for PeriodicFluid::Channel (ignored otherwise).
  PeriodicFarField(const PeriodicBox& box, double tolerance, PeriodicFluid fluid, double channelHeight = 0.0);

  std::string name() const override { return "Spectral Ewald"; }
  void setSources(const double* x, const double* y, const double* z, const std::vector<int>& cellPointOffsets) override;
  void singleLayer(const operators::SingleLayerSources& sources, const double* targets, int n, double* result) override;
  void doubleLayer(const operators::DoubleLayerSources& sources, const double* targets, const int* targetCells,
                   const double* subtracted, int n, double* result) override;

private:
  std::vector<double> foldedTargets(const double* targets, int n) const;
  // -B_t,ij at [9 t + 3 i + j] (the subtraction's term j for s_t = e_i) for these targets,
  // summed on the first call after setSources or with other targets, then reused.
  const std::vector<double>& ownCellBlocks(const operators::DoubleLayerSources& sources, const double* targets,
                                           const int* targetCells, int n);

  PeriodicBox box_;
  double tolerance_;
  PeriodicFluid fluid_;
  double channelHeight_;
  const double *x_ = nullptr, *y_ = nullptr, *z_ = nullptr;
  std::vector<int> offsets_;
  std::vector<double> folded_;     // the sources folded into the box, 3 per point
  std::vector<double> ownTargets_; // the targets and cells ownBlocks_ holds the blocks of
  std::vector<int> ownTargetCells_;
  std::vector<double> ownBlocks_;
};

} // namespace capsula::periodic
