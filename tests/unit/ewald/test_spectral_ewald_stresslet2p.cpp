// The spectral Ewald sum of the stresslet (SpectralEwaldStresslet2P.hpp) against its reference
// sum (StressletReference2P.hpp): within the tolerance, periodic, independent of xi.
#include <capsula/ewald/SpectralEwaldStresslet2P.hpp>
#include <capsula/ewald/StressletReference2P.hpp>
#include <capsula/greens/FreeSpace3D.hpp>

#include "EwaldTesting.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

namespace {

using namespace capsula::ewald;
using capsula::ewald::testing::randomForces;
using capsula::ewald::testing::randomPoints;
using capsula::ewald::testing::relativeError;

const PeriodicLayer stressletBox{1.8, 2.2};

struct StressletProblem {
  std::vector<double> sources, tensors, targets, reference;
};

/// 40 sources with random (non-symmetric) tensors, 25 targets; the reference sum to 1e-15.
const StressletProblem& stressletProblem()
{
  static const StressletProblem problem = [] {
    StressletProblem p;
    p.sources = randomPoints(stressletBox, 40, 21, -0.7, 0.9);
    p.tensors = randomForces(40, 22, 9);
    p.targets = randomPoints(stressletBox, 25, 23, -1.0, 1.1);
    p.reference.assign(p.targets.size(), 0.0);
    const EwaldTruncation truncation = ewaldTruncation(2.0, 1e-15);
    for (std::size_t t = 0; t < p.targets.size(); t += 3) {
      for (std::size_t n = 0; 3 * n < p.sources.size(); ++n) {
        const double xh[3] = {p.targets[t] - p.sources[3 * n], p.targets[t + 1] - p.sources[3 * n + 1],
                              p.targets[t + 2] - p.sources[3 * n + 2]};
        double T[3][3][3];
        periodicStresslet2P(stressletBox, truncation, xh, T);
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) {
            for (int k = 0; k < 3; ++k) {
              p.reference[t + i] += T[i][j][k] * p.tensors[9 * n + 3 * j + k];
            }
          }
        }
      }
    }
    return p;
  }();
  return problem;
}

TEST(SpectralEwaldStresslet2P, ErrorIsBelowTheTolerance)
{
  // The rule of SpectralEwald2P.hpp applied to the stresslet (whose transform falls like 1/k,
  // not 1/k^2): measured errors in the commit message. A wrong multiplier term, zero-mode
  // combination or symmetrisation gives O(1) errors; the tensors are not symmetric, so a sum
  // that used S_kj for S_jk would differ from the reference.
  const StressletProblem& p = stressletProblem();
  for (double tolerance : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8}) {
    const auto u = spectralEwaldStresslet2P(stressletBox, tolerance, p.sources, p.tensors, p.targets);
    const double error = relativeError(u, p.reference);
    EXPECT_LT(error, tolerance) << "tolerance " << tolerance;
    std::printf("stresslet tolerance %.0e: error %.2e\n", tolerance, error);
  }
}

TEST(SpectralEwaldStresslet2P, IndependentOfTheSplittingParameterAndPeriodic)
{
  // xi = 1.5 (r_c longer than the periods), 5 and 10 agree within twice the tolerance 1e-8;
  // whole-period moves of sources and targets change only rounding (1e-12).
  const StressletProblem& p = stressletProblem();
  const auto first = spectralEwaldStresslet2P(stressletBox, 1e-8, p.sources, p.tensors, p.targets, 1.5);
  for (double xi : {5.0, 10.0}) {
    const auto other = spectralEwaldStresslet2P(stressletBox, 1e-8, p.sources, p.tensors, p.targets, xi);
    EXPECT_LT(relativeError(other, first), 2e-8) << "xi " << xi;
  }
  auto movedSources = p.sources;
  auto movedTargets = p.targets;
  for (std::size_t n = 0; n < movedSources.size(); n += 3) {
    movedSources[n] -= stressletBox.lengthX;
    movedSources[n + 2] += 2.0 * stressletBox.lengthZ;
  }
  for (std::size_t n = 0; n < movedTargets.size(); n += 3) {
    movedTargets[n] += 4.0 * stressletBox.lengthX;
  }
  const auto u = spectralEwaldStresslet2P(stressletBox, 1e-6, p.sources, p.tensors, p.targets);
  const auto moved = spectralEwaldStresslet2P(stressletBox, 1e-6, movedSources, p.tensors, movedTargets);
  EXPECT_LT(relativeError(moved, u), 1e-12);
}

TEST(SpectralEwaldStresslet2P, TargetOnASourceGetsTheFieldOfItsImages)
{
  // Targets on the sources: source n gives its own target lim (T - T_free) S_n (T^F is odd, so
  // nothing of its own smooth part). The reference takes it at xh = delta = 1e-4 (T ~ 1e8 there:
  // rounding ~1e-8; the regular part moves by ~delta |grad| ~ 1e-4), so the fast sum at
  // tolerance 1e-4 must agree to 3e-4 of the largest velocity; a self term of the size of
  // T^R's Gaussian terms (xi^3 ~ 10) would not.
  const StressletProblem& p = stressletProblem();
  const std::vector<double> sources(p.sources.begin(), p.sources.begin() + 30);
  const std::vector<double> tensors(p.tensors.begin(), p.tensors.begin() + 90);
  const auto u = spectralEwaldStresslet2P(stressletBox, 1e-4, sources, tensors, sources);
  const EwaldTruncation truncation = ewaldTruncation(2.0, 1e-15);
  std::vector<double> reference(sources.size(), 0.0);
  for (std::size_t t = 0; t < sources.size(); t += 3) {
    for (std::size_t n = 0; 3 * n < sources.size(); ++n) {
      double xh[3] = {sources[t] - sources[3 * n], sources[t + 1] - sources[3 * n + 1],
                      sources[t + 2] - sources[3 * n + 2]};
      double T[3][3][3], free[3][3][3] = {};
      if (t == 3 * n) {
        xh[0] = 0.6e-4;
        xh[2] = 0.8e-4;
        capsula::greens::stressletFreeSpace3D(xh, free);
      }
      periodicStresslet2P(stressletBox, truncation, xh, T);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          for (int k = 0; k < 3; ++k) {
            reference[t + i] += (T[i][j][k] - free[i][j][k]) * tensors[9 * n + 3 * j + k];
          }
        }
      }
    }
  }
  EXPECT_LT(relativeError(u, reference), 3e-4);
  std::printf("stresslet self: error %.2e\n", relativeError(u, reference));
}

} // namespace
