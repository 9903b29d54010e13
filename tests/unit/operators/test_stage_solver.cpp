// StageSolver: GMRES on the stage matrix W = I - shift J~ of the stiff time integrators
// (StageSolver.hpp). A small dense J~ stands for the scene's Jacobian.
#include <capsula/operators/StageSolver.hpp>

#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_Core.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using capsula::operators::StageSolver;

constexpr std::size_t kN = 24;

// A nonsymmetric J~ with a stiff, negative spectrum (eigenvalues ~ -1 ... -200) plus a
// smooth coupling, like a membrane's: W = I - shift J~ is then well conditioned for any
// shift > 0 but far from the identity.
double jacobianEntry(std::size_t i, std::size_t j)
{
  const double x = static_cast<double>(i), y = static_cast<double>(j);
  const double diagonal = i == j ? -(1.0 + 200.0 * x * x / static_cast<double>(kN * kN)) : 0.0;
  return diagonal + 0.3 * std::sin(0.7 * x + 1.3 * y) / static_cast<double>(kN);
}

void applyJacobian(const double* x, double* y)
{
  for (std::size_t i = 0; i < kN; ++i) {
    y[i] = 0.0;
    for (std::size_t j = 0; j < kN; ++j) {
      y[i] += jacobianEntry(i, j) * x[j];
    }
  }
}

std::vector<double> applyW(double shift, const std::vector<double>& x)
{
  std::vector<double> Jx(kN), Wx(kN);
  applyJacobian(x.data(), Jx.data());
  for (std::size_t i = 0; i < kN; ++i) {
    Wx[i] = x[i] - shift * Jx[i];
  }
  return Wx;
}

std::vector<double> pattern(double a, double b)
{
  std::vector<double> v(kN);
  for (std::size_t i = 0; i < kN; ++i) {
    v[i] = std::sin(a * static_cast<double>(i) + b) + 0.2 * std::cos(b * static_cast<double>(i));
  }
  return v;
}

double norm(const std::vector<double>& v)
{
  double s = 0.0;
  for (const double x : v) {
    s += x * x;
  }
  return std::sqrt(s);
}

// M = diag(W)^-1 at a fixed shift: a right preconditioner that leaves a few iterations.
class StageDiagonalInverse final : public Tpetra::Operator<double> {
public:
  StageDiagonalInverse(Teuchos::RCP<const Tpetra::Map<>> map, double shift) : map_(std::move(map)), shift_(shift) {}
  Teuchos::RCP<const Tpetra::Map<>> getDomainMap() const override { return map_; }
  Teuchos::RCP<const Tpetra::Map<>> getRangeMap() const override { return map_; }
  void apply(const Tpetra::MultiVector<double>& X, Tpetra::MultiVector<double>& Y, Teuchos::ETransp, double alpha,
             double beta) const override
  {
    for (std::size_t v = 0; v < X.getNumVectors(); ++v) {
      const auto x = X.getData(v);
      auto y = Y.getDataNonConst(v);
      for (std::size_t i = 0; i < kN; ++i) {
        y[i] = (beta == 0.0 ? 0.0 : beta * y[i]) + alpha * x[i] / (1.0 - shift_ * jacobianEntry(i, i));
      }
    }
  }

private:
  Teuchos::RCP<const Tpetra::Map<>> map_;
  double shift_;
};

int blockGmresSolves()
{
  const auto timer = Teuchos::TimeMonitor::lookupCounter("Belos: BlockGmresSolMgr total solve time");
  return timer.is_null() ? 0 : timer->numCalls();
}

} // namespace

