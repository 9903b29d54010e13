#include "capsula/fastsum/TreecodeParameters.hpp"

#include "capsula/fastsum/BarycentricLagrange.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/operators/RegularSums.hpp>

#include <cmath>

namespace capsula::fastsum {

namespace {

struct TableRow {
  double tolerance;
  int degree;
  double theta;
  bool singlePrecision;
};

// Measured on the quadrature points of four level-3 spheres 0.1 above the wall (Wall
// kernel, 35840 points, 10248 node targets; smooth load and density with 10% noise) and on
// random clouds: the 2-norm relative error of the single and the double layer, the larger
// of the two, against the direct sums in double. Each row is the cheapest measured (degree,
// theta, precision) whose error on the spheres stays at least a factor 2 below the row's
// tolerance (the cloud's errors are smaller); docs/fastsum.md has the table. Odd degrees
// are markedly better than even ones for the double layer on surfaces (n = 4: 3.7e-4,
// n = 5: 3.6e-5 at theta = 0.6). The single layer in float (SinglePrecisionSums.hpp) adds
// ~1e-7 (1.3e-7 with every pair in float; 1.5e-7 in all at n = 9), so only the last row
// keeps it in double. Measured with the default batch (32 targets) and leaf (400 points) sizes;
// larger batches are more accurate and dearer.
constexpr TableRow table[] = {
    {1e-2, 2, 0.5, true},  // 4.7e-3
    {1e-3, 3, 0.5, true},  // 3.5e-4 (theta = 0.6: 1.1e-3)
    {1e-4, 5, 0.6, true},  // 3.6e-5 (theta = 0.65: 6.3e-5)
    {1e-5, 7, 0.6, true},  // 1.1e-6 (n = 6: 6.6e-6, too close)
    {1e-6, 8, 0.6, true},  // 3.7e-7
    {1e-7, 9, 0.6, false}, // 4.1e-8 (single layer in float: 1.5e-7)
};

} // namespace

TreecodeParameters treecodeParametersForTolerance(double tolerance)
{
  core::require<core::InputError>(std::isfinite(tolerance) && tolerance >= 1e-7 && tolerance <= 1e-1,
                                  "Treecode tolerance ", tolerance, " must lie in [1e-7, 1e-1] (the measured table).");
  TreecodeParameters p;
  for (const TableRow& row : table) {
    p.degree = row.degree;
    p.theta = row.theta;
    p.singlePrecision = row.singlePrecision;
    if (row.tolerance <= tolerance) {
      break;
    }
  }
  return p;
}

void validate(const TreecodeParameters& p)
{
  core::require<core::InputError>(p.degree >= 1 && p.degree <= maxInterpolationDegree, "Treecode degree ", p.degree,
                                  " must lie in [1, ", maxInterpolationDegree, "].");
  core::require<core::InputError>(std::isfinite(p.theta) && p.theta >= 0.0 && p.theta < 1.0, "Treecode theta ", p.theta,
                                  " must lie in [0, 1) (0: every interaction direct).");
  core::require<core::InputError>(p.leafSize >= 1, "Treecode leaf size ", p.leafSize, " must be >= 1.");
  core::require<core::InputError>(p.batchSize >= 1 && p.batchSize <= operators::targetBlockSize, "Treecode batch size ",
                                  p.batchSize, " must lie in [1, ", operators::targetBlockSize, "].");
}

} // namespace capsula::fastsum
