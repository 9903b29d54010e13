// The discrete Helfrich bending energy (HelfrichBending): the energy and load of spheres
// and ellipsoids against their closed forms under refinement, the forces against
// central differences of the energy, the invariances, the stress-free initial shape, the
// stiffness operators and the input checks.
#include "EllipsoidBending.hpp"
#include "MembraneTesting.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/elasticity/HelfrichBending.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/mesh/SurfaceMassMatrix.hpp>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace capsula::elasticity;
using capsula::elasticity::testing::ellipsoidBendingLoad;
using capsula::elasticity::testing::virtualWorkError;
using capsula::mesh::SurfaceMesh;
using capsula::mesh::Vec3;
using capsula::testing::orderOverLevels;

constexpr double bendingPi = 3.14159265358979323846;
constexpr double kb = 0.3;

BendingParameters bending(double c0 = 0.0, BendingReference reference = BendingReference::Flat)
{
  BendingParameters p;
  p.modulus = kb;
  p.spontaneousCurvature = c0;
  p.reference = reference;
  return p;
}

// The load density f with int phi_k f dA = F_k (consistent mass at the current shape, as
// MembraneMechanics's virtual-work path).
std::vector<Vec3> bendingLoad(const SurfaceMesh& mesh, const std::vector<double>& x, const std::vector<Vec3>& F)
{
  capsula::mesh::SurfaceMassMatrix mass(mesh);
  mass.assemble(x.data());
  std::vector<Vec3> f(F.size());
  mass.solve(F.front().data(), f.front().data());
  return f;
}

// Every coordinate moved by a uniform random amount in [-amplitude, amplitude].
std::vector<double> perturbed(const std::vector<double>& x, double amplitude, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  std::vector<double> y = x;
  for (double& v : y) {
    v += u(random);
  }
  return y;
}

double rms(const std::vector<double>& v)
{
  double sum = 0.0;
  for (const double e : v) {
    sum += e * e;
  }
  return std::sqrt(sum / static_cast<double>(v.size()));
}

} // namespace

// A sphere of radius R: E = 8 pi k_b (1 - c0 R / 2)^2 and Delta f . n = -k_b c0 (2 - c0 R) / R^2
// (dE/dR over the area). The nodal load M^-1 F does not converge pointwise (see the
// ellipsoid test); its virtual work on smooth displacements does.
TEST(HelfrichBending, SphereEnergyAndLoad)
{
  const double R = 1.7;
  const Vec3 axes(R, R, R);
  for (const double c0 : {0.0, 0.5}) {
    std::vector<int> levels;
    std::vector<double> energyError, normalError, tangentialError, weakError;
    const double exactEnergy = 8.0 * bendingPi * kb * std::pow(1.0 - 0.5 * c0 * R, 2);
    const double exactLoad = -kb * c0 * (2.0 - c0 * R) / (R * R);
    const double scale = kb / (R * R * R);
    for (int level = 1; level <= 4; ++level) {
      const SurfaceMesh mesh = capsula::mesh::makeSphere(level, R);
      HelfrichBending b(mesh, mesh.positions(), bending(c0));
      b.evaluate(mesh.positionData());
      const std::vector<Vec3> f = bendingLoad(mesh, mesh.positions(), b.nodalForces());
      std::vector<double> dn, dt;
      for (int k = 0; k < mesh.numNodes(); ++k) {
        const Vec3 n = mesh.position(k) / R;
        dn.push_back((f[k].dot(n) - exactLoad) / scale);
        dt.push_back((f[k] - f[k].dot(n) * n).norm() / scale);
      }
      levels.push_back(level);
      energyError.push_back(std::abs(b.energy() / exactEnergy - 1.0));
      normalError.push_back(rms(dn));
      tangentialError.push_back(rms(dt));
      weakError.push_back(virtualWorkError(mesh, b.nodalForces(), kb, axes, c0, scale));
      std::printf("sphere c0 R = %.2f level %d: energy rel err %.2e, nodal load normal rms %.2e, tangential rms %.2e "
                  "(of k_b/R^3), virtual work err %.2e\n",
                  c0 * R, level, energyError.back(), normalError.back(), tangentialError.back(), weakError.back());
    }
    const double energyOrder = orderOverLevels(levels, energyError);
    const double tangentialOrder = orderOverLevels(levels, tangentialError);
    const double weakOrder = orderOverLevels(levels, weakError);
    std::printf("orders: energy %.2f, nodal normal %.2f, nodal tangential %.2f, virtual work %.2f\n", energyOrder,
                orderOverLevels(levels, normalError), tangentialOrder, weakOrder);
    // Observed 3.84 (c0 = 0) and 3.87 (c0 R = 0.85), level-4 errors 7.0e-7 and 2.4e-6: a
    // wrong factor or sign of the c0 term would leave an O(1) error.
    EXPECT_GT(energyOrder, 3.5);
    EXPECT_LT(energyError.back(), 3e-6);
    EXPECT_GT(tangentialOrder, 0.8); // observed 0.91
    // The virtual work sum_k F_k . psi(x_k) of smooth displacements psi: observed orders 3.54
    // and 4.22, level-4 errors 1.1e-8 and 4.9e-8 (of k_b / R^3 times int |psi| dA).
    EXPECT_GT(weakOrder, 3.2);
    EXPECT_LT(weakError.back(), 1e-7);
  }
}

