// The foundation's two-rank check: the distribution pattern every Capsula
// operator uses works on this stack.
//   1. a Tpetra::Map spreads N unknowns over the ranks;
//   2. a Tpetra::Import gathers a distributed vector into a locally replicated
//      copy (each boundary-integral row needs every node's value);
//   3. Belos GMRES, through the solve every operator uses (operators::solveLinearSystem),
//      solves with a matrix-free Tpetra::Operator whose apply() uses that gather, and
//      recovers a known solution.
// The solve goes through capsula::operators rather than Belos's own templates so that this
// file does not instantiate Belos on Tpetra a second time (about 20 s of compilation).
#include "capsula/testing/MpiTesting.hpp"

#include <capsula/operators/KrylovSolve.hpp>
#include <capsula/operators/OperatorParameters.hpp>

#include <Tpetra_Core.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>
#include <Tpetra_Vector.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

using Scalar = double;
using Map = Tpetra::Map<>;
using MV = Tpetra::MultiVector<Scalar>;
using Vector = Tpetra::Vector<Scalar>;
using Operator = Tpetra::Operator<Scalar>;
using GO = Map::global_ordinal_type;

// A dense, non-symmetric "integral-like" operator, applied matrix-free:
//   (A x)_i = 2 x_i + sum_j k(i, j) x_j / N,  k(i, j) = cos(0.3 i - 0.7 j).
// Its rows need every entry of x, as a boundary-integral row does.
double kernel(GO i, GO j)
{
  return std::cos(0.3 * static_cast<double>(i) - 0.7 * static_cast<double>(j));
}

class DenseKernelOperator final : public Operator {
public:
  explicit DenseKernelOperator(Teuchos::RCP<const Map> map)
      : map_(std::move(map)),
        replicatedMap_(
            Teuchos::rcp(new Map(map_->getGlobalNumElements(), 0, map_->getComm(), Tpetra::LocallyReplicated))),
        gather_(Teuchos::rcp(new Tpetra::Import<>(map_, replicatedMap_)))
  {}

  Teuchos::RCP<const Map> getDomainMap() const override { return map_; }
  Teuchos::RCP<const Map> getRangeMap() const override { return map_; }
  bool hasTransposeApply() const override { return false; }

  // Y = alpha A X + beta Y.
  void apply(const MV& X, MV& Y, Teuchos::ETransp mode, Scalar alpha, Scalar beta) const override
  {
    TEUCHOS_TEST_FOR_EXCEPTION(mode != Teuchos::NO_TRANS, std::invalid_argument,
                               "DenseKernelOperator has no transpose apply");
    const auto n = static_cast<GO>(map_->getGlobalNumElements());
    MV all(replicatedMap_, X.getNumVectors());
    all.doImport(X, *gather_, Tpetra::INSERT);
    for (std::size_t v = 0; v < X.getNumVectors(); ++v) {
      const auto xAll = all.getData(v);
      const auto xOwn = X.getData(v);
      auto y = Y.getDataNonConst(v);
      for (std::size_t row = 0; row < map_->getNodeNumElements(); ++row) {
        const GO i = map_->getGlobalElement(static_cast<Map::local_ordinal_type>(row));
        double sum = 2.0 * xOwn[row];
        for (GO j = 0; j < n; ++j) {
          sum += kernel(i, j) * xAll[j] / static_cast<double>(n);
        }
        y[row] = (beta == 0.0 ? 0.0 : beta * y[row]) + alpha * sum;
      }
    }
  }

private:
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<const Map> replicatedMap_;
  Teuchos::RCP<Tpetra::Import<>> gather_;
};

double exactSolution(GO i)
{
  return std::sin(0.1 * static_cast<double>(i)) + 0.5;
}

} // namespace

