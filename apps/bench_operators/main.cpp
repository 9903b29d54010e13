// bench_operators: the cost of one velocity evaluation of the boundary-integral operators.
//
//   mpiexec -n 2 bench_operators [--level=3] [--kernel=Wall|FreeSpace|WallTensors] [--lambda=1]
//                                [--quadrature-points=7]
//                                [--rings=2] [--repeat=3]
//
// One spherical cell (radius 1, centre 2 above the wall) under a smooth non-uniform load.
// Prints, as the maximum over ranks of the best of --repeat runs:
//   geometry   rebuilding the quadrature caches after the nodes moved;
//   velocity   one node-velocity evaluation (singular and near-singular corrections, the
//              sums, and for lambda != 1 the GMRES solve, with its iterations);
//   direct sum the bare vectorised regular sum of the Stokeslet over every quadrature point
//              for the owned nodes (no corrections): the floor the evaluation is compared to.
#include <capsula/core/MpiSessionDirectory.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/operators/BuiltInKernels.hpp>
#include <capsula/operators/KernelRegistry.hpp>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_CommandLineProcessor.hpp>
#include <Tpetra_Core.hpp>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>

namespace {

using namespace capsula;
using namespace capsula::operators;
using Clock = std::chrono::steady_clock;

// Best of `repeat` runs, then the slowest rank (what the user waits for), in ms: wall
// clock, and the CPU time of the rank (which time-sharing with other jobs does not inflate).
struct Timing {
  double wall = 0.0;
  double cpu = 0.0;
};

Timing timeIt(const Teuchos::Comm<int>& comm, int repeat, const std::function<void()>& work)
{
  double bestWall = std::numeric_limits<double>::infinity();
  double bestCpu = std::numeric_limits<double>::infinity();
  for (int r = 0; r < repeat; ++r) {
    comm.barrier();
    const auto start = Clock::now();
    const std::clock_t cpuStart = std::clock();
    work();
    const double cpu = 1e3 * static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    bestWall = std::min(bestWall, std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    bestCpu = std::min(bestCpu, cpu);
  }
  Timing slowest;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, bestWall, Teuchos::outArg(slowest.wall));
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, bestCpu, Teuchos::outArg(slowest.cpu));
  return slowest;
}

template <class Kernel>
double directSum(LayerPotentials<Kernel>& potentials, const std::vector<double>& loads, std::vector<double>& out)
{
  // The regular sum alone: the same loop the evaluation runs, without corrections.
  const SurfaceQuadrature& quad = potentials.quadrature();
  const QuadraturePoints& p = quad.points();
  const int nq = quad.pointsPerElement();
  std::vector<double> fx(p.weight.size()), fy(fx.size()), fz(fx.size());
  for (std::size_t q = 0; q < fx.size(); ++q) {
    const double* f = &loads[3 * (q / nq)];
    fx[q] = f[0] * p.weight[q];
    fy[q] = f[1] * p.weight[q];
    fz[q] = f[2] * p.weight[q];
  }
  const SingleLayerSources sources{p.x.data(), p.y.data(), p.z.data(), fx.data(), fy.data(), fz.data()};
  const double* x = quad.nodePositions().data();
  const int first = potentials.firstTargetNode();
  const int n = potentials.numTargetNodes();
  out.resize(3 * static_cast<std::size_t>(n));
  for (int begin = 0; begin < n; begin += targetBlockSize) {
    TargetBlock block;
    block.start(std::min(targetBlockSize, n - begin));
    for (int k = 0; k < block.size; ++k) {
      block.x[k] = x[3 * (first + begin + k)];
      block.y[k] = x[3 * (first + begin + k) + 1];
      block.z[k] = x[3 * (first + begin + k) + 2];
    }
    block.pad();
    addSingleLayerSums<Kernel>(block, sources, 0, quad.numPoints());
    for (int k = 0; k < block.size; ++k) {
      out[3 * (begin + k)] = block.ux[k];
    }
  }
  return out.empty() ? 0.0 : out[0];
}