// Ellipsoids: nodal H = Y . n / 2 against the exact H, and the load against the analytic
// bending load, at levels 1-4.
TEST(HelfrichBending, EllipsoidCurvatureAndLoad)
{
  for (const Vec3& axes : {Vec3(1.0, 0.8, 0.6), Vec3(1.0, 0.5, 2.0)}) {
    for (const double c0 : {0.0, 0.7}) {
      std::vector<int> levels;
      std::vector<double> hError, loadError, weakError;
      for (int level = 1; level <= 4; ++level) {
        const SurfaceMesh mesh = capsula::mesh::makeEllipsoid(level, axes);
        HelfrichBending b(mesh, mesh.positions(), bending(c0));
        b.evaluate(mesh.positionData());
        const std::vector<Vec3> f = bendingLoad(mesh, mesh.positions(), b.nodalForces());
        std::vector<double> dh, dl, exactH, exactL;
        for (int k = 0; k < mesh.numNodes(); ++k) {
          const Vec3 x = mesh.position(k);
          const double H = capsula::mesh::ellipsoidCurvature(axes, x).mean;
          const double load = ellipsoidBendingLoad(kb, axes, c0, x);
          dh.push_back(b.meanCurvature()[k] - H);
          exactH.push_back(H);
          dl.push_back(f[k].dot(capsula::mesh::ellipsoidNormal(axes, x)) - load);
          exactL.push_back(load);
        }
        levels.push_back(level);
        hError.push_back(rms(dh) / rms(exactH));
        loadError.push_back(rms(dl) / rms(exactL));
        weakError.push_back(virtualWorkError(mesh, b.nodalForces(), kb, axes, c0, rms(exactL)));
        std::printf("ellipsoid (%.1f %.1f %.1f) c0 %.1f level %d: H rel rms %.2e, nodal load rel rms %.2e, virtual "
                    "work err %.2e\n",
                    axes[0], axes[1], axes[2], c0, level, hError.back(), loadError.back(), weakError.back());
      }
      const double hOrder = orderOverLevels(levels, hError), weakOrder = orderOverLevels(levels, weakError);
      std::printf("orders: H %.2f, nodal load %.2f, virtual work %.2f\n", hOrder, orderOverLevels(levels, loadError),
                  weakOrder);
      // Observed H orders 1.86 and 1.75 (level-4 errors 1.8e-3, 3.8e-3).
      EXPECT_GT(hOrder, 1.6);
      EXPECT_LT(hError.back(), 5e-3);
      // Virtual work of smooth displacements: observed orders 3.38-3.84, level-4 errors
      // 2.4e-7 to 9.5e-7 of the RMS load: the load converges weakly at third order or better.
      EXPECT_GT(weakOrder, 3.0);
      EXPECT_LT(weakError.back(), 2e-6);
      // The nodal load density M^-1 F (the one the membrane passes to the fluid) does not
      // converge pointwise: its error is a grid-scale mode (vertex against midside nodes)
      // of size O(1) relative to the load, the O(h^2) nodal error of Y seen through the two
      // derivatives the load takes of it. The fluid sees it only weakly (the virtual work
      // above), and whole runs converge (docs/membrane-forces.md, "Bending"). Pinned so
      // that a change shows: observed 1.1-11 at level 4.
      EXPECT_LT(loadError.back(), 15.0);
    }
  }
}

