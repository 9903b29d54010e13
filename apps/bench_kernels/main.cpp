// bench_kernels: Google Benchmark microbenchmarks of the boundary-integral kernels and operators.
//
//   bench_kernels [--benchmark_filter=REGEX] [--benchmark_repetitions=N] ...
//
// Sums:      one block of targetBlockSize targets against the 8960 quadrature points of a
//            level-3 cell at N_Q = 7 (the inner loop of every evaluation), single and double
//            layer, free-space and wall kernels; counters give (target, source) pairs per second.
// Operators: one node-velocity evaluation of a sphere above the wall (levels 1-3, lambda = 1;
//            level 2, lambda = 5 with its GMRES solve), one rank; and the geometry update.
// Wall times on a shared machine: compare runs made at the same load (utils/bench/bench_targets.py
// records the load; docs/accuracy-cost.md).
#include <capsula/core/CommandLine.hpp>
#include <capsula/core/MpiSessionDirectory.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/operators/BuiltInKernels.hpp>
#include <capsula/operators/KernelRegistry.hpp>

#include <Tpetra_Core.hpp>
#include <benchmark/benchmark.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

namespace {

using namespace capsula;
using namespace capsula::operators;

constexpr int level3Points = 1280 * 7; // level-3 elements x N_Q = 7

// Points on a unit sphere centred 2 above the wall, spread by the golden-angle spiral.
struct Cloud {
  std::vector<double> x, y, z, fx, fy, fz;
  explicit Cloud(int n)
  {
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
      const double c = 1.0 - 2.0 * (i + 0.5) / n;
      const double s = std::sqrt(1.0 - c * c);
      x.push_back(s * std::cos(golden * i));
      y.push_back(2.0 + c);
      z.push_back(s * std::sin(golden * i));
      fx.push_back(0.1 * c);
      fy.push_back(1.0 + 0.2 * s);
      fz.push_back(-0.1 * c);
    }
  }
};

TargetBlock makeBlock(const Cloud& targets)
{
  TargetBlock block;
  block.start(targetBlockSize);
  for (int t = 0; t < targetBlockSize; ++t) {
    block.x[t] = targets.x[t];
    block.y[t] = targets.y[t] + 0.01; // off the source points
    block.z[t] = targets.z[t];
  }
  block.pad();
  return block;
}

