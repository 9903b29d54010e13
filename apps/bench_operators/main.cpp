// bench_operators: the cost of one velocity evaluation of the boundary-integral operators.
//
//   mpiexec -n 2 bench_operators [--level=3] [--kernel=Wall|FreeSpace|WallTensors|PeriodicWall|PeriodicChannel]
//                                [--lambda=1] [--channel-height=4.4]
//                                [--quadrature-points=7]
//                                [--rings=2] [--repeat=3] [--cells=1]
//                                [--summation=Direct|Treecode] [--tolerance=1e-5]
//                                [--cell-gap=0.2] [--wall-gap=0.2] [--single-layer=table|float|double]
//
// One spherical cell (radius 1, centre 2 above the wall) under a smooth non-uniform load;
// with --cells=N > 1, N unit spheres 0.2 above the wall on a square grid of pitch 2.2 in
// the wall plane (gaps of 0.2, no overlap; --cell-gap and --wall-gap set the gaps between
// neighbours and above the wall). --kernel=PeriodicWall puts the grid in a box periodic along
// x and z whose periods are the grid's (columns and rows times the pitch, so the neighbours'
// gaps repeat across the boundary), its far field the spectral Ewald sum to --ewald-tolerance
// (docs/domains.md); --kernel=PeriodicChannel does the same in the channel 0 < y < H,
// H = --channel-height (4.4: the grid's volume fraction 0.2 at any N). --summation picks the
// far-field back-end of the
// regular sums ('Operator/Summation'; Treecode to --tolerance, docs/fastsum.md; the single
// layer's precision from the tolerance's table row or, with --single-layer, float or
// double); for Treecode the velocities are also computed with Direct and their relative
// difference (2-norm) printed, and the single and double layers' errors per node: the
// largest |u_i - u_i,Direct| over max_i |u_i,Direct| (u_i the node's 3-vector), beside the
// 2-norm relative error the tolerance table is measured in. Prints, as the maximum over ranks
// of the best of --repeat runs:
//   geometry   rebuilding the quadrature caches after the nodes moved;
//   velocity   one node-velocity evaluation (singular and near-singular corrections, the
//              sums, and for lambda != 1 the GMRES solve, with its iterations);
//   direct sum the bare vectorised regular sum of the Stokeslet over every quadrature point
//              for the owned nodes (no corrections): the floor the evaluation is compared to;
//   memory     the peak resident memory of every rank (MiB) after the evaluations with
//              --summation, before a Treecode run builds its Direct reference.
#include <capsula/fastsum/LargestNodeError.hpp>
#include <capsula/core/CommandLine.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/core/MpiSessionDirectory.hpp>
#include <capsula/core/PeakMemory.hpp>
#include <capsula/fastsum/TreecodeBackEnd.hpp>
#include <capsula/fastsum/TreecodeSummation.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/operators/BuiltInKernels.hpp>
#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/periodic/PeriodicOperators.hpp>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_CommandLineProcessor.hpp>
#include <Tpetra_Core.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <ctime>
#include <cstdio>
#include <functional>
#include <iostream>
#include <limits>
#include <string>
#include <type_traits>

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

struct BenchOptions {
  int level = 3;
  double lambda = 1.0;
  int quadraturePoints = 7;
  int rings = DiscretisationParameters{}.regularNeighbourRings;
  int repeat = 3;
  int cells = 1;
  std::string summation = "Direct";
  double tolerance = 1e-5;
  int leafSize = fastsum::TreecodeParameters{}.leafSize;
  int batchSize = fastsum::TreecodeParameters{}.batchSize;
  double cellGap = 0.2;
  double wallGap = -1.0; ///< < 0: 1 for one cell (centre 2 above the wall), else 0.2
  std::string singleLayer = "table";
  double ewaldTolerance = 1e-6;  ///< PeriodicWall, PeriodicChannel: 'Operator/<kernel>/Tolerance'
  double boxX = 0.0, boxZ = 0.0; ///< PeriodicWall, PeriodicChannel: the periods, set from the grid
  double channelHeight = 4.4;    ///< PeriodicChannel: H
};