// F against central differences of E on a randomly perturbed level-2 ellipsoid (the
// reference perturbed as well): truncation ~h^2 E''' and round-off ~1e-13 E / h
// (the mass solves' tolerance) are both ~1e-8 of max |F|; observed 1.5e-8 to 1.9e-8.
TEST(HelfrichBending, ForcesAreTheEnergyGradient)
{
  const SurfaceMesh mesh = capsula::mesh::makeEllipsoid(2, Vec3(1.0, 0.8, 0.6));
  const std::vector<double> reference = perturbed(mesh.positions(), 0.01, 7);
  const std::vector<double> x = perturbed(mesh.positions(), 0.02, 11);
  for (const auto& p : {bending(0.0), bending(1.3), bending(0.0, BendingReference::InitialShape)}) {
    HelfrichBending b(mesh, reference, p);
    b.evaluate(x.data());
    const std::vector<Vec3> F = b.nodalForces();
    double scale = 0.0;
    for (const Vec3& f : F) {
      scale = std::max(scale, f.norm());
    }
    std::vector<double> y = x;
    const double h = 1e-5;
    double worst = 0.0;
    std::mt19937 random(3);
    for (int trial = 0; trial < 60; ++trial) {
      const std::size_t i = random() % x.size();
      y[i] = x[i] + h;
      b.evaluate(y.data());
      const double plus = b.energy();
      y[i] = x[i] - h;
      b.evaluate(y.data());
      const double minus = b.energy();
      y[i] = x[i];
      worst = std::max(worst, std::abs((plus - minus) / (2.0 * h) - F[i / 3][static_cast<int>(i % 3)]));
    }
    std::printf("gradient check c0 %.1f reference %s: max |dE_fd - F| / max |F| = %.2e\n", p.spontaneousCurvature,
                to_string(p.reference).c_str(), worst / scale);
    EXPECT_LT(worst / scale, 1e-7);
  }
}

// No net force or torque (E is invariant under translations and rotations), E invariant
// under rigid motions, and under scaling when c = 0. All to round-off: the mass solves
// stop at 1e-13 relative, the sums cancel terms of size sum |x_k| |F_k|.
TEST(HelfrichBending, Invariances)
{
  const SurfaceMesh mesh = capsula::mesh::makeEllipsoid(2, Vec3(1.0, 0.5, 2.0));
  const std::vector<double> x = perturbed(mesh.positions(), 0.02, 5);
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  const Vec3 shift(0.3, -1.2, 2.5);
  const std::vector<double> moved =
      capsula::elasticity::testing::mapNodes(x, [&](const Vec3& y) { return Vec3(rotation * y + shift); });
  const std::vector<double> scaled =
      capsula::elasticity::testing::mapNodes(x, [](const Vec3& y) { return Vec3(1.7 * y); });
  for (const auto& p : {bending(0.0), bending(1.3), bending(0.0, BendingReference::InitialShape)}) {
    HelfrichBending b(mesh, mesh.positions(), p);
    b.evaluate(x.data());
    const double energy = b.energy();
    Vec3 net = Vec3::Zero(), torque = Vec3::Zero();
    double size = 0.0, force = 0.0;
    for (int k = 0; k < mesh.numNodes(); ++k) {
      const Vec3& F = b.nodalForces()[k];
      const Vec3 xk = capsula::mesh::nodeAt(x.data(), k);
      net += F;
      torque += xk.cross(F);
      force += F.norm();
      size += xk.norm() * F.norm();
    }
    std::printf("net force %.2e, torque %.2e (relative)\n", net.norm() / force, torque.norm() / size);
    EXPECT_LT(net.norm() / force, 1e-12);
    EXPECT_LT(torque.norm() / size, 1e-12);
    b.evaluate(moved.data());
    EXPECT_NEAR(b.energy(), energy, 1e-11 * energy);
    if (p.spontaneousCurvature == 0.0 && p.reference == BendingReference::Flat) {
      b.evaluate(scaled.data());
      EXPECT_NEAR(b.energy(), energy, 1e-11 * energy);
    }
  }
}