template <class Kernel>
void singleLayerSums(benchmark::State& state)
{
  const Cloud sources(level3Points);
  const Cloud targets(targetBlockSize);
  const SingleLayerSources s{sources.x.data(),  sources.y.data(),  sources.z.data(),
                             sources.fx.data(), sources.fy.data(), sources.fz.data()};
  TargetBlock block = makeBlock(targets);
  for (auto _ : state) {
    addSingleLayerSums<Kernel>(block, s, 0, level3Points);
    benchmark::DoNotOptimize(block.ux[0]);
    benchmark::ClobberMemory();
  }
  state.counters["pairs/s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * targetBlockSize * level3Points, benchmark::Counter::kIsRate);
}

template <class Kernel>
void doubleLayerSums(benchmark::State& state)
{
  const Cloud sources(level3Points);
  const Cloud targets(targetBlockSize);
  // Weighted normals a = n w (outward radial on the sphere) and a density v.
  std::vector<double> ax(level3Points), ay(level3Points), az(level3Points);
  for (int q = 0; q < level3Points; ++q) {
    ax[q] = sources.x[q] * 1e-3;
    ay[q] = (sources.y[q] - 2.0) * 1e-3;
    az[q] = sources.z[q] * 1e-3;
  }
  const DoubleLayerSources s{sources.x.data(), sources.y.data(),  sources.z.data(),  ax.data(),        ay.data(),
                             az.data(),        sources.fx.data(), sources.fy.data(), sources.fz.data()};
  TargetBlock block = makeBlock(targets);
  for (auto _ : state) {
    addDoubleLayerSums<Kernel, true>(block, s, 0, level3Points);
    benchmark::DoNotOptimize(block.ux[0]);
    benchmark::ClobberMemory();
  }
  state.counters["pairs/s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * targetBlockSize * level3Points, benchmark::Counter::kIsRate);
}

// One sphere (radius 1, centre 2 above the wall) and a smooth load, as in bench_operators.
struct Scene {
  std::unique_ptr<KernelBoundaryIntegralSolver<Wall3DKernel>> solver;
  std::vector<double> loads, positions;
  Scene(int level, double lambda)
  {
    mesh::Placement placement;
    placement.centre = mesh::Vec3(0.0, 2.0, 0.0);
    std::vector<mesh::SurfaceMesh> cells;
    cells.push_back(mesh::makeSphere(level, 1.0, placement));
    solver = std::make_unique<KernelBoundaryIntegralSolver<Wall3DKernel>>(
        Tpetra::getDefaultComm(), CellSurfaces(std::move(cells), lambda), DiscretisationParameters{},
        SolverParameters{});
    const auto& quad = solver->layerPotentials().quadrature();
    for (int m = 0; m < solver->surfaces().numElements(); ++m) {
      const mesh::Vec3 c(quad.elements().cx[m], quad.elements().cy[m], quad.elements().cz[m]);
      const mesh::Vec3 n = (c - placement.centre).normalized();
      const mesh::Vec3 f = (2.0 + 0.5 * n[0] * n[1]) * n + 0.3 * mesh::Vec3(n[2], 0.0, -n[0]);
      loads.insert(loads.end(), {f[0], f[1], f[2]});
    }
    positions = solver->surfaces().positions();
  }
};

void nodeVelocities(benchmark::State& state, double lambda)
{
  Scene scene(static_cast<int>(state.range(0)), lambda);
  FlowConditions flow;
  flow.capillaryNumber = 0.5;
  int iterations = 0;
  for (auto _ : state) {
    const VelocitySolution solution =
        scene.solver->nodeVelocities(LoadDensity::constantOverElements(scene.loads), flow);
    iterations = solution.iterations;
    benchmark::DoNotOptimize(solution);
  }
  state.counters["nodes"] = scene.solver->surfaces().numNodes();
  state.counters["gmres_iterations"] = iterations;
}

void geometryUpdate(benchmark::State& state)
{
  Scene scene(static_cast<int>(state.range(0)), 1.0);
  for (auto _ : state) {
    scene.solver->setPositions(scene.positions.data());
  }
}

BENCHMARK_TEMPLATE(singleLayerSums, FreeSpace3DKernel)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(singleLayerSums, Wall3DKernel)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(doubleLayerSums, FreeSpace3DKernel)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(doubleLayerSums, Wall3DKernel)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(nodeVelocities, lambda1, 1.0)->DenseRange(1, 3)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(nodeVelocities, lambda5, 5.0)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(geometryUpdate)->DenseRange(1, 3)->Unit(benchmark::kMillisecond);

} // namespace

// Our usage, with Google Benchmark's flags that matter here and their defaults (version 1.7).
constexpr const char* usageText =
    "Usage: bench_kernels [--benchmark_filter=REGEX] [--benchmark_repetitions=N]\n"
    "                     [--benchmark_min_time=SECONDS] [--benchmark_format=console|json|csv]\n"
    "                     [--benchmark_out=FILE] [--benchmark_list_tests]\n"
    "\n"
    "Google Benchmark microbenchmarks of the boundary-integral kernels and operators, one rank:\n"
    "the regular sums of one target block against a level-3 cell (singleLayerSums, doubleLayerSums;\n"
    "free-space and wall kernels), one node-velocity evaluation of a sphere above the wall\n"
    "(nodeVelocities, levels 1-3 at lambda = 1, level 2 at lambda = 5) and the geometry update.\n"
    "\n"
    "  --benchmark_filter=REGEX        run the benchmarks whose name matches (default: all)\n"
    "  --benchmark_repetitions=N       run each N times and report mean, median, stddev (default 1)\n"
    "  --benchmark_min_time=SECONDS    least time per benchmark (default 0.5)\n"
    "  --benchmark_format=FORMAT       console, json or csv (default console)\n"
    "  --benchmark_out=FILE            also write the results to FILE (json unless\n"
    "                                  --benchmark_out_format says otherwise)\n"
    "  --benchmark_list_tests          print the benchmarks' names and exit\n"
    "  --help                          this text\n"
    "\n"
    "utils/bench/accuracy-cost.sh runs it for docs/accuracy-cost.md.\n";

int main(int argc, char* argv[])
{
  // Our usage before MPI and Kokkos start (Kokkos answers --help with its own options).
  if (capsula::core::asksForHelp(argc, argv)) {
    std::cout << usageText;
    return 0;
  }
  // Tpetra (and MPI) around the whole run: the operators use a Teuchos communicator.
  const capsula::core::MpiSessionDirectory sessionDirectory; // outlives MPI
  Tpetra::ScopeGuard scope(&argc, &argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
    return 1;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