TEST(TpetraBelos, MapSpreadsUnknownsOverTwoRanks)
{
  const auto comm = Tpetra::getDefaultComm();
  ASSERT_EQ(comm->getSize(), 2) << "this test is registered to run on 2 ranks";
  const auto map = Teuchos::rcp(new Map(101, 0, comm));
  const std::size_t local = map->getNodeNumElements();
  // Tpetra's uniform contiguous map: 51 + 50.
  const bool ok = local == (comm->getRank() == 0 ? 51u : 50u) && map->isDistributed();
  EXPECT_TRUE(capsula::testing::allRanks(*comm, ok));
}

TEST(TpetraBelos, ImportGathersTheWholeVectorOnEveryRank)
{
  const auto comm = Tpetra::getDefaultComm();
  const auto map = Teuchos::rcp(new Map(57, 0, comm));
  const auto replicated = Teuchos::rcp(new Map(57, 0, comm, Tpetra::LocallyReplicated));
  Vector distributed(map);
  {
    auto d = distributed.getDataNonConst();
    for (std::size_t k = 0; k < map->getNodeNumElements(); ++k) {
      d[k] = 3.0 * static_cast<double>(map->getGlobalElement(static_cast<int>(k))) + 1.0;
    }
  }
  Vector all(replicated);
  all.doImport(distributed, Tpetra::Import<>(map, replicated), Tpetra::INSERT);
  const auto a = all.getData();
  bool ok = a.size() == 57;
  for (decltype(a.size()) g = 0; g < a.size(); ++g) {
    ok = ok && a[g] == 3.0 * static_cast<double>(g) + 1.0; // exact: integers
  }
  EXPECT_TRUE(capsula::testing::allRanks(*comm, ok));
}

TEST(TpetraBelos, GmresWithMatrixFreeOperatorRecoversKnownSolution)
{
  const auto comm = Tpetra::getDefaultComm();
  const GO n = 200;
  const auto map = Teuchos::rcp(new Map(n, 0, comm));
  const auto op = Teuchos::rcp(new DenseKernelOperator(map));

  auto xExact = Teuchos::rcp(new MV(map, 1));
  {
    auto d = xExact->getDataNonConst(0);
    for (std::size_t k = 0; k < map->getNodeNumElements(); ++k) {
      d[k] = exactSolution(map->getGlobalElement(static_cast<int>(k)));
    }
  }
  auto b = Teuchos::rcp(new MV(map, 1));
  op->apply(*xExact, *b, Teuchos::NO_TRANS, 1.0, 0.0);

  // alpha and beta are honoured: 2 A x - 1 (A x) = A x.
  MV check(*b, Teuchos::Copy);
  op->apply(*xExact, check, Teuchos::NO_TRANS, 2.0, -1.0);
  check.update(-1.0, *b, 1.0);
  Teuchos::Array<double> diffNorm(1);
  check.norm2(diffNorm());

  auto x = Teuchos::rcp(new MV(map, 1));
  capsula::operators::SolverParameters solver;
  solver.method = "Block GMRES";
  solver.restart = 50;
  solver.tolerance = 1e-12;
  solver.maximumIterations = 200;
  const capsula::operators::KrylovResult result = capsula::operators::solveLinearSystem(op, b, x, solver);

  x->update(-1.0, *xExact, 1.0);
  Teuchos::Array<double> errorNorm(1);
  x->normInf(errorNorm());

  const bool ok = diffNorm[0] < 1e-12 // round-off on O(1) entries
                  && result.converged
                  // A = 2I + a rank-2 perturbation (cos(a - b) = cos a cos b + sin a sin b):
                  // GMRES must converge in at most 3 iterations in exact arithmetic.
                  && result.iterations <= 4 &&
                  result.residual < 1e-12
                  // Relative residual 1e-12 with a condition number O(1): an error O(1e-12).
                  && errorNorm[0] < 1e-10;
  EXPECT_TRUE(capsula::testing::allRanks(*comm, ok))
      << "rank " << comm->getRank() << ": |2Ax - Ax - Ax| " << diffNorm[0] << ", converged " << result.converged
      << " in " << result.iterations << " iterations, residual " << result.residual << ", error " << errorNorm[0];
}