// The centres of the unit cells: one 2 above the wall, or a square grid 0.2 above it, the
// neighbours 0.2 apart (other gaps from --wall-gap and --cell-gap).
std::vector<mesh::Vec3> cellCentres(const BenchOptions& options)
{
  const int n = options.cells;
  const double height = 1.0 + (options.wallGap >= 0.0 ? options.wallGap : n == 1 ? 1.0 : 0.2);
  const double pitch = 2.0 + options.cellGap;
  const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  std::vector<mesh::Vec3> centres;
  for (int c = 0; c < n; ++c) {
    centres.emplace_back(pitch * (c % columns), height, pitch * (c / columns));
  }
  return centres;
}

// The box periodic along x and z that repeats the grid of cellCentres: columns and rows
// times the pitch.
void setGridBox(BenchOptions& options)
{
  const int n = options.cells;
  const double pitch = 2.0 + options.cellGap;
  const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  const int rows = (n + columns - 1) / columns;
  options.boxX = columns * pitch;
  options.boxZ = rows * pitch;
}

using capsula::fastsum::largestNodeError; // fastsum/LargestNodeError.hpp

double relativeDifference(const std::vector<double>& u, const std::vector<double>& reference)
{
  double difference = 0.0, norm = 0.0;
  for (std::size_t k = 0; k < u.size(); ++k) {
    difference += (u[k] - reference[k]) * (u[k] - reference[k]);
    norm += reference[k] * reference[k];
  }
  return std::sqrt(difference / norm);
}

struct LayerErrors {
  double singleLargest = 0.0, single2 = 0.0, doubleLargest = 0.0, double2 = 0.0;
};

// The single layer of the membrane load and the double layer (subtracted form) of a smooth
// density, the rigid rotation about z plus a stretch, against the direct sums.
LayerErrors layerErrors(BoundaryIntegralSolver& fast, BoundaryIntegralSolver& direct, const std::vector<double>& loads)
{
  LayerErrors out;
  const LoadDensity load = LoadDensity::constantOverElements(loads);
  const std::vector<double> single = fast.singleLayer(load), singleReference = direct.singleLayer(load);
  out.singleLargest = largestNodeError(single, singleReference);
  out.single2 = relativeDifference(single, singleReference);
  std::vector<double> density = direct.surfaces().positions();
  for (std::size_t g = 0; 3 * g < density.size(); ++g) {
    const double x = density[3 * g], y = density[3 * g + 1];
    density[3 * g] = -y + 0.2 * x;
    density[3 * g + 1] = x;
    density[3 * g + 2] = 0.1;
  }
  const std::vector<double> dbl = fast.doubleLayer(density.data(), DoubleLayerForm::Subtracted);
  const std::vector<double> dblReference = direct.doubleLayer(density.data(), DoubleLayerForm::Subtracted);
  out.doubleLargest = largestNodeError(dbl, dblReference);
  out.double2 = relativeDifference(dbl, dblReference);
  return out;
}

