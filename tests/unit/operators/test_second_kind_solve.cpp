// solveSecondKind (SecondKindSolve.hpp), the solve the 2D contour and the 3D surfaces share,
// on a stand-in double layer whose equation has a closed-form solution: DL[v]_t = sum of all
// entries of v at every row, so u_k - r_k sum_j s_j u_j = b_k has u_k = b_k + r_k S with
// S = sum_j s_j b_j / (1 - sum_j s_j r_j) (r the row scale, s the density scale of each
// unknown's node).
#include "OperatorTesting.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/operators/SecondKindSolve.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using namespace capsula;
using namespace capsula::operators;
namespace ot = capsula::operators::testing;

constexpr int kNodes = 5;

SecondKindOperator::DoubleLayerRows sumOfEntries(int unknowns)
{
  return [unknowns](const double* v, double* rows) {
    double sum = 0.0;
    for (int k = 0; k < unknowns; ++k) {
      sum += v[k];
    }
    for (int k = 0; k < unknowns; ++k) {
      rows[k] = sum;
    }
  };
}

/// u_k = b_k + r_k S, S = sum s_j b_j / (1 - sum s_j r_j), per unknown k of node k / width.
std::vector<double> exactSolution(const std::vector<double>& b, const std::vector<double>& rowScale,
                                  const std::vector<double>& densityScale, int width)
{
  double sb = 0.0, sr = 0.0;
  for (std::size_t k = 0; k < b.size(); ++k) {
    const double s = densityScale.empty() ? 1.0 : densityScale[k / width];
    sb += s * b[k];
    sr += s * rowScale[k / width];
  }
  std::vector<double> u(b.size());
  for (std::size_t k = 0; k < b.size(); ++k) {
    u[k] = b[k] + rowScale[k / width] * sb / (1.0 - sr);
  }
  return u;
}

std::vector<double> rightHandSide(int width)
{
  std::vector<double> b(static_cast<std::size_t>(width * kNodes));
  for (std::size_t k = 0; k < b.size(); ++k) {
    b[k] = std::sin(1.0 + static_cast<double>(k));
  }
  return b;
}

TEST(SecondKindSolve, SolvesTheEquationOfTheSurfacesAndOfTheContours)
{
  // 3D: density scales 1 - lambda of the node's cell, row scales 1 / (4 pi (1 + lambda));
  // 2D: no density scale, row scale (1 - lambda) / (2 pi (1 + lambda)) and 0 at a prescribed
  // node, whose velocity is then its right-hand side. From u = b the residual of a rank-one
  // coupling is an eigenvector of A: GMRES converges in one iteration, to round-off (a wrong
  // scale or a row left out of the gather errs by O(1)).
  for (const int width : {3, 2}) {
    const NodeDistribution distribution(ot::serialComm(), kNodes, width);
    std::vector<double> densityScale, rowScale;
    for (int n = 0; n < kNodes; ++n) {
      const double lambda = n % 2 == 0 ? 5.0 : 0.2;
      if (width == 3) {
        densityScale.push_back(1.0 - lambda);
        rowScale.push_back(1.0 / (4.0 * M_PI * (1.0 + lambda)));
      } else {
        rowScale.push_back(n == 2 ? 0.0 : (1.0 - lambda) / (2.0 * M_PI * (1.0 + lambda)));
      }
    }
    const std::vector<double> b = rightHandSide(width);
    const std::vector<double> expected = exactSolution(b, rowScale, densityScale, width);
    SolverParameters solver;
    solver.tolerance = 1e-12;
    const SecondKindSolution solution =
        solveSecondKind({distribution, sumOfEntries(width * kNodes), densityScale, rowScale, "the test equation"}, b,
                        solver, nullptr, nullptr);
    ASSERT_EQ(solution.velocities.size(), b.size());
    for (std::size_t k = 0; k < b.size(); ++k) {
      EXPECT_NEAR(solution.velocities[k], expected[k], 1e-12) << "width " << width << ", unknown " << k;
    }
    if (width == 2) {
      EXPECT_EQ(solution.velocities[4], b[4]); // the prescribed node's row is u = b
      EXPECT_EQ(solution.velocities[5], b[5]);
    }
    EXPECT_EQ(solution.krylov.iterations, 1);
  }
}

TEST(SecondKindSolve, ZeroRightHandSideGivesZeroWithoutASolve)
{
  const NodeDistribution distribution(ot::serialComm(), kNodes, 3);
  int applications = 0;
  const SecondKindOperator::DoubleLayerRows counting = [&](const double* v, double* rows) {
    ++applications;
    sumOfEntries(3 * kNodes)(v, rows);
  };
  WarmStartHistory history;
  const SecondKindSolution solution =
      solveSecondKind({distribution, counting, {}, std::vector<double>(kNodes, 0.1), "the test equation"},
                      std::vector<double>(3 * kNodes, 0.0), SolverParameters{}, nullptr, &history);
  EXPECT_EQ(solution.velocities, std::vector<double>(3 * kNodes, 0.0));
  EXPECT_EQ(solution.krylov.iterations, 0);
  EXPECT_EQ(applications, 0);
  EXPECT_TRUE(history.empty()); // nothing solved, nothing to start from
}

TEST(SecondKindSolve, WarmStartFromTheLastSolutionNeedsNoIteration)
{
  // The history's guess for the same right-hand side is its solution: the second solve starts
  // converged (0 iterations) and returns it, and each solve adds its pair.
  const NodeDistribution distribution(ot::serialComm(), kNodes, 3);
  const std::vector<double> rowScale(kNodes, 0.05);
  const std::vector<double> b = rightHandSide(3);
  SolverParameters solver;
  solver.tolerance = 1e-12;
  WarmStartHistory history;
  const SecondKindSolution first = solveSecondKind(
      {distribution, sumOfEntries(3 * kNodes), {}, rowScale, "the test equation"}, b, solver, nullptr, &history);
  EXPECT_EQ(history.size(), 1);
  const SecondKindSolution second = solveSecondKind(
      {distribution, sumOfEntries(3 * kNodes), {}, rowScale, "the test equation"}, b, solver, nullptr, &history);
  EXPECT_EQ(history.size(), 2);
  EXPECT_GE(first.krylov.iterations, 1);
  EXPECT_EQ(second.krylov.iterations, 0);
  for (std::size_t k = 0; k < b.size(); ++k) {
    EXPECT_NEAR(second.velocities[k], first.velocities[k], 1e-13);
  }
}

TEST(SecondKindSolve, StoppedShortNamesTheEquation)
{
  // From u = b the residual of a rank-one coupling is an eigenvector of A, solved in one
  // iteration; a coupling with a diagonal part as well, DL[v]_k = sum v + k v_k, needs
  // several. Capped at one it stops short, and the error names the equation.
  const NodeDistribution distribution(ot::serialComm(), kNodes, 3);
  const SecondKindOperator::DoubleLayerRows coupled = [](const double* v, double* rows) {
    sumOfEntries(3 * kNodes)(v, rows);
    for (int k = 0; k < 3 * kNodes; ++k) {
      rows[k] += k * v[k];
    }
  };
  SolverParameters solver;
  solver.tolerance = 1e-12;
  solver.maximumIterations = 1;
  solver.restart = 1;
  try {
    solveSecondKind({distribution, coupled, {}, std::vector<double>(kNodes, 0.3), "the test equation"},
                    rightHandSide(3), solver, nullptr, nullptr);
    FAIL() << "a solve capped at one iteration converged";
  } catch (const core::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("the test equation"), std::string::npos) << e.what();
  }
}

} // namespace