template <class Kernel>
int run(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int level, double lambda, int quadraturePoints, int rings,
        int repeat)
{
  const bool root = comm->getRank() == 0;
  mesh::Placement placement;
  placement.centre = mesh::Vec3(0.0, 2.0, 0.0);
  std::vector<mesh::SurfaceMesh> cells;
  cells.push_back(mesh::makeSphere(level, 1.0, placement));
  DiscretisationParameters discretisation;
  discretisation.quadraturePoints = quadraturePoints;
  discretisation.regularNeighbourRings = rings;
  KernelBoundaryIntegralSolver<Kernel> solver(comm, CellSurfaces(std::move(cells), lambda), discretisation,
                                              SolverParameters{});
  const CellSurfaces& surfaces = solver.surfaces();
  // A smooth non-uniform membrane load: an inflation-like normal part and a shear part.
  std::vector<double> loads;
  const auto& quad = solver.layerPotentials().quadrature();
  for (int m = 0; m < surfaces.numElements(); ++m) {
    const mesh::Vec3 c(quad.elements().cx[m], quad.elements().cy[m], quad.elements().cz[m]);
    const mesh::Vec3 n = (c - placement.centre).normalized();
    const mesh::Vec3 f = (2.0 + 0.5 * n[0] * n[1]) * n + 0.3 * mesh::Vec3(n[2], 0.0, -n[0]);
    loads.insert(loads.end(), {f[0], f[1], f[2]});
  }
  const std::vector<double> positions = surfaces.positions();
  FlowConditions flow;
  flow.capillaryNumber = 0.5;

  VelocitySolution solution;
  const Timing geometry = timeIt(*comm, repeat, [&] { solver.setPositions(positions.data()); });
  Timing velocity = timeIt(*comm, repeat, [&] {
    solver.setPositions(positions.data());
    solution = solver.nodeVelocities(LoadDensity::constantOverElements(loads), flow);
  });
  velocity.wall -= geometry.wall;
  velocity.cpu -= geometry.cpu;
  std::vector<double> direct;
  double sink = 0.0;
  const Timing directTime = timeIt(*comm, repeat, [&] { sink += directSum(solver.layerPotentials(), loads, direct); });
  const long long nearLocal = solver.layerPotentials().nearSingularElementCount();
  long long nearTotal = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, nearLocal, Teuchos::outArg(nearTotal));

  if (root) {
    const int numPoints = quad.numPoints();
    std::printf("bench_operators: %s kernel, %d rank(s), level %d: %d nodes, %d elements, N_Q = %d "
                "(%d quadrature points), N_GL = %d, regular neighbour rings %d, lambda = %g\n",
                Kernel::name, comm->getSize(), level, surfaces.numNodes(), surfaces.numElements(), quadraturePoints,
                numPoints, discretisation.singularQuadraturePoints, rings, lambda);
    std::printf("  near-singular (target, element) pairs: %lld (%.1f per node)\n", nearTotal,
                static_cast<double>(nearTotal) / surfaces.numNodes());
    std::printf("                           wall ms   cpu ms (slowest rank, best of %d)\n", repeat);
    std::printf("  geometry update          %8.1f  %8.1f\n", geometry.wall, geometry.cpu);
    std::printf("  velocity evaluation      %8.1f  %8.1f", velocity.wall, velocity.cpu);
    if (solution.iterations > 0) {
      std::printf("   GMRES: %d iterations, residual %.2e", solution.iterations, solution.residual);
    }
    std::printf("\n  direct sum (floor)       %8.1f  %8.1f   (%d targets x %d points)\n", directTime.wall,
                directTime.cpu, surfaces.numNodes(), numPoints);
    std::printf("  ratio velocity / direct  %8.2f  %8.2f\n", velocity.wall / directTime.wall,
                velocity.cpu / directTime.cpu);
    std::printf("  target: 50 ms per velocity evaluation on 2 cores; velocity / 50 ms: %.2f (wall)\n",
                velocity.wall / 50.0);
    std::printf("  (direct-sum checksum %.6e)\n", sink);
  }
  return 0;
}

} // namespace

int main(int argc, char* argv[])
{
  const capsula::core::MpiSessionDirectory sessionDirectory; // outlives MPI
  Tpetra::ScopeGuard scope(&argc, &argv);
  const auto comm = Tpetra::getDefaultComm();
  int level = 3, quadraturePoints = 7, repeat = 3;
  int rings = DiscretisationParameters{}.regularNeighbourRings;
  double lambda = 1.0;
  std::string kernel = "Wall";
  Teuchos::CommandLineProcessor clp(false, true);
  clp.setDocString("Times one velocity evaluation of the boundary-integral operators.");
  clp.setOption("level", &level, "icosphere level of the cell (3: 2562 nodes)");
  clp.setOption("kernel", &kernel, "Wall, FreeSpace, or WallTensors (the wall kernel without the contracted forms)");
  clp.setOption("lambda", &lambda, "viscosity ratio (1: explicit; otherwise GMRES)");
  clp.setOption("quadrature-points", &quadraturePoints, "N_Q");
  clp.setOption("rings", &rings, "regular neighbour rings (0: subdivide near elements of the own cell too)");
  clp.setOption("repeat", &repeat, "runs per measurement (the best counts)");
  if (clp.parse(argc, argv) != Teuchos::CommandLineProcessor::PARSE_SUCCESSFUL) {
    return 1;
  }
  try {
    if (kernel == "Wall") {
      return run<Wall3DKernel>(comm, level, lambda, quadraturePoints, rings, repeat);
    }
    if (kernel == "FreeSpace") {
      return run<FreeSpace3DKernel>(comm, level, lambda, quadraturePoints, rings, repeat);
    }
    if (kernel == "WallTensors") {
      // The wall kernel straight from greens: full tensors contracted in the loops.
      return run<greens::Wall3D>(comm, level, lambda, quadraturePoints, rings, repeat);
    }
    std::fprintf(stderr, "bench_operators: unknown --kernel=%s (Wall, FreeSpace or WallTensors)\n", kernel.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_operators: %s\n", e.what());
  }
  return 1;
}
