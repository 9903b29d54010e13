// bench_ewald: the cost of one spectral Ewald evaluation of the doubly periodic Stokeslet
// (packages/ewald, SpectralEwald2P.hpp) for N random sources, which are also the targets.
//
//   bench_ewald [--tolerance=1e-6] [--sizes=1000,10000,100000] [--repeat=3] [--density=1]
//               [--kernel=stokeslet|stresslet|wall|channel]
//
// The points fill a cube periodic in x and z, of side (N / density)^{1/3}, with random forces
// (or, with --kernel=stresslet, random tensors S_jk for the stresslet's sum; with --kernel=wall
// the cube stands on the no-slip wall y = 0 and the sum is SpectralEwaldWall2P's, whose grid
// also covers the mirror points, so xi and the grid printed are those of 2N points; with
// --kernel=channel the cube is the periodic channel 0 < y < H = side and the sum is
// SpectralEwaldChannel2P's, two lower-wall sums of about N/2 sources each, xi and the grid
// printed those of one, and before the table the fast sum's error against the reference
// series for 48 sources and 16 targets in a channel of side 4). Prints per N the
// best of --repeat wall-clock times of one evaluation (for the Stokeslet also split into the
// local and the smooth part), xi and the grid, and the time divided by N log2 N (constant when
// the cost grows like N log N).
#include <capsula/ewald/ChannelStokeslet2P.hpp>
#include <capsula/ewald/SpectralEwald2P.hpp>
#include <capsula/ewald/SpectralEwaldChannel2P.hpp>
#include <capsula/ewald/SpectralEwaldStresslet2P.hpp>
#include <capsula/ewald/SpectralEwaldWall2P.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <algorithm>
#include <utility>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

struct Options {
  double tolerance = 1e-6;
  std::vector<int> sizes{1000, 10000, 100000};
  int repeat = 3;
  double density = 1.0;
  std::string kernel = "stokeslet";
};

void printUsage()
{
  std::printf("Usage: bench_ewald [options]\n"
              "  --tolerance=TOL     relative tolerance of the sum (default: 1e-6)\n"
              "  --sizes=N1,N2,...   numbers of points (default: 1000,10000,100000)\n"
              "  --repeat=R          evaluations per size, the best is printed (default: 3)\n"
              "  --density=RHO       points per unit volume (default: 1)\n"
              "  --kernel=NAME       stokeslet, stresslet, wall or channel (default: stokeslet)\n");
}

/// Parses --key=value flags; false (after a message) on anything else.
bool parseOptions(int argc, char** argv, Options& options)
{
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    const auto equals = arg.find('=');
    const std::string key = arg.substr(0, equals);
    const std::string value = equals == std::string::npos ? "" : arg.substr(equals + 1);
    if (key == "--tolerance" && std::atof(value.c_str()) > 0.0 && std::atof(value.c_str()) < 1.0) {
      options.tolerance = std::atof(value.c_str());
    } else if (key == "--repeat" && std::atoi(value.c_str()) > 0) {
      options.repeat = std::atoi(value.c_str());
    } else if (key == "--density" && std::atof(value.c_str()) > 0.0) {
      options.density = std::atof(value.c_str());
    } else if (key == "--kernel" &&
               (value == "stokeslet" || value == "stresslet" || value == "wall" || value == "channel")) {
      options.kernel = value;
    } else if (key == "--sizes" && !value.empty()) {
      options.sizes.clear();
      std::stringstream list(value);
      std::string item;
      while (std::getline(list, item, ',')) {
        if (std::atoi(item.c_str()) < 2) {
          std::fprintf(stderr, "bench_ewald: error: --sizes needs integers >= 2, got '%s'\n", item.c_str());
          return false;
        }
        options.sizes.push_back(std::atoi(item.c_str()));
      }
    } else {
      std::fprintf(stderr, "bench_ewald: error: unknown or invalid option '%s' (--help lists them)\n", arg.c_str());
      return false;
    }
  }
  return true;
}

double secondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void runSize(int count, const Options& options)
{
  using namespace capsula::ewald;
  const double side = std::cbrt(count / options.density);
  const PeriodicLayer layer{side, side};
  std::mt19937 generator(12345u + static_cast<unsigned>(count));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const bool stokeslet = options.kernel == "stokeslet";
  const bool wall = options.kernel == "wall";
  const bool channel = options.kernel == "channel";
  const int components = options.kernel == "stresslet" ? 9 : 3;
  std::vector<double> points(3 * count), forces(static_cast<std::size_t>(components) * count);
  for (double& p : points) {
    p = side * (1.0 - unit(generator)); // in (0, side]: above the wall for --kernel=wall
  }
  for (std::size_t n = 1; channel && n < points.size(); n += 3) {
    points[n] = side * (0.001 + 0.998 * unit(generator)); // inside the channel 0 < y < side
  }
  for (double& f : forces) {
    f = 2.0 * unit(generator) - 1.0;
  }
  const SpectralEwaldSettings settings = wall ? spectralEwaldSettings(layer, options.tolerance, -side, side, 2 * count)
                                         : channel
                                             ? spectralEwaldSettings(layer, options.tolerance, -0.5 * side, side, count)
                                             : spectralEwaldSettings(layer, options.tolerance, 0.0, side, count);
  double bestLocal = 1e300, bestSmooth = 1e300, bestTotal = 1e300;
  for (int r = 0; r < options.repeat && !stokeslet; ++r) {
    const auto start = Clock::now();
    const auto u = wall      ? spectralEwaldWall2P(layer, options.tolerance, points, forces, points)
                   : channel ? spectralEwaldChannel2P(layer, side, options.tolerance, points, forces, points)
                             : spectralEwaldStresslet2P(layer, options.tolerance, points, forces, points);
    bestTotal = std::min(bestTotal, secondsSince(start));
  }
  for (int r = 0; r < options.repeat && stokeslet; ++r) {
    std::vector<double> u(3 * count, 0.0);
    const auto start = Clock::now();
    addLocalPart2P(layer, settings, points, forces, points, u);
    const double local = secondsSince(start);
    const auto smoothStart = Clock::now();
    addSmoothPart2P(layer, settings, points, forces, points, u);
    const double smooth = secondsSince(smoothStart);
    bestLocal = std::min(bestLocal, local);
    bestSmooth = std::min(bestSmooth, smooth);
    bestTotal = std::min(bestTotal, local + smooth);
  }
  const double nLogN = count * std::log2(static_cast<double>(count));
  char local[32] = "-", smooth[32] = "-";
  if (stokeslet) {
    std::snprintf(local, sizeof local, "%.4f", bestLocal);
    std::snprintf(smooth, sizeof smooth, "%.4f", bestSmooth);
  }
  std::printf("%8d %10.4f %10.10s %10.10s %7.3f %4d x %4d x %4d %12.3e\n", count, bestTotal, local, smooth, settings.xi,
              settings.gridX, settings.gridY, settings.gridZ, bestTotal / nLogN * 1e6);
}

/// The channel's fast sum against its reference series: 48 sources in the height bands
/// [0.1, 0.25], [0.45, 0.55], [0.75, 0.9] times H and 16 targets at heights 0, 0.35, 0.65 and 1
/// times H (at least 0.1 H from every source, where the series converges), H = L_x = L_z = 4.
double channelReferenceError(double tolerance)
{
  using namespace capsula::ewald;
  const double side = 4.0;
  const PeriodicLayer layer{side, side};
  std::mt19937 generator(2024u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> sources, forces, targets;
  for (const auto& [low, high] : {std::pair{0.1, 0.25}, std::pair{0.45, 0.55}, std::pair{0.75, 0.9}}) {
    for (int n = 0; n < 16; ++n) {
      const double p[3] = {side * unit(generator), side * (low + (high - low) * unit(generator)),
                           side * unit(generator)};
      sources.insert(sources.end(), p, p + 3);
      for (int i = 0; i < 3; ++i) {
        forces.push_back(2.0 * unit(generator) - 1.0);
      }
    }
  }
  for (double y : {0.0, 0.35, 0.65, 1.0}) {
    for (int n = 0; n < 4; ++n) {
      const double p[3] = {side * unit(generator), side * y, side * unit(generator)};
      targets.insert(targets.end(), p, p + 3);
    }
  }
  const auto fast = spectralEwaldChannel2P(layer, side, tolerance, sources, forces, targets);
  double error = 0.0, size = 0.0;
  for (std::size_t t = 0; t < targets.size(); t += 3) {
    double u[3] = {0.0, 0.0, 0.0};
    for (std::size_t n = 0; n < sources.size(); n += 3) {
      double G[3][3];
      periodicChannelStokeslet2P(layer, side, &targets[t], &sources[n], G);
      for (int i = 0; i < 3; ++i) {
        u[i] += G[i][0] * forces[n] + G[i][1] * forces[n + 1] + G[i][2] * forces[n + 2];
      }
    }
    error = std::max(error, std::hypot(fast[t] - u[0], fast[t + 1] - u[1], fast[t + 2] - u[2]));
    size = std::max(size, std::hypot(u[0], u[1], u[2]));
  }
  return error / size;
}

} // namespace

int main(int argc, char** argv)
{
  for (int a = 1; a < argc; ++a) {
    if (std::string(argv[a]) == "--help" || std::string(argv[a]) == "-h") {
      printUsage();
      return 0;
    }
  }
  Options options;
  if (!parseOptions(argc, argv, options)) {
    return 2;
  }
  std::printf("spectral Ewald 2P, %s, tolerance %.1e, density %.3g\n",
              options.kernel == "wall"        ? "lower wall's Stokeslet"
              : options.kernel == "channel"   ? "channel's Stokeslet"
              : options.kernel == "stresslet" ? "stresslet"
                                              : "Stokeslet",
              options.tolerance, options.density);
  if (options.kernel == "channel") {
    std::printf("error against the reference series (48 sources, 16 targets, H = L = 4): %.2e of the largest "
                "velocity\n",
                channelReferenceError(options.tolerance));
  }
  std::printf("%8s %10s %10s %10s %7s %18s %12s\n", "N", "total (s)", "local (s)", "smooth (s)", "xi", "grid",
              "us/(N log2N)");
  for (int count : options.sizes) {
    runSize(count, options);
  }
  return 0;
}