// With the InitialShape reference the moment-free curvature vector is the reference's own
// Y_h at every quadrature point, so the reference is an exact minimum: E = 0 and F = 0 to
// round-off. The round-off is that of the two mass solves (relative residual 1e-13),
// amplified by K ~ h^-2: measured max |F| 2.8e-13, 1.7e-12, 8.6e-12 of the flat reference's
// at levels 1-3, and 7.5e-11 at level 3 after a rigid motion; the bound 1e-9 is far below
// the 1-15% a nodal reference curvature leaves. Rigidly moving the reference keeps F at
// round-off (R turns with the elements: frame indifference), and a perturbation of 1% raises
// E far above its round-off (E/E_flat ~ 1e-25 at rest).
TEST(HelfrichBending, InitialShapeIsStressFree)
{
  const Vec3 axes(1.0, 0.8, 0.6);
  for (int level = 1; level <= 3; ++level) {
    const SurfaceMesh mesh = capsula::mesh::makeEllipsoid(level, axes);
    HelfrichBending flat(mesh, mesh.positions(), bending(0.0));
    flat.evaluate(mesh.positionData());
    HelfrichBending b(mesh, mesh.positions(), bending(0.0, BendingReference::InitialShape));
    double flatF = 0.0;
    for (int k = 0; k < mesh.numNodes(); ++k) {
      flatF = std::max(flatF, flat.nodalForces()[k].norm());
    }
    // The reference, and the reference turned by 50 degrees about (1, 2, 3) and moved.
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.87, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
    std::vector<double> moved(mesh.positions());
    for (std::size_t k = 0; k < moved.size(); k += 3) {
      const Vec3 y = turn * Vec3(moved[k], moved[k + 1], moved[k + 2]) + Vec3(0.3, -1.0, 2.0);
      for (int d = 0; d < 3; ++d) {
        moved[k + static_cast<std::size_t>(d)] = y[d];
      }
    }
    const std::vector<double>* reference = &mesh.positions();
    for (const std::vector<double>* x : {reference, static_cast<const std::vector<double>*>(&moved)}) {
      b.evaluate(x->data());
      double F = 0.0;
      for (int k = 0; k < mesh.numNodes(); ++k) {
        F = std::max(F, b.nodalForces()[k].norm());
      }
      EXPECT_LT(F, 1e-9 * flatF) << "level " << level;
      EXPECT_LT(b.energy(), 1e-20 * flat.energy()) << "level " << level;
    }
    const std::vector<double> y = perturbed(mesh.positions(), 0.01, 9);
    b.evaluate(y.data());
    EXPECT_GT(b.energy(), 1e-8 * flat.energy()) << "level " << level;
  }
}

