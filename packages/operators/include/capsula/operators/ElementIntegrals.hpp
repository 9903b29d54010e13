#pragma once
// Integrals over ONE element with an arbitrary parametric rule: the special quadratures
// (polar rules on the elements that hold the target, adaptive subdivision near it).
//
// An ElementMap samples the element (eqs 3.19-3.24) at a parametric point; an integrand
// turns a sample into the weighted kernel values it integrates. The integrands hold
// their result in a fixed-size array split into groups (the single-layer matrix, the
// double-layer matrices) that the adaptive quadrature judges separately.
#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/operators/KernelTraits.hpp>
#include <capsula/operators/PolarRules.hpp>

#include <array>
#include <cmath>

namespace capsula::operators {

/// The element geometry at one quadrature point, with the rule weight folded in.
struct ElementSample {
  double x[3];              ///< position
  double weight;            ///< w h_s
  double weightedNormal[3]; ///< n w h_s = w (x_xi cross x_eta)
  double phi[6];            ///< shape functions, to interpolate nodal densities
};

/// The map (xi, eta) -> x of one element in its current configuration (eqs 3.17-3.24).
///
/// Whatever alpha, beta and gamma are, the map and the shape functions of eq 3.19 are
/// quadratic in (xi, eta), so each equals the standard quadratic interpolant of its own
/// values at the six points (0,0), (1,0), (0,1), (1/2,0), (1/2,1/2), (0,1/2). Those values
/// are taken once from mesh::shapeFunctions; a sample then costs a few multiplications
/// and no division (the special quadratures take hundreds of samples per element).
class ElementMap {
public:
  ElementMap(const mesh::ElementNodes& nodes, const mesh::ShapeParameters& shape) : shape_(shape)
  {
    constexpr double lagrangePoints[6][2] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.5, 0.0}, {0.5, 0.5}, {0.0, 0.5}};
    for (int k = 0; k < 6; ++k) {
      double phi[6];
      mesh::shapeFunctions(shape, lagrangePoints[k][0], lagrangePoints[k][1], phi);
      for (int i = 0; i < 3; ++i) {
        position_[k][i] = 0.0;
      }
      for (int a = 0; a < 6; ++a) {
        phi_[a][k] = phi[a];
        for (int i = 0; i < 3; ++i) {
          position_[k][i] += phi[a] * nodes[a][i];
        }
      }
    }
  }

  const mesh::ShapeParameters& shape() const { return shape_; }

  /// x(xi, eta) only.
  void position(double xi, double eta, double x[3]) const
  {
    const double zeta = 1.0 - xi - eta;
    const double L[6] = {zeta * (2.0 * zeta - 1.0), xi * (2.0 * xi - 1.0), eta * (2.0 * eta - 1.0),
                         4.0 * xi * zeta,           4.0 * xi * eta,        4.0 * eta * zeta};
    for (int i = 0; i < 3; ++i) {
      x[i] = L[0] * position_[0][i] + L[1] * position_[1][i] + L[2] * position_[2][i] + L[3] * position_[3][i] +
             L[4] * position_[4][i] + L[5] * position_[5][i];
    }
  }

  /// Geometry at (xi, eta) for a rule weight w (relative to dxi deta).
  ElementSample sample(double xi, double eta, double w) const
  {
    // Standard quadratic Lagrange basis on the six points and its derivatives.
    const double zeta = 1.0 - xi - eta;
    const double L[6] = {zeta * (2.0 * zeta - 1.0), xi * (2.0 * xi - 1.0), eta * (2.0 * eta - 1.0),
                         4.0 * xi * zeta,           4.0 * xi * eta,        4.0 * eta * zeta};
    const double dXi[6] = {1.0 - 4.0 * zeta, 4.0 * xi - 1.0, 0.0, 4.0 * (zeta - xi), 4.0 * eta, -4.0 * eta};
    const double dEta[6] = {1.0 - 4.0 * zeta, 0.0, 4.0 * eta - 1.0, -4.0 * xi, 4.0 * xi, 4.0 * (zeta - eta)};
    ElementSample s;
    double tXi[3] = {0.0, 0.0, 0.0}, tEta[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i < 3; ++i) {
      s.x[i] = 0.0;
    }
    for (int k = 0; k < 6; ++k) {
      for (int i = 0; i < 3; ++i) {
        s.x[i] += L[k] * position_[k][i];
        tXi[i] += dXi[k] * position_[k][i];
        tEta[i] += dEta[k] * position_[k][i];
      }
    }
    for (int a = 0; a < 6; ++a) {
      s.phi[a] = phi_[a][0] * L[0] + phi_[a][1] * L[1] + phi_[a][2] * L[2] + phi_[a][3] * L[3] + phi_[a][4] * L[4] +
                 phi_[a][5] * L[5];
    }
    const double area[3] = {tXi[1] * tEta[2] - tXi[2] * tEta[1], tXi[2] * tEta[0] - tXi[0] * tEta[2],
                            tXi[0] * tEta[1] - tXi[1] * tEta[0]};
    for (int i = 0; i < 3; ++i) {
      s.weightedNormal[i] = w * area[i];
    }
    s.weight = w * std::sqrt(area[0] * area[0] + area[1] * area[1] + area[2] * area[2]);
    return s;
  }

