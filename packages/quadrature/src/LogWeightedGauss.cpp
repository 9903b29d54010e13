#include <capsula/quadrature/LogWeightedGauss.hpp>

#include <capsula/core/Error.hpp>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <utility>
#include <vector>

namespace capsula::quadrature {
namespace {

// The recurrence, the Newton polish and the Christoffel sums run in extended precision
// (80-bit on x86-64): in double, rounding in the modified Chebyshev algorithm cost up to
// 1e-13 relative in the smallest node and the smallest weights at n = 60.
using Real = long double;

// Recurrence coefficients of the monic shifted Legendre polynomials on [0, 1],
// pi_{l+1} = (x - a_l) pi_l - b_l pi_{l-1}: the basis of the modified moments.
Real legendreA(int /*l*/)
{
  return 0.5L;
}
Real legendreB(int l)
{
  return Real(l) * l / (4.0L * (4.0L * l * l - 1.0L));
}

// Modified moments nu_l = int_0^1 -ln(x) pi_l(x) dx, l = 0 .. count-1. With
// pi_l = P_l(2x - 1) (l!)^2 / (2l)!  and  int_0^1 -ln(x) P_l(2x - 1) dx = (-1)^l / (l (l+1))
// for l >= 1 (= 1 for l = 0). Exact closed forms: no cancellation enters here.
std::vector<Real> modifiedMoments(int count)
{
  std::vector<Real> nu(count);
  nu[0] = 1.0L;
  Real monicScale = 1.0L; // (l!)^2 / (2l)!
  for (int l = 1; l < count; ++l) {
    monicScale *= l / (2.0L * (2.0L * l - 1.0L));
    const Real sign = (l % 2 == 0) ? 1.0L : -1.0L;
    nu[l] = sign * monicScale / (l * (l + 1.0L));
  }
  return nu;
}

struct Recurrence {
  std::vector<Real> alpha; // alpha_0 .. alpha_{n-1}
  std::vector<Real> beta;  // beta_0 = int w, beta_1 .. beta_{n-1}
};

// Gautschi's modified Chebyshev algorithm: recurrence coefficients of the monic
// polynomials orthogonal for -ln(x) on [0, 1] from 2n modified moments.
Recurrence logWeightRecurrence(int n)
{
  const std::vector<Real> nu = modifiedMoments(2 * n);
  Recurrence rec{std::vector<Real>(n), std::vector<Real>(n)};
  rec.alpha[0] = legendreA(0) + nu[1] / nu[0];
  rec.beta[0] = nu[0];
  std::vector<Real> sigmaOlder(2 * n, 0.0L); // sigma_{k-2, l}
  std::vector<Real> sigmaOld = nu;           // sigma_{k-1, l}
  for (int k = 1; k < n; ++k) {
    std::vector<Real> sigma(2 * n, 0.0L); // sigma_{k, l}, valid for k <= l <= 2n-k-1
    for (int l = k; l < 2 * n - k; ++l) {
      sigma[l] = sigmaOld[l + 1] - (rec.alpha[k - 1] - legendreA(l)) * sigmaOld[l] - rec.beta[k - 1] * sigmaOlder[l] +
                 legendreB(l) * sigmaOld[l - 1];
    }
    rec.alpha[k] = legendreA(k) + sigma[k + 1] / sigma[k] - sigmaOld[k] / sigmaOld[k - 1];
    rec.beta[k] = sigma[k] / sigmaOld[k - 1];
    sigmaOlder = std::move(sigmaOld);
    sigmaOld = std::move(sigma);
  }
  return rec;
}

// The monic orthogonal polynomial pi_n and its derivative at x.
std::pair<Real, Real> monicValue(const Recurrence& rec, Real x)
{
  Real previous = 0.0L, current = 1.0L;           // pi_{-1}, pi_0
  Real previousSlope = 0.0L, currentSlope = 0.0L; // their derivatives
  for (std::size_t k = 0; k < rec.alpha.size(); ++k) {
    const Real b = (k == 0) ? 0.0L : rec.beta[k];
    const Real next = (x - rec.alpha[k]) * current - b * previous;
    const Real nextSlope = current + (x - rec.alpha[k]) * currentSlope - b * previousSlope;
    previous = current;
    current = next;
    previousSlope = currentSlope;
    currentSlope = nextSlope;
  }
  return {current, currentSlope};
}

// Christoffel number 1 / sum_{k<n} p_k(x)^2 with the orthonormal p_k: accurate to a few
// ulps relative even for small weights (the eigenvector formula is only accurate absolutely).
Real christoffelWeight(const Recurrence& rec, Real x)
{
  Real previous = 0.0L;
  Real current = 1.0L / std::sqrt(rec.beta[0]);
  Real sum = current * current;
  for (std::size_t k = 0; k + 1 < rec.alpha.size(); ++k) {
    const Real next = ((x - rec.alpha[k]) * current - ((k == 0) ? 0.0L : std::sqrt(rec.beta[k])) * previous) /
                      std::sqrt(rec.beta[k + 1]);
    previous = current;
    current = next;
    sum += current * current;
  }
  return 1.0L / sum;
}

} // namespace

Rule1D logWeightedGauss(int n)
{
  core::require<core::InputError>(n >= 1 && n <= maxLogWeightedGaussOrder, "log-weighted Gauss order n = ", n,
                                  " is invalid; use 1 <= n <= ", maxLogWeightedGaussOrder, ".");
  const Recurrence rec = logWeightRecurrence(n);

  // Golub-Welsch: the nodes are the eigenvalues of the Jacobi matrix.
  Eigen::VectorXd diagonal(n), offDiagonal(n > 1 ? n - 1 : 0);
  for (int k = 0; k < n; ++k) {
    diagonal[k] = static_cast<double>(rec.alpha[k]);
    if (k > 0) {
      offDiagonal[k - 1] = static_cast<double>(std::sqrt(rec.beta[k]));
    }
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver;
  solver.computeFromTridiagonal(diagonal, offDiagonal, Eigen::EigenvaluesOnly);
  core::require<core::NumericalError>(solver.info() == Eigen::Success, "the Jacobi matrix of the ", n,
                                      "-point log-weighted Gauss rule did not diagonalise.");

  Rule1D rule;
  rule.points.resize(n);
  rule.weights.resize(n);
  for (int k = 0; k < n; ++k) {
    Real x = solver.eigenvalues()[k]; // ascending
    // Newton steps on pi_n restore full relative accuracy of the smallest nodes, where the
    // eigenvalue is only accurate to eps * ||J||. A genuine correction is tiny; a large one
    // would mean the polynomial evaluation is off, so it is not taken.
    for (int iteration = 0; iteration < 2; ++iteration) {
      const auto [value, slope] = monicValue(rec, x);
      const Real step = value / slope;
      if (std::isfinite(step) && std::abs(step) < 1e-10L) {
        x -= step;
      }
    }
    rule.points[k] = static_cast<double>(x);
    rule.weights[k] = static_cast<double>(christoffelWeight(rec, x));
  }
  return rule;
}

} // namespace capsula::quadrature
