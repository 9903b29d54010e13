// The stage preconditioners' shared part (StagePreconditioner.hpp), through the dense one
// the 2D cell uses (DenseStagePreconditioner.hpp), and the sum of J~'s two terms that the
// 3D and 2D Jacobians share (StageJacobian.hpp, combineWithFlowGradient).
#include <capsula/core/Error.hpp>
#include <capsula/operators/DenseStagePreconditioner.hpp>
#include <capsula/operators/StageJacobian.hpp>

#include <Tpetra_Core.hpp>
#include <Tpetra_MultiVector.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using capsula::operators::DenseStagePreconditioner;
using MultiVector = Tpetra::MultiVector<double>;

constexpr int kUnknowns = 6;

Teuchos::RCP<const Tpetra::Map<>> replicatedMap()
{
  return Teuchos::rcp(new Tpetra::Map<>(kUnknowns, 0, Tpetra::getDefaultComm(), Tpetra::LocallyReplicated));
}

// A nonsymmetric approximate Jacobian with a negative, stiff diagonal: I - shift A is well
// conditioned for every shift > 0.
Eigen::MatrixXf approximation(float scale)
{
  Eigen::MatrixXf A(kUnknowns, kUnknowns);
  for (int i = 0; i < kUnknowns; ++i) {
    for (int j = 0; j < kUnknowns; ++j) {
      A(i, j) = scale * (i == j ? -(2.0f + 3.0f * static_cast<float>(i)) : 0.3f * std::sin(1.0f + i - 2.0f * j));
    }
  }
  return A;
}

// Y = alpha P^-1 X + beta Y0 for the two columns X = (x, 2x), Y0 = (y0, y0).
std::vector<std::vector<double>> applied(const DenseStagePreconditioner& P, double alpha, double beta)
{
  MultiVector X(replicatedMap(), 2), Y(replicatedMap(), 2);
  for (int k = 0; k < kUnknowns; ++k) {
    const double x = std::cos(0.8 * k) + 0.1 * k;
    X.replaceLocalValue(k, 0, x);
    X.replaceLocalValue(k, 1, 2.0 * x);
    Y.replaceLocalValue(k, 0, 1.0 + k);
    Y.replaceLocalValue(k, 1, 1.0 + k);
  }
  P.apply(X, Y, Teuchos::NO_TRANS, alpha, beta);
  std::vector<std::vector<double>> columns(2, std::vector<double>(kUnknowns));
  for (std::size_t v = 0; v < 2; ++v) {
    const auto y = Y.getData(v);
    for (int k = 0; k < kUnknowns; ++k) {
      columns[v][static_cast<std::size_t>(k)] = y[static_cast<std::size_t>(k)];
    }
  }
  return columns;
}

// (I - shift A) (Y - beta Y0) / alpha, which must give back X.
std::vector<double> recovered(const Eigen::MatrixXf& A, double shift, const std::vector<double>& y, double alpha,
                              double beta)
{
  Eigen::VectorXd z(kUnknowns);
  for (int k = 0; k < kUnknowns; ++k) {
    z[k] = (y[static_cast<std::size_t>(k)] - beta * (1.0 + k)) / alpha;
  }
  const Eigen::VectorXd x = z - shift * (A.cast<double>() * z);
  return {x.data(), x.data() + kUnknowns};
}

} // namespace

// P^-1 is applied to every column with alpha and beta; the factorisation is in single
// precision, so X comes back to a few float epsilons (1e-5 relative: the matrix's condition
// number is below 10).
TEST(StagePreconditioner, AppliesAlphaTimesTheInverseShiftedApproximationPlusBetaY)
{
  DenseStagePreconditioner P(replicatedMap());
  const Eigen::MatrixXf A = approximation(1.0f);
  P.setJacobian(A);
  P.setShift(0.7);
  const double alpha = 1.5, beta = -0.25;
  const auto columns = applied(P, alpha, beta);
  for (std::size_t v = 0; v < 2; ++v) {
    const std::vector<double> x = recovered(A, 0.7, columns[v], alpha, beta);
    for (int k = 0; k < kUnknowns; ++k) {
      const double expected = (1.0 + static_cast<double>(v)) * (std::cos(0.8 * k) + 0.1 * k);
      EXPECT_NEAR(x[static_cast<std::size_t>(k)], expected, 1e-5) << "column " << v << ", row " << k;
    }
  }
}

// beta = 0 overwrites Y, even where it held NaN (a fresh MultiVector may).
TEST(StagePreconditioner, BetaZeroIgnoresWhatYHeld)
{
  DenseStagePreconditioner P(replicatedMap());
  P.setJacobian(approximation(1.0f));
  P.setShift(0.3);
  MultiVector X(replicatedMap(), 1), Y(replicatedMap(), 1);
  X.putScalar(1.0);
  Y.putScalar(std::nan(""));
  P.apply(X, Y);
  for (const double y : Y.getData(0)) {
    EXPECT_TRUE(std::isfinite(y));
  }
}