// Each solve reaches its RMS residual target in the true residual (W recomputed here); a
// caller's guess that already solves the system comes back unchanged; a right-hand side
// within the target gives x = 0 without an iteration.
TEST(StageSolver, ReachesItsTargetFromZeroAndFromAGuess)
{
  const auto comm = Tpetra::getDefaultComm();
  auto map = Teuchos::rcp(new Tpetra::Map<>(kN, 0, comm, Tpetra::LocallyReplicated));
  capsula::operators::SolverParameters gmres;
  gmres.restart = 10; // below the dimension (Belos warns otherwise), so GMRES restarts
  gmres.maximumIterations = 200;
  StageSolver solver(map, applyJacobian, Teuchos::null, gmres);
  const double shift = 0.2, target = 1e-10;
  for (const auto& r : {pattern(0.4, 0.3), pattern(1.3, 0.6)}) {
    std::vector<double> x(kN, 0.0);
    const auto result = solver.solve(shift, r, x, target);
    ASSERT_TRUE(result.converged);
    EXPECT_GT(result.iterations, 3);
    const std::vector<double> W = applyW(shift, x);
    double sum = 0.0;
    for (std::size_t i = 0; i < kN; ++i) {
      sum += (W[i] - r[i]) * (W[i] - r[i]);
    }
    // GMRES's residual estimate tracks the true one to round-off (1% margin); a wrong
    // shift sign or a dropped identity would leave an O(1) residual.
    EXPECT_LT(std::sqrt(sum / kN), 1.01 * target);
    EXPECT_LE(result.residualRms, target);
    std::vector<double> again = x;
    const auto second = solver.solve(shift, r, again, target);
    EXPECT_TRUE(second.converged);
    EXPECT_LE(second.iterations, 1);
    for (std::size_t i = 0; i < kN; ++i) {
      EXPECT_NEAR(again[i], x[i], 1e-9);
    }
  }
  std::vector<double> tiny(kN, 1e-12), x(kN, 1.0);
  const auto trivial = solver.solve(shift, tiny, x, 1e-10);
  EXPECT_TRUE(trivial.converged);
  EXPECT_EQ(trivial.iterations, 0);
  EXPECT_EQ(norm(x), 0.0);
}

// The stage solves keep flexible GMRES whatever 'Solver/Method' and 'Solver/Belos' say
// (StageSolver.hpp): Belos's block GMRES solver runs, the Belos entry that would stop it
// after one iteration does not apply, and W is applied once per iteration and no more (no
// explicit residual to confirm the estimate: the flexible variant).
TEST(StageSolver, KeepsFlexibleGmresWhateverTheViscosityRatioMethod)
{
  const auto comm = Tpetra::getDefaultComm();
  auto map = Teuchos::rcp(new Tpetra::Map<>(kN, 0, comm, Tpetra::LocallyReplicated));
  const double shift = 0.2;
  capsula::operators::SolverParameters gmres;
  gmres.restart = 20; // more than the iterations it takes: no restart, whose residual costs an application
  gmres.maximumIterations = 200;
  gmres.method = "TFQMR";
  gmres.belos.set("Maximum Iterations", 1);
  long long applications = 0;
  const auto counted = [&](const double* x, double* y) {
    ++applications;
    applyJacobian(x, y);
  };
  StageSolver solver(map, counted, Teuchos::rcp(new StageDiagonalInverse(map, shift)), gmres);
  std::vector<double> x(kN, 0.0);
  const int before = blockGmresSolves();
  const auto result = solver.solve(shift, pattern(0.4, 0.3), x, 1e-10);
  EXPECT_EQ(blockGmresSolves(), before + 1);
  ASSERT_TRUE(result.converged);
  EXPECT_GT(result.iterations, 1);
  EXPECT_LT(result.iterations, gmres.restart);
  EXPECT_EQ(applications, result.iterations);
  const std::vector<double> W = applyW(shift, x);
  const std::vector<double> r = pattern(0.4, 0.3);
  double sum = 0.0;
  for (std::size_t i = 0; i < kN; ++i) {
    sum += (W[i] - r[i]) * (W[i] - r[i]);
  }
  // Flexible GMRES's residual is that of its iterate (1% margin for round-off).
  EXPECT_LT(std::sqrt(sum / kN), 1.01e-10);
}

