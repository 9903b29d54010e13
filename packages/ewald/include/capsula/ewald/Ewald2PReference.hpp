#pragma once
// Reference sum of the Stokeslet in a layer periodic in x and z (periods L_x, L_z), unbounded in
// y (the "2P" Ewald sum), in the convention of greens/FreeSpace3D.hpp: a force g per cell at x0
// and at its images x0 + (m L_x, 0, n L_z) gives u(x) = G_ij(x - x0) g_j / (8 pi mu), with
//   G(xh) = sum_images G^R(xh + p; xi)
//         + (1/A) sum_{(kx,kz) != 0} e^{i (kx xh_x + kz xh_z)} (1/2pi) int G^F^(k; xi) e^{i ky xh_y} dky
//         + (1/A) h(xh_y) (delta_ij - delta_iy delta_jy),
// k = (kx, ky, kz), (kx, kz) = 2 pi (m / L_x, n / L_z), A = L_x L_z, G^R and G^F^ Hasimoto's split
// (EwaldSplit.hpp) and h the zero mode (ZeroMode2P.hpp: the x-z average of G is
// -4 pi |xh_y| / A on the parallel components, zero at the source's height).
//
// The ky integrals are in closed form: with a = |(kx, kz)|, c = 1/(2 sqrt(pi) xi),
// E+- = e^{+-a y} erfc(a / (2 xi) +- xi y), P = E+ + E-, D = E+ - E-, g = e^{-a^2/(4 xi^2) - xi^2 y^2},
//   J0(y) = (1/2pi) int gamma^(k) / k^4 e^{i ky y} dky = P / (8 a^3) - y D / (8 a^2) + c g / (2 a^2),
//   J0'(y) = -y P / (8 a),   J0''(y) = -P / (8 a) - y D / 8,
// (J0 = -(1/2a) d/da of the 2P Ewald integral (1/4a) P), and per mode
//   parallel-parallel: 8 pi [delta_ij (a^2 J0 - J0'') - k_i k_j J0],  parallel-y: 8 pi i k_i J0',
//   y-y: 8 pi a^2 J0.
// Sums are truncated where the neglected terms fall below the tolerance (ewaldTruncation): the
// images within r_c = sqrt(ln(1/tol)) / xi, the modes with |(kx, kz)| <= 2 xi sqrt(ln(1/tol)).
// The cost is O(modes + images) per pair, so this is the reference for the fast sum and for
// tests, not for many sources.

namespace capsula::ewald {

/// The periods of a layer periodic in x and z and unbounded in y.
struct PeriodicLayer {
  double lengthX = 0.0;
  double lengthZ = 0.0;
};

/// Where a 2P Ewald sum with splitting parameter xi is truncated for a tolerance.
struct EwaldTruncation {
  double xi = 0.0;
  double realCutoff = 0.0;       // images with |xh + p| < realCutoff
  double wavenumberCutoff = 0.0; // modes with |(kx, kz)| <= wavenumberCutoff
};

/// r_c and k_c with e^{-xi^2 r_c^2} = e^{-k_c^2 / (4 xi^2)} = tol e^{-2}: the local part
/// beyond r_c and the modes beyond k_c are below tol (the e^{-2} covers their polynomial
/// prefactors, measured in test_ewald2p_reference).
EwaldTruncation ewaldTruncation(double xi, double tolerance);

/// The periodic Stokeslet G_ij(xh) (header comment); xh not a lattice vector (m L_x, 0, n L_z).
void periodicStokeslet2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double xh[3],
                         double G[3][3]);

/// The local part alone: sum over the images p within r_c of G^R(xh + p; xi).
void periodicStokesletReal2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double xh[3],
                             double G[3][3]);

/// The smooth part alone, zero mode included (the Fourier sum of the header comment).
void periodicStokesletFourier2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double xh[3],
                                double G[3][3]);

/// The ky-integral profiles of one mode: J0 and its first three y-derivatives at height y for
/// |(kx, kz)| = a > 0 (the third, -D/4 - y a P/8 + xi y g / (2 sqrt(pi)), serves the stresslet).
struct ModeProfiles {
  double j0 = 0.0;
  double j0Prime = 0.0;
  double j0Second = 0.0;
  double j0Third = 0.0;
};
ModeProfiles modeProfiles(double a, double y, double xi);

/// The building blocks of the ky integrals at height y for |(kx, kz)| = a > 0 (header comment):
/// P = E+ + E-, D = E+ - E- and g = e^{-a^2/(4 xi^2) - xi^2 y^2}.
struct ModeExponentials {
  double sum = 0.0;        // P
  double difference = 0.0; // D
  double gauss = 0.0;      // g
};
ModeExponentials modeExponentials(double a, double y, double xi);

} // namespace capsula::ewald
