#pragma once
// Spectral Ewald fast sum of the Stokeslet in a layer periodic in x and z, unbounded in y
// (Lindbo & Tornberg 2011 J Comput Phys 230; for the free direction cf. their 2012 J Chem Phys
// 2P method, here plain padding plus the exact 1D zero mode): for sources x_n with forces g_n
// and targets x_t,
//   u_t = sum_n G(x_t - x_n) g_n        (G units: the velocity is u_t / (8 pi mu)),
// G the periodic Stokeslet of Ewald2PReference.hpp (its zero mode included). A target on a
// source takes from it lim_{xh -> 0} (G(xh) - G_free(xh)) g_n: the field of its images.
//
// Local part: G^R (EwaldSplit.hpp) over the images within r_c, with a cell list: O(N) for fixed
// xi. Smooth part: the forces are spread with Gaussians e^{-2 xi^2 r^2 / eta} onto a uniform grid
// periodic in x and z and padded in y, FFT'd (FFTW), multiplied by
//   8 pi (delta k^2 - k k) / k^4 (1 + k^2/(4 xi^2)) e^{-(1 - eta) k^2 / (4 xi^2)},
// transformed back and gathered with the same Gaussians. The grid spans the points' heights
// plus the Gaussians' support in y; the FFT in x and z runs on each of its y-levels, and each
// mode (k_x, k_z) != 0, a = |(k_x, k_z)|, is then a 1D convolution in y, done by an FFT over the
// levels padded with zeros to a period of its own: long enough that the nearest y-image of the
// spread data lies d(a) beyond it, (1 + a d) e^{-a d} = tol (the ky-integral's kernel decays
// like that). Only the few modes with small a need long periods (d ~ ln(1/tol) / a), so a wide
// flat layer costs N log N, where one period for all modes (that of the lowest a = 2 pi / L)
// would grow the grid like L^3 for N ~ L^2 points (the padded FFT of Lindbo & Tornberg's 2P
// method does the same for the zero mode's neighbourhood). The mode (k_x, k_z) = 0 is the
// exact 1D problem (ZeroMode2P.hpp): the x-z sums of the spread forces convolved in y, directly
// on the grid, with the kernel whose transform is 8 pi (1 + k^2/(4 xi^2)) e^{-(1-eta) k^2/(4 xi^2)} / k^2.
//
// The tolerance rule (tol relative to the largest velocity; spectralEwaldSettings), L = ln(1/tol):
//   r_c = sqrt(L + 2) / xi: the local part beyond r_c is below tol (as in Ewald2PReference);
//   grid spacing h <= pi / k_c, k_c = 2 xi sqrt(L + 6): the modes beyond the grid's are below tol;
//   P = ceil(2 L / pi) + 4 grid spacings across a Gaussian, m = 0.95 sqrt(pi P),
//   eta = (P h xi / m)^2 (kept below 0.9 by a smaller h): cutting and sampling the Gaussians
//   cost ~e^{-pi P / 2} (Lindbo & Tornberg's estimate);
//   each mode's y-period: the nearest y-image of the spread data d away, (1 + a d) e^{-a d} = tol;
// and xi, unless given, such that a target has about `neighbours` sources within r_c when the
// sources fill the cell area times their height range (at least a tenth of the shorter period).
// The margins (+6, +4) were measured: the largest error is 0.05-0.1 tol for tol = 1e-3..1e-8
// (test_spectral_ewald2p), and at most 0.3 tol for tol down to 1e-10 and xi up to twice the
// rule's. Grid points then grow like N for a fixed tolerance and the cost like N log N (the
// FFT), the local part like N.
#include "capsula/ewald/Ewald2PReference.hpp"

#include <vector>

namespace capsula::ewald {

/// Everything the fast sum needs, derived from the tolerance (header comment).
struct SpectralEwaldSettings {
  double xi = 0.0;
  double realCutoff = 0.0;
  double eta = 0.0;
  double gaussianExponent = 0.0; // 2 xi^2 / eta
  double supportRadius = 0.0;    // w: the Gaussians are cut beyond |x - x_n| = w along each axis
  int supportPoints = 0;         // P
  int gridX = 0, gridZ = 0;
  int gridY = 0; // the y-levels spanning the heights plus the support (each mode pads its own period)
  double spacingX = 0.0, spacingY = 0.0, spacingZ = 0.0;
  double yOrigin = 0.0;   // height of the grid's first y-plane
  double tolerance = 0.0; // sets each mode's y-period (yImagePadding)
};

/// d with (1 + a d) e^{-a d} = tol: how far beyond the spread data the nearest y-image of a mode
/// of wavenumber a must lie.
double yImagePadding(double a, double tolerance);

/// The y-period, in grid levels (a fast FFT size), of the mode of wavenumber a > 0.
int yPeriodLevels(const SpectralEwaldSettings& settings, double a);

/// The settings for points with heights in [yMin, yMax]; xi <= 0 picks xi by the neighbour rule.
SpectralEwaldSettings spectralEwaldSettings(const PeriodicLayer& layer, double tolerance, double yMin, double yMax,
                                            int sourceCount, double xi = 0.0, int neighbours = 300);

/// The settings for these sources and targets (their heights' range and the sources' number).
SpectralEwaldSettings spectralEwaldSettingsFor(const PeriodicLayer& layer, double tolerance,
                                               const std::vector<double>& sources, const std::vector<double>& targets,
                                               double xi = 0.0);

/// The local part: u_t += sum over sources and images within r_c of G^R(x_t - x_n - p) g_n
/// (a coincident pair gives lim (G^R - G_free) g_n = -4 xi / sqrt(pi) g_n). Positions and forces are 3 per point.
void addLocalPart2P(const PeriodicLayer& layer, const SpectralEwaldSettings& settings,
                    const std::vector<double>& sources, const std::vector<double>& forces,
                    const std::vector<double>& targets, std::vector<double>& velocities);

/// The smooth part, zero mode included: u_t += sum_n G^F-sum(x_t - x_n) g_n.
void addSmoothPart2P(const PeriodicLayer& layer, const SpectralEwaldSettings& settings,
                     const std::vector<double>& sources, const std::vector<double>& forces,
                     const std::vector<double>& targets, std::vector<double>& velocities);

/// u_t = sum_n G(x_t - x_n) g_n to the tolerance (header comment); xi <= 0 picks it.
std::vector<double> spectralEwald2P(const PeriodicLayer& layer, double tolerance, const std::vector<double>& sources,
                                    const std::vector<double>& forces, const std::vector<double>& targets,
                                    double xi = 0.0);

} // namespace capsula::ewald
