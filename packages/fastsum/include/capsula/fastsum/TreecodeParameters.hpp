#pragma once
// The knobs of the barycentric Lagrange treecode (Wang, Tlupova & Krasny 2020) and their
// choice from one relative tolerance.
//
// Error: a source cluster of radius r_C seen from a target batch of radius r_B at centre
// distance R is replaced by its proxies when (r_B + r_C) / R < theta (the multipole
// acceptance criterion, eq 16); the interpolation error then falls like theta^(n+1) for
// degree n. Cost: each accepted cluster costs (n+1)^3 kernel evaluations per target, so
// a cluster is used only when it holds more sources than that.
namespace capsula::fastsum {

struct TreecodeParameters {
  int degree = 6;     ///< n: (n+1)^3 Chebyshev proxies per cluster
  double theta = 0.7; ///< acceptance criterion (r_B + r_C) / R < theta; 0: all direct
  int leafSize = 400; ///< most sources in a leaf cluster
  int batchSize = 32; ///< most targets in a batch (at most operators::targetBlockSize)
  /// Evaluate the single layer's kernel in float (SinglePrecisionSums.hpp), for kernels
  /// that allow it; the double layer stays double (Treecode.hpp).
  bool singlePrecision = false;
};

/// The cheapest measured (degree, theta, precision) whose relative error on the single and
/// double layers of cells near the wall stays below `tolerance` (table in
/// TreecodeParameters.cpp).
/// Throws core::InputError outside [1e-7, 1e-1], the range measured.
TreecodeParameters treecodeParametersForTolerance(double tolerance);

/// Throws core::InputError naming the field unless the values are usable.
void validate(const TreecodeParameters& parameters);

} // namespace capsula::fastsum