// A new approximation must be factorised before use, even at the shift of the last
// factorisation; the same approximation and shift are not factorised again.
TEST(StagePreconditioner, ANewApproximationIsFactorisedAtTheSameShift)
{
  DenseStagePreconditioner P(replicatedMap());
  P.setJacobian(approximation(1.0f));
  P.setShift(0.5);
  const auto before = applied(P, 1.0, 0.0);
  P.setJacobian(approximation(4.0f));
  MultiVector X(replicatedMap(), 1), Y(replicatedMap(), 1);
  EXPECT_THROW(P.apply(X, Y), capsula::core::Error); // not factorised since the change
  P.setShift(0.5);
  const auto after = applied(P, 1.0, 0.0);
  const std::vector<double> x = recovered(approximation(4.0f), 0.5, after[0], 1.0, 0.0);
  for (int k = 0; k < kUnknowns; ++k) {
    EXPECT_NEAR(x[static_cast<std::size_t>(k)], std::cos(0.8 * k) + 0.1 * k, 1e-5);
  }
  EXPECT_GT(std::abs(before[0][0] - after[0][0]), 1e-3); // the new approximation took effect
}

TEST(StagePreconditioner, RefusesTransposeAndApplicationBeforeTheFirstShift)
{
  DenseStagePreconditioner P(replicatedMap());
  MultiVector X(replicatedMap(), 1), Y(replicatedMap(), 1);
  P.setJacobian(approximation(1.0f));
  EXPECT_THROW(P.apply(X, Y), capsula::core::Error);
  P.setShift(0.5);
  EXPECT_THROW(P.apply(X, Y, Teuchos::TRANS), std::invalid_argument);
  EXPECT_FALSE(P.hasTransposeApply());
}

// shift = 1 / 2 on A = 2 I makes I - shift A zero: the message names the key that avoids it.
TEST(StagePreconditioner, SingularFactorisationNamesThePreconditionerKey)
{
  DenseStagePreconditioner P(replicatedMap());
  P.setJacobian(Eigen::MatrixXf::Identity(kUnknowns, kUnknowns) * 2.0f);
  try {
    P.setShift(0.5);
    FAIL() << "a singular preconditioner was accepted";
  } catch (const capsula::core::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("'Solver/Stiff/Preconditioner'"), std::string::npos) << e.what();
  }
  MultiVector X(replicatedMap(), 1), Y(replicatedMap(), 1);
  EXPECT_THROW(P.apply(X, Y), capsula::core::Error); // the failed factorisation left none
}

// y = a s + b G x per node, with small integers so that every value is exact: a
// transposed G, a swapped weight or a missing term changes some entry.
TEST(StageJacobian, CombinesTheSingleLayerAndTheFlowGradientPerNode)
{
  // Node 0 takes G, node 1 takes G + E_01 (the gradient of plane Poiseuille flow varies with
  // the node's height).
  Eigen::Matrix2d G, G1;
  G << 1.0, 2.0, 3.0, 5.0;
  G1 << 1.0, 3.0, 3.0, 5.0;
  const std::vector<double> x{1.0, -1.0, 2.0, 4.0};
  const std::vector<double> s{10.0, 20.0, 30.0, 40.0};
  std::vector<double> y(4);
  const auto a = [](std::size_t g) { return g == 0 ? -1.0 : -2.0; };
  const auto b = [](std::size_t g) { return g == 0 ? 0.5 : 3.0; };
  const auto gradient = [&](std::size_t g) -> const Eigen::Matrix2d& { return g == 0 ? G : G1; };
  capsula::operators::combineWithFlowGradient<2>(gradient, a, b, 2, x.data(), s, y.data());
  // node 0: G x = (1 - 2, 3 - 5) = (-1, -2); node 1: G1 x = (2 + 12, 6 + 20) = (14, 26).
  EXPECT_EQ(y, (std::vector<double>{-10.0 - 0.5, -20.0 - 1.0, -60.0 + 42.0, -80.0 + 78.0}));

  const Eigen::Matrix3d G3 = Eigen::Matrix3d::Identity() * 2.0;
  const std::vector<double> x3{1.0, 2.0, 3.0}, s3{1.0, 1.0, 1.0};
  std::vector<double> y3(3);
  capsula::operators::combineWithFlowGradient<3>([&](std::size_t) -> const Eigen::Matrix3d& { return G3; },
                                                 [](std::size_t) { return 4.0; }, [](std::size_t) { return 0.5; }, 1,
                                                 x3.data(), s3, y3.data());
  EXPECT_EQ(y3, (std::vector<double>{5.0, 6.0, 7.0}));
}