// Kept products of J~ (JacobianProducts.hpp): a right-hand side within their span is solved
// with no new application, for any shift (W x = x - shift J~ x from the kept pair); one
// outside it starts from its least-residual part, so it needs fewer iterations than from
// zero and reaches the same true residual; newJacobian() forgets them.
TEST(StageSolver, StartsFromTheKeptProductsOfTheJacobian)
{
  const auto comm = Tpetra::getDefaultComm();
  auto map = Teuchos::rcp(new Tpetra::Map<>(kN, 0, comm, Tpetra::LocallyReplicated));
  capsula::operators::SolverParameters gmres;
  gmres.restart = 20;
  gmres.maximumIterations = 200;
  long long applications = 0;
  const auto counted = [&](const double* x, double* y) {
    ++applications;
    applyJacobian(x, y);
  };
  const double shift = 0.2, target = 1e-10;
  const auto trueResidualRms = [](double s, const std::vector<double>& x, const std::vector<double>& r) {
    const std::vector<double> W = applyW(s, x);
    double sum = 0.0;
    for (std::size_t i = 0; i < kN; ++i) {
      sum += (W[i] - r[i]) * (W[i] - r[i]);
    }
    return std::sqrt(sum / kN);
  };
  StageSolver plain(map, applyJacobian, Teuchos::rcp(new StageDiagonalInverse(map, shift)), gmres);
  StageSolver recycling(map, counted, Teuchos::rcp(new StageDiagonalInverse(map, shift)), gmres, 40);

  // The first solve has nothing to start from.
  const std::vector<double> r1 = pattern(0.4, 0.3);
  std::vector<double> x1(kN, 0.0);
  const auto first = recycling.solve(shift, r1, x1, target);
  ASSERT_TRUE(first.converged);
  EXPECT_FALSE(first.recycled);
  EXPECT_EQ(applications, first.iterations);

  // W x1 = r1, so 2.5 r1 is 2.5 x1: no application; the same at another shift (a retried
  // attempt), where W x1 is a different vector. The true residual is recomputed here: a
  // wrong sign of the shift in the kept W x would leave an O(1) residual.
  for (const double s : {shift, 0.05}) {
    std::vector<double> rs = applyW(s, x1);
    for (double& v : rs) {
      v *= 2.5;
    }
    std::vector<double> x(kN, 0.0);
    const long long before = applications;
    const auto again = recycling.solve(s, rs, x, target);
    ASSERT_TRUE(again.converged);
    EXPECT_TRUE(again.recycled);
    EXPECT_EQ(again.iterations, 0);
    EXPECT_EQ(applications, before);
    // The projection's round-off on a 24-vector is ~1e-15 of |r| ~ 10: far below the target.
    EXPECT_LT(trueResidualRms(s, x, rs), target);
  }

  // A related right-hand side (as a later stage's: r1 plus a change 1e-4 of its size) needs
  // fewer iterations than from zero and meets the same target in the true residual.
  std::vector<double> r2 = r1;
  const std::vector<double> change = pattern(1.3, 0.6);
  for (std::size_t i = 0; i < kN; ++i) {
    r2[i] += 1e-4 * change[i];
  }
  std::vector<double> fromZero(kN, 0.0), recycled(kN, 0.0);
  const auto zeroStart = plain.solve(shift, r2, fromZero, target);
  const auto keptStart = recycling.solve(shift, r2, recycled, target);
  ASSERT_TRUE(zeroStart.converged);
  ASSERT_TRUE(keptStart.converged);
  EXPECT_TRUE(keptStart.recycled);
  EXPECT_LT(keptStart.iterations, zeroStart.iterations);
  EXPECT_LT(trueResidualRms(shift, recycled, r2), 1.01 * target); // 1%: GMRES's estimate vs the true residual
  EXPECT_LE(keptStart.residualRms, target);

  // After newJacobian() the same right-hand side starts from zero again.
  recycling.newJacobian();
  std::vector<double> afresh(kN, 0.0);
  const auto cleared = recycling.solve(shift, r2, afresh, target);
  EXPECT_FALSE(cleared.recycled);
  EXPECT_EQ(cleared.iterations, zeroStart.iterations);
}
