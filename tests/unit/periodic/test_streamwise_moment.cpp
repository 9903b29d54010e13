// The mean flow of the cells in the periodic channel as moments of the load and of the
// double-layer density (operators/StreamwiseMoment.hpp) against the flow itself: the flux
// through a cross-section, integrated from flowVelocity over the plane x = const, and the
// mean of du/dy on the two walls, from the x-z averages of flowVelocity near each wall.
// Two cells, one at viscosity ratio 5 with an arbitrary double-layer density, so that both
// terms of the moment are weighed.
#include "PeriodicTesting.hpp"

#include <capsula/operators/StreamwiseMoment.hpp>
#include <capsula/quadrature/GaussLegendre.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

// A namespace of its own: the unity build compiles the files of this executable together.
namespace streamwise_moment_tests {

using namespace capsula;
namespace pt = capsula::periodic::testing;
namespace ot = capsula::operators::testing;

const double lx = 3.0, lz = 2.5, height = 4.0, capillaryNumber = 0.7;

// A load with a net force, a torque and a stresslet.
mesh::Vec3 load(const mesh::Vec3& x, const mesh::Vec3& n)
{
  return mesh::Vec3(0.4 + 0.5 * x[1] + n[0] - 0.8 * n[1], 0.3 * x[2] - n[1], 0.2 + 0.4 * x[0] * n[2]);
}

// A smooth double-layer density, not a solved velocity (the moment is linear in any density),
// but divergence-free as a cell's velocity is: the flux through the cell surfaces, and with it
// the difference between cross-sections, vanishes (a density with a source would change the
// flux from one cross-section to the next; the moment is their mean over x).
mesh::Vec3 density(const mesh::Vec3& x)
{
  return mesh::Vec3(0.3 + 0.9 * x[1] + 0.1 * x[2] * x[2], -0.4 * x[0] + 0.6 * x[2], 0.5 - 0.2 * x[1]);
}

struct TwoCells {
  std::unique_ptr<operators::BoundaryIntegralSolver> solver;
  std::vector<double> loads;      // 3 per element
  std::vector<double> velocities; // 3 per node
  operators::FlowConditions flow;
};

// A level-2 sphere at viscosity ratio 5 in the lower half and an ellipsoid at 1 in the upper
// half, both at least 1 from the plane x = 2 and 0.5 from the walls.
TwoCells twoCells()
{
  std::vector<mesh::SurfaceMesh> cells;
  cells.push_back(mesh::makeSphere(2, 0.5, {mesh::Vec3(0.4, 1.2, 0.4)}));
  cells.push_back(mesh::makeEllipsoid(2, mesh::Vec3(0.5, 0.3, 0.4), {mesh::Vec3(0.3, 2.9, 1.7)}));
  TwoCells s;
  s.solver = pt::makeSolver("PeriodicChannel", std::move(cells), {5.0, 1.0}, pt::channel(lx, lz, height), 1e-10);
  s.loads = ot::elementAverages(s.solver->surfaces(), load);
  const std::vector<double> positions = s.solver->surfaces().positions();
  for (std::size_t k = 0; k < positions.size() / 3; ++k) {
    const mesh::Vec3 u = density(mesh::Vec3(positions[3 * k], positions[3 * k + 1], positions[3 * k + 2]));
    s.velocities.insert(s.velocities.end(), {u[0], u[1], u[2]});
  }
  s.flow.capillaryNumber = capillaryNumber;
  s.flow.background = operators::LinearFlow::quiescent();
  return s;
}

TEST(StreamwiseMoment, IsTheFluxThroughACrossSection)
{
  TwoCells s = twoCells();
  const operators::LoadDensity loadDensity = operators::LoadDensity::constantOverElements(s.loads);
  // Gauss-Legendre across y (the flow on the plane is smooth, the cells 1 away) and the
  // periodic trapezoidal rule along z.
  const int ny = 40, nz = 40;
  const quadrature::Rule1D across = quadrature::gaussLegendre(ny, 0.0, height);
  std::vector<double> points, weights;
  for (int i = 0; i < ny; ++i) {
    for (int j = 0; j < nz; ++j) {
      points.insert(points.end(), {2.0, across.points[i], lz * j / nz});
      weights.push_back(across.weights[i] * lz / nz);
    }
  }
  const std::vector<double> u = s.solver->flowVelocity(points, loadDensity, s.velocities.data(), s.flow);
  double flux = 0.0;
  for (std::size_t p = 0; p < weights.size(); ++p) {
    flux += weights[p] * u[3 * p];
  }
  const operators::WallNormalWeight weight = operators::crossSectionFluxWeight(0.0, height);
  const double moment =
      operators::streamwiseMoment(s.solver->surfaces(), loadDensity, s.velocities.data(), capillaryNumber, weight) / lx;
  // The same without the double layer, and without the cells' interior term.
  const double loadOnly = operators::streamwiseMoment(s.solver->surfaces(), loadDensity, s.velocities.data(),
                                                      capillaryNumber, {weight.value, [](double) { return 0.0; }}) /
                          lx;
  const double noInterior = operators::streamwiseMoment(s.solver->surfaces(), loadDensity, s.velocities.data(),
                                                        capillaryNumber, {weight.value, weight.slope}) /
                            lx;
  std::printf("StreamwiseMoment: flux through x = 2: %.10f, moment %.10f (load alone %.6f, without the interior "
              "term %.6f)\n",
              flux, moment, loadOnly, noInterior);
  // The quadratures of the plane converge spectrally and the fast sums run at 1e-10 of the
  // largest velocity: 1e-8 of the flux bounds both (measured 2e-11). The double layer moves
  // the flux by 5% and the interior term by 18%: dropping either, or a wrong sign or factor of
  // any term, fails by far.
  EXPECT_GT(std::abs(moment - loadOnly), 0.02 * std::abs(moment));
  EXPECT_GT(std::abs(moment - noInterior), 0.1 * std::abs(moment));
  EXPECT_NEAR(flux, moment, 1e-8 * std::abs(moment));
}

TEST(StreamwiseMoment, IsTheMeanShearRateOnTheWalls)
{
  TwoCells s = twoCells();
  const operators::LoadDensity loadDensity = operators::LoadDensity::constantOverElements(s.loads);
  // Below the lowest and above the highest surface point the x-z mean of the cells' flow is
  // linear in y (a sheet's zero mode, docs/domains.md): its slope is the mean at y = d (or H -
  // d) over d. The plane's other modes cancel under the periodic trapezoidal rule.
  const double d = 0.2;
  const int nx = 48, nz = 40;
  std::vector<double> points;
  for (const double y : {d, height - d}) {
    for (int i = 0; i < nx; ++i) {
      for (int j = 0; j < nz; ++j) {
        points.insert(points.end(), {lx * i / nx, y, lz * j / nz});
      }
    }
  }
  const std::vector<double> u = s.solver->flowVelocity(points, loadDensity, s.velocities.data(), s.flow);
  double lowerMean = 0.0, upperMean = 0.0;
  const std::size_t perPlane = static_cast<std::size_t>(nx) * nz;
  for (std::size_t p = 0; p < perPlane; ++p) {
    lowerMean += u[3 * p] / perPlane;
    upperMean += u[3 * (perPlane + p)] / perPlane;
  }
  const double meanShearRate = 0.5 * (lowerMean / d + (-upperMean) / d);
  const double moment = operators::streamwiseMoment(s.solver->surfaces(), loadDensity, s.velocities.data(),
                                                    capillaryNumber, operators::meanWallShearRateWeight(0.0, height)) /
                        (lx * lz);
  const operators::WallNormalWeight weight = operators::meanWallShearRateWeight(0.0, height);
  const double loadOnly = operators::streamwiseMoment(s.solver->surfaces(), loadDensity, s.velocities.data(),
                                                      capillaryNumber, {weight.value, [](double) { return 0.0; }}) /
                          (lx * lz);
  std::printf("StreamwiseMoment: mean du/dy on the walls %.10f, moment %.10f (load alone %.6f)\n", meanShearRate,
              moment, loadOnly);
  // The trapezoidal rule's aliasing falls like e^{-2 pi 48 D / 3}, D >= 0.5 the planes' distance
  // from the cells, and the fast sums run at 1e-10: 1e-8 of the value bounds both (measured
  // 1e-11). The double layer is two thirds of the value.
  EXPECT_GT(std::abs(moment - loadOnly), 0.1 * std::abs(moment));
  EXPECT_NEAR(meanShearRate, moment, 1e-8 * std::abs(moment));
}

} // namespace streamwise_moment_tests