private:
  mesh::ShapeParameters shape_;
  double position_[6][3]; // x at the six Lagrange points
  double phi_[6][6];      // phi_a at the six Lagrange points, [a][k]
};

/// int_E G_ij(x, x0) dS as value[3 i + j] (one group): the single layer of eq 3.36.
template <class Kernel>
struct SingleLayerIntegrand {
  static constexpr int size = 9;
  static constexpr std::array<int, 2> groups = {0, 9};
  using Value = std::array<double, size>;

  const Kernel* kernel;
  const double* x0;

  void evaluate(const ElementSample& s, Value& value) const
  {
    double G[3][3];
    kernel->stokeslet(s.x, x0, G);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        value[3 * i + j] = s.weight * G[i][j];
      }
    }
  }
};

/// int_E phi_a G_ij(x, x0) dS as value[9 a + 3 i + j] (one group): the single layer of a
/// load interpolated from the element's six nodes, f = sum_a phi_a f_a, as node blocks
/// (the corrections a repeated single layer at one geometry keeps).
template <class Kernel>
struct NodalSingleLayerIntegrand {
  static constexpr int size = 54;
  static constexpr std::array<int, 2> groups = {0, 54};
  using Value = std::array<double, size>;

  const Kernel* kernel;
  const double* x0;

  void evaluate(const ElementSample& s, Value& value) const
  {
    double G[3][3];
    kernel->stokeslet(s.x, x0, G);
    for (int a = 0; a < 6; ++a) {
      const double w = s.weight * s.phi[a];
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          value[9 * a + 3 * i + j] = w * G[i][j];
        }
      }
    }
  }
};

/// int_E f_i G_ij(x, x0) dS for the load f = sum_a phi_a f_a interpolated from the
/// element's nodes, as value[j] (one group): the element's term of the single layer
/// (eq 3.36) when the load is known.
template <class Kernel>
struct LoadedSingleLayerIntegrand {
  static constexpr int size = 3;
  static constexpr std::array<int, 2> groups = {0, 3};
  using Value = std::array<double, size>;

  const Kernel* kernel;
  const double* x0;
  const double* load; ///< Delta f at the element's six nodes, [3 a + i] (LoadDensity.hpp)

  void evaluate(const ElementSample& s, Value& value) const
  {
    double f[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < 6; ++a) {
      for (int i = 0; i < 3; ++i) {
        f[i] += s.phi[a] * load[3 * a + i];
      }
    }
    for (double& fi : f) {
      fi *= s.weight;
    }
    value = {0.0, 0.0, 0.0};
    addSingleLayerTerm(*kernel, s.x, x0, f, value.data());
  }
};

/// int_E phi_a T_ijk(x, x0) n_k dS as value[9 a + 3 i + j] (one group): the double layer
/// of a density interpolated from the element's six nodes, u = sum_a phi_a u_a.
template <class Kernel>
struct DoubleLayerIntegrand {
  static constexpr int size = 54;
  static constexpr std::array<int, 2> groups = {0, 54};
  using Value = std::array<double, size>;

  const Kernel* kernel;
  const double* x0;

  void evaluate(const ElementSample& s, Value& value) const
  {
    double Tn[9] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    addDoubleLayerMatrix(*kernel, s.x, x0, s.weightedNormal, Tn);
    for (int a = 0; a < 6; ++a) {
      for (int k = 0; k < 9; ++k) {
        value[9 * a + k] = s.phi[a] * Tn[k];
      }
    }
  }
};

/// The solid angle int_E (x - x0) . n / r^3 dS under which the element is seen from x0:
/// summed over a closed outward surface, 4 pi inside and 0 outside.
struct SolidAngleIntegrand {
  static constexpr int size = 1;
  static constexpr std::array<int, 2> groups = {0, 1};
  using Value = std::array<double, size>;

  const double* x0;

  void evaluate(const ElementSample& s, Value& value) const
  {
    const double d[3] = {s.x[0] - x0[0], s.x[1] - x0[1], s.x[2] - x0[2]};
    const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    value[0] =
        (d[0] * s.weightedNormal[0] + d[1] * s.weightedNormal[1] + d[2] * s.weightedNormal[2]) / (r2 * std::sqrt(r2));
  }
};

/// sum_k of the integrand over a parametric rule on the element.
template <class Integrand>
typename Integrand::Value integrateWithRule(const ElementMap& element, const Integrand& integrand,
                                            const ParametricRule& rule)
{
  typename Integrand::Value sum{}, term;
  for (int k = 0; k < rule.size(); ++k) {
    integrand.evaluate(element.sample(rule.xi[k], rule.eta[k], rule.weight[k]), term);
    for (int c = 0; c < Integrand::size; ++c) {
      sum[c] += term[c];
    }
  }
  return sum;
}

} // namespace capsula::operators