template <class Kernel>
int run(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const BenchOptions& options, const Kernel& kernel = {})
{
  const bool root = comm->getRank() == 0;
  const int level = options.level, quadraturePoints = options.quadraturePoints, rings = options.rings;
  const int repeat = options.repeat;
  const double lambda = options.lambda;
  core::require<core::InputError>(options.cells >= 1, "--cells=", options.cells, ": give at least 1 cell.");
  core::require<core::InputError>(options.cellGap > 0.0 && options.wallGap != 0.0, "--cell-gap=", options.cellGap,
                                  ", --wall-gap=", options.wallGap, ": the cells must not touch.");
  const std::vector<mesh::Vec3> centres = cellCentres(options);
  std::vector<mesh::SurfaceMesh> cells;
  for (const mesh::Vec3& centre : centres) {
    mesh::Placement placement;
    placement.centre = centre;
    cells.push_back(mesh::makeSphere(level, 1.0, placement));
  }
  DiscretisationParameters discretisation;
  discretisation.quadraturePoints = quadraturePoints;
  discretisation.regularNeighbourRings = rings;
  const DiscretisationParameters directDiscretisation = discretisation;
  if (options.summation == "Treecode") {
    auto parameters = fastsum::treecodeParametersForTolerance(options.tolerance);
    parameters.leafSize = options.leafSize;
    parameters.batchSize = options.batchSize;
    if (options.singleLayer != "table") {
      core::require<core::InputError>(options.singleLayer == "float" || options.singleLayer == "double",
                                      "--single-layer=", options.singleLayer, ": use table, float or double.");
      parameters.singlePrecision = options.singleLayer == "float";
    }
    discretisation.farField = std::make_shared<fastsum::TreecodeBackEnd>(parameters);
  } else if (options.summation != "Direct") {
    throw core::InputError(core::message("--summation=", options.summation, ": use Direct or Treecode."));
  }
  const CellSurfaces scene(std::move(cells), lambda);
  KernelBoundaryIntegralSolver<Kernel> solver(comm, scene, discretisation, SolverParameters{}, kernel);
  const CellSurfaces& surfaces = solver.surfaces();
  // A smooth non-uniform membrane load: an inflation-like normal part and a shear part.
  std::vector<double> loads;
  const auto& quad = solver.layerPotentials().quadrature();
  for (int m = 0; m < surfaces.numElements(); ++m) {
    const mesh::Vec3 c(quad.elements().cx[m], quad.elements().cy[m], quad.elements().cz[m]);
    const mesh::Vec3 n = (c - centres[surfaces.cellOfElement(m)]).normalized();
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
  const std::vector<double> memory = core::peakResidentMiBPerRank(*comm);
  std::vector<double> direct;
  double sink = 0.0;
  Timing directTime;
  double difference = -1.0;
  Timing reference;
  LayerErrors layers;
  constexpr bool periodic =
      std::is_same_v<Kernel, periodic::PeriodicWallKernel> || std::is_same_v<Kernel, periodic::PeriodicChannelKernel>;
  if (options.summation == "Direct") {
    if constexpr (!periodic) { // a periodic kernel's regular sums are its Ewald sums, timed above
      directTime = timeIt(*comm, repeat, [&] { sink += directSum(solver.layerPotentials(), loads, direct); });
    }
  } else {
    // The same evaluation with the direct sums, once: the reference and its time.
    KernelBoundaryIntegralSolver<Kernel> directSolver(comm, scene, directDiscretisation, SolverParameters{}, kernel);
    VelocitySolution exact;
    reference = timeIt(*comm, 1, [&] {
      directSolver.setPositions(positions.data());
      exact = directSolver.nodeVelocities(LoadDensity::constantOverElements(loads), flow);
    });
    difference = relativeDifference(solution.velocities, exact.velocities);
    layers = layerErrors(solver, directSolver, loads);
  }
  const long long nearLocal = solver.layerPotentials().nearSingularElementCount();
  long long nearTotal = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, nearLocal, Teuchos::outArg(nearTotal));

  if (root) {
    const int numPoints = quad.numPoints();
    std::printf("bench_operators: %s kernel, %d rank(s), %d cell(s) at level %d: %d nodes, %d elements, N_Q = %d "
                "(%d quadrature points), N_GL = %d, regular neighbour rings %d, lambda = %g, summation %s",
                Kernel::name, comm->getSize(), surfaces.numCells(), level, surfaces.numNodes(), surfaces.numElements(),
                quadraturePoints, numPoints, discretisation.singularQuadraturePoints, rings, lambda,
                options.summation.c_str());
    if (options.summation == "Treecode") {
      const auto p = fastsum::treecodeParametersForTolerance(options.tolerance);
      const bool single = options.singleLayer == "table" ? p.singlePrecision : options.singleLayer == "float";
      const char* precision = single ? "single layer in float" : "double";
      std::printf(" (tolerance %.0e: degree %d, theta %.2f, leaf size %d, %s)", options.tolerance, p.degree, p.theta,
                  options.leafSize, precision);
    }
    std::printf("\n");
    std::printf("  near-singular (target, element) pairs: %lld (%.1f per node)\n", nearTotal,
                static_cast<double>(nearTotal) / surfaces.numNodes());
    std::printf("  peak resident memory per rank (MiB):");
    for (const double mib : memory) {
      std::printf(" %.1f", mib);
    }
    std::printf("\n");
    std::printf("                           wall ms   cpu ms (slowest rank, best of %d)\n", repeat);
    std::printf("  geometry update          %8.1f  %8.1f\n", geometry.wall, geometry.cpu);
    std::printf("  velocity evaluation      %8.1f  %8.1f", velocity.wall, velocity.cpu);
    if (solution.iterations > 0) {
      std::printf("   GMRES: %d iterations, residual %.2e", solution.iterations, solution.residual);
    }
    std::printf("\n");
    if (difference >= 0.0) {
      std::printf("  same with Direct         %8.1f  %8.1f   (once)\n", reference.wall, reference.cpu);
      std::printf("  speed-up over Direct     %8.2f  %8.2f\n", reference.wall / velocity.wall,
                  reference.cpu / velocity.cpu);
      std::printf("  relative difference from Direct (2-norm over the node velocities): %.2e\n", difference);
      std::printf("  layers against Direct: single layer largest node error %.2e (2-norm %.2e), double layer "
                  "largest node error %.2e (2-norm %.2e)\n",
                  layers.singleLargest, layers.single2, layers.doubleLargest, layers.double2);
      const auto* fast = dynamic_cast<const fastsum::TreecodeSummation<Kernel>*>(&solver.layerPotentials().farField());
      if (fast) {
        const auto& lists = fast->treecode().interactionLists();
        const double all = static_cast<double>(surfaces.numNodes()) * numPoints;
        std::printf("  kernel evaluations per single layer: direct %.3g, proxy %.3g (%.3f of all pairs)\n",
                    static_cast<double>(lists.directPairs), static_cast<double>(lists.proxyPairs),
                    (lists.directPairs + lists.proxyPairs) / all);
      }
      std::printf("  (velocity cpu ms per cell: %.1f)\n", velocity.cpu / surfaces.numCells());
      return 0;
    }
    if (periodic) {
      std::printf("  box %g x %g, Ewald tolerance %.0e; (velocity cpu ms per cell: %.1f)\n", options.boxX, options.boxZ,
                  options.ewaldTolerance, velocity.cpu / surfaces.numCells());
      if (std::is_same_v<Kernel, periodic::PeriodicChannelKernel>) {
        std::printf("  channel height %g, volume fraction %.3f\n", options.channelHeight,
                    surfaces.numCells() * 4.0 * M_PI / 3.0 / (options.boxX * options.boxZ * options.channelHeight));
      }
      return 0;
    }
    std::printf("  direct sum (floor)       %8.1f  %8.1f   (%d targets x %d points)\n", directTime.wall, directTime.cpu,
                surfaces.numNodes(), numPoints);
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
  BenchOptions options;
  std::string kernel = "Wall";
  Teuchos::CommandLineProcessor clp(false, true);
  clp.setDocString("Times one velocity evaluation of the boundary-integral operators "
                   "(mpiexec -n N bench_operators [options]).");
  clp.setOption("level", &options.level, "icosphere level of the cells (3: 2562 nodes each)");
  clp.setOption("kernel", &kernel,
                "Wall, FreeSpace, WallTensors (the wall kernel without the contracted forms), PeriodicWall (the grid "
                "in a periodic box) or PeriodicChannel (the same in a channel)");
  clp.setOption("ewald-tolerance", &options.ewaldTolerance,
                "PeriodicWall, PeriodicChannel: tolerance of the spectral Ewald sums");
  clp.setOption("channel-height", &options.channelHeight, "PeriodicChannel: the channel's height H");
  clp.setOption("lambda", &options.lambda, "viscosity ratio (1: explicit; otherwise GMRES)");
  clp.setOption("quadrature-points", &options.quadraturePoints, "N_Q");
  clp.setOption("rings", &options.rings, "regular neighbour rings (0: subdivide near elements of the own cell too)");
  clp.setOption("repeat", &options.repeat, "runs per measurement (the best counts)");
  clp.setOption("cells", &options.cells, "cells: 1 (2 above the wall) or N on a grid 0.2 above the wall");
  clp.setOption("summation", &options.summation, "far-field back-end: Direct or Treecode");
  clp.setOption("tolerance", &options.tolerance, "treecode tolerance (Operator/Treecode/Tolerance)");
  clp.setOption("leaf-size", &options.leafSize, "treecode leaf size (Operator/Treecode/Leaf size)");
  clp.setOption("batch-size", &options.batchSize, "most targets in a treecode batch (<= 128)");
  clp.setOption("cell-gap", &options.cellGap, "gap between neighbouring cells (units of the radius)");
  clp.setOption("wall-gap", &options.wallGap, "gap between the cells and the wall (default 1 for one cell, else 0.2)");
  clp.setOption("single-layer", &options.singleLayer, "treecode single layer: table (the tolerance's), float, double");
  // Our usage, with the defaults, before MPI and Kokkos start (Kokkos answers --help with its own).
  if (capsula::core::asksForHelp(argc, argv)) {
    clp.printHelpMessage("bench_operators", std::cout);
    return 0;
  }
  const capsula::core::MpiSessionDirectory sessionDirectory; // outlives MPI
  Tpetra::ScopeGuard scope(&argc, &argv);
  const auto comm = Tpetra::getDefaultComm();
  if (clp.parse(argc, argv) != Teuchos::CommandLineProcessor::PARSE_SUCCESSFUL) {
    return 1;
  }
  try {
    if (kernel == "Wall") {
      return run<Wall3DKernel>(comm, options);
    }
    if (kernel == "FreeSpace") {
      return run<FreeSpace3DKernel>(comm, options);
    }
    if (kernel == "PeriodicWall") {
      setGridBox(options);
      periodic::PeriodicWallKernel policy;
      policy.box = periodic::PeriodicBox{options.boxX, options.boxZ};
      policy.tolerance = options.ewaldTolerance;
      core::require<core::InputError>(
          options.summation == "Direct",
          "--kernel=PeriodicWall: --summation=Direct only (its far field is its Ewald sum).");
      return run<periodic::PeriodicWallKernel>(comm, options, policy);
    }
    if (kernel == "PeriodicChannel") {
      setGridBox(options);
      periodic::PeriodicChannelKernel policy;
      policy.box = periodic::PeriodicBox{options.boxX, options.boxZ};
      policy.tolerance = options.ewaldTolerance;
      policy.local.height = options.channelHeight;
      const double top = 2.0 + (options.wallGap >= 0.0 ? options.wallGap : options.cells == 1 ? 1.0 : 0.2);
      core::require<core::InputError>(options.summation == "Direct" && options.channelHeight > top,
                                      "--kernel=PeriodicChannel: --summation=Direct only (its far field is its Ewald "
                                      "sum), and --channel-height above the cells' tops (",
                                      top, ").");
      return run<periodic::PeriodicChannelKernel>(comm, options, policy);
    }
    if (kernel == "WallTensors") {
      // The wall kernel straight from greens: full tensors contracted in the loops.
      return run<greens::Wall3D>(comm, options);
    }
    std::fprintf(stderr,
                 "bench_operators: unknown --kernel=%s (Wall, FreeSpace, WallTensors, PeriodicWall or "
                 "PeriodicChannel)\n",
                 kernel.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_operators: %s\n", e.what());
  }
  return 1;
}