// The stiffness operators at a perturbed sphere: both symmetric; the sparse one below the
// matrix-free one (D >= M); and on grid-scale normal modes psi n the matrix-free one close
// to the change of F (the exact Hessian's action), by central differences.
TEST(HelfrichBending, StiffnessOperators)
{
  const SurfaceMesh mesh = capsula::mesh::makeSphere(2, 1.0);
  const std::vector<double> x = perturbed(mesh.positions(), 0.01, 13);
  HelfrichBending b(mesh, mesh.positions(), bending(0.0));
  b.evaluate(x.data());
  const std::size_t n = x.size();
  const std::vector<double> u = perturbed(std::vector<double>(n, 0.0), 1.0, 21);
  const std::vector<double> v = perturbed(std::vector<double>(n, 0.0), 1.0, 22);
  std::vector<double> Au(n), Av(n);
  b.applyStiffness(u.data(), Au.data());
  b.applyStiffness(v.data(), Av.data());
  const auto dot = [](const std::vector<double>& a, const std::vector<double>& c) {
    double s = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      s += a[i] * c[i];
    }
    return s;
  };
  // Symmetric to the mass solve's tolerance (1e-13).
  EXPECT_NEAR(dot(u, Av), dot(v, Au), 1e-10 * std::abs(dot(u, Au)));
  std::map<std::pair<int, int>, double> sparse;
  b.forEachEntry([&](int row, int column, double value) { sparse[{row, column}] += value; });
  double asymmetry = 0.0, largest = 0.0;
  std::vector<double> Su(n, 0.0);
  for (const auto& [at, value] : sparse) {
    asymmetry = std::max(asymmetry, std::abs(value - sparse[{at.second, at.first}]));
    largest = std::max(largest, std::abs(value));
    Su[static_cast<std::size_t>(at.first)] += value * u[static_cast<std::size_t>(at.second)];
  }
  EXPECT_LT(asymmetry, 1e-13 * largest); // the same products summed in another order
  // u^T K D^-1 K u <= u^T K M^-1 K u (D - M is diagonally dominant).
  std::printf("sparse / matrix-free on a random vector: %.3f\n", dot(u, Su) / dot(u, Au));
  EXPECT_LE(dot(u, Su), dot(u, Au));
  EXPECT_GT(dot(u, Su), 0.1 * dot(u, Au)); // observed 0.31

  // Grid-scale normal modes: +1 at the vertices and -1 at the midside nodes, and random
  // signs, times n_k, amplitude 1e-5 (the first-order change of F by central differences).
  for (const bool checkerboard : {true, false}) {
    std::mt19937 random(5);
    std::vector<double> w(n), plus = x, minus = x;
    for (int k = 0; k < mesh.numNodes(); ++k) {
      const double sign = checkerboard ? (mesh.isVertex(k) ? 1.0 : -1.0) : (random() % 2 ? 1.0 : -1.0);
      for (int d = 0; d < 3; ++d) {
        w[3 * k + d] = sign * b.nodeNormals()[k][d];
      }
    }
    const double eps = 1e-5;
    for (std::size_t i = 0; i < n; ++i) {
      plus[i] += eps * w[i];
      minus[i] -= eps * w[i];
    }
    HelfrichBending c(mesh, mesh.positions(), bending(0.0));
    c.evaluate(plus.data());
    const std::vector<Vec3> Fp = c.nodalForces();
    c.evaluate(minus.data());
    std::vector<double> dF(n), Aw(n);
    for (std::size_t i = 0; i < n; ++i) {
      dF[i] = (Fp[i / 3][static_cast<int>(i % 3)] - c.nodalForces()[i / 3][static_cast<int>(i % 3)]) / (2.0 * eps);
    }
    b.applyStiffness(w.data(), Aw.data());
    std::vector<double> diff(n);
    for (std::size_t i = 0; i < n; ++i) {
      diff[i] = Aw[i] - dF[i];
    }
    const double rayleigh = dot(w, Aw) / dot(w, dF);
    const double relative = std::sqrt(dot(diff, diff) / dot(dF, dF));
    std::printf("%s normal mode: w.Aw / w.dF = %.3f, |Aw - dF| / |dF| = %.3f\n",
                checkerboard ? "checkerboard" : "random", rayleigh, relative);
    // Observed 1.067 and 1.074 (Rayleigh quotients) and 0.114, 0.117 (relative
    // differences): the approximation leaves out the lower-order curvature terms of the
    // second variation (k_b (4H^2 - 2K) and the like), a ~10% correction at level 2.
    EXPECT_GT(rayleigh, 0.9);
    EXPECT_LT(rayleigh, 1.25);
    EXPECT_LT(relative, 0.2);
  }
}

// Each bad input is an InputError naming its deck key.
TEST(HelfrichBending, RejectsBadInput)
{
  const SurfaceMesh mesh = capsula::mesh::makeSphere(1, 1.0);
  const auto message = [&](std::vector<double> reference, const BendingParameters& p) -> std::string {
    try {
      HelfrichBending b(mesh, std::move(reference), p);
    } catch (const capsula::core::InputError& error) {
      return error.what();
    }
    return "";
  };
  BendingParameters negative = bending();
  negative.modulus = -1.0;
  EXPECT_NE(message(mesh.positions(), negative).find("'Bending modulus'"), std::string::npos);
  BendingParameters noModulus = bending(0.5);
  noModulus.modulus = 0.0;
  EXPECT_NE(message(mesh.positions(), noModulus).find("'Spontaneous curvature'"), std::string::npos);
  EXPECT_NE(message(mesh.positions(), bending(0.5, BendingReference::InitialShape)).find("'Spontaneous curvature'"),
            std::string::npos);
  std::vector<double> shortReference = mesh.positions();
  shortReference.pop_back();
  EXPECT_NE(message(shortReference, bending()).find("'Bending reference'"), std::string::npos);
  // A collapsed element: its six nodes at one point.
  std::vector<double> collapsed = mesh.positions();
  for (const int node : mesh.element(0)) {
    for (int d = 0; d < 3; ++d) {
      collapsed[3 * node + d] = collapsed[3 * mesh.element(0)[0] + d];
    }
  }
  EXPECT_NE(message(collapsed, bending(0.0, BendingReference::InitialShape)).find("'Bending reference'"),
            std::string::npos);
  EXPECT_EQ(message(mesh.positions(), bending(0.0, BendingReference::InitialShape)), "");
  EXPECT_THROW(bendingReference("Curved"), capsula::core::InputError);
}
