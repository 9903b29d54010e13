#pragma once
// The Helfrich bending energy of a membrane of 6-node quadratic triangles,
//   E = (k_b / 2) int_S (2H - c)^2 dA,
// H the mean curvature (outward n, H = 1/R on a sphere), c the spontaneous curvature
// (BendingParameters.hpp), discretised by Dziuk's mixed formulation (Numer. Math. 111,
// 2008): the mean-curvature vector Y = -Lap_s x = 2 H n is a quadratic nodal field
// solving the weak form
//   M(x) Y = K(x) x   (each coordinate),  M_kl = int phi_k phi_l dA,
//                                         K_kl = int grad_s phi_k . grad_s phi_l dA,
// with the consistent mass M (a lumped quadratic mass is singular), and
//   E(x) = (k_b / 2) int_S |Y_h - R|^2 dA,   R = c n_e + beta^i a_i,
// n_e the element's own unit normal and a_i its tangents at each point of the 7-point
// rule. R is the curvature vector the membrane carries no moment at, held per quadrature
// point as components in the element's own frame, so it turns with the element:
//   Flat:          c = c0, beta = 0 (|Y - c0 n|^2 = (2H - c0)^2 where Y = 2 H n);
//   InitialShape:  R = Y_h of the reference shape at that point (c its normal part,
//                  beta^i = Y_h . a^i its tangential part), so that the reference is an
//                  exact minimum, E = 0, and carries no bending force to round-off. A
//                  nodal c_k = 2 H_k interpolated instead would leave the discretisation
//                  error of Y_h as a force at rest (measured: 4-15% of a flat reference's).
//
// The element maps use the REFERENCE shape parameters (eq 3.17), fixed for the
// object's life as in MembraneMechanics, so they are linear in the nodal positions.
// The nodal forces F_k = dE/dx_k are exact without forming M^-1: with the Lagrangian
//   L(x, Y, Lambda) = E(x, Y) + Lambda^T (M(x) Y - K(x) x),
// stationarity in Y gives M Lambda = -k_b (M Y - N), N_k = int phi_k R dA, i.e.
// Lambda = -k_b (Y - M^-1 N), and then dE/dx_k = dL/dx_k at fixed Y and Lambda, a sum of
// element integrals (BendingIntegrand.hpp). One mass solve for Y, and one more for
// M^-1 N where c is nonzero somewhere.
//
// F_k is a virtual-work nodal force, the same kind as MembraneMechanics::nodalForces():
// int phi_k Delta f dA = F_k gives the load density, with Delta f = (sigma_ext -
// sigma_int) . n; a sphere with c = c0 carries Delta f . n = -k_b c0 (2 - c0 R) / R^2.
//
// For stiff time integrators, the bending stiffness on the grid-scale normal modes is
// approximated by k_b P K M^-1 K P, P = n n^T at the nodes (the second variation
// k_b int (Lap_s psi)^2 dA of a normal displacement psi n, discretised):
// applyStiffness() applies it; forEachEntry() hands over a sparse version with M replaced
// by the diagonal D_k = sum_l |M_kl| (see there).
#include "capsula/elasticity/BendingParameters.hpp"

#include <capsula/mesh/SurfaceMassMatrix.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace capsula::elasticity {

using mesh::Vec3;

class HelfrichBending {
public:
  /// `mesh` gives the topology (it must outlive this object; its positions are not
  /// used); `referencePositions` (3 per node) fix the shape parameters and, with
  /// BendingReference::InitialShape, the spontaneous curvature c_k = 2 H_k. Throws
  /// core::InputError for a negative modulus, a nonzero c0 with zero modulus or with
  /// InitialShape, a wrong array size, or a reference whose curvature cannot be computed.
  HelfrichBending(const mesh::SurfaceMesh& mesh, std::vector<double> referencePositions,
                  const BendingParameters& parameters);

  /// Computes Y, the energy and the nodal forces at `positions` (3 * numNodes doubles),
  /// which also become the linearisation point of the stiffness operators. No allocation.
  /// Throws core::NumericalError for a degenerate element or a failed mass solve.
  void evaluate(const double* positions);

  // --- after evaluate ----------------------------------------------------------
  double energy() const { return energy_; }
  /// F_k = dE/dx_k; sum_k F_k = 0 and sum_k x_k x F_k = 0 to round-off.
  const std::vector<Vec3>& nodalForces() const { return force_; }
  /// Y_k, the nodal mean-curvature vectors (2 H n, up to the discretisation error).
  const std::vector<Vec3>& curvatureVectors() const { return curvature_; }
  /// H_k = Y_k . n_k / 2.
  const std::vector<double>& meanCurvature() const { return meanCurvature_; }
  /// n_k: the element normals at the node averaged with the element areas as weights.
  const std::vector<Vec3>& nodeNormals() const { return normal_; }

  /// y = k_b P K M^-1 K P v at the last evaluate()'s positions (3 entries per node; the
  /// mass solve by conjugate gradients). Symmetric positive semi-definite.
  void applyStiffness(const double* v, double* y);

  /// The sparse approximation k_b P K D^-1 K P, D_k = sum_l |M_kl|: calls
  /// add(row, column, value), rows and columns numbered 3 node + coordinate, with
  /// entries to be summed (a pair of nodes comes once per node they both couple to).
  /// D is the Gershgorin bound of M: D - M is diagonally dominant, so D >= M and the
  /// sparse operator never exceeds applyStiffness() (x^T K D^-1 K x <= x^T K M^-1 K x),
  /// while D and M are spectrally equivalent uniformly in the mesh size (both scale
  /// with the element areas), so it keeps the h^-4 scaling of the stiff modes. A
  /// lumped mass (row sums of M) would not do: it vanishes at the vertices of flat
  /// quadratic elements.
  template <class Add>
  void forEachEntry(Add&& add) const
  {
    const double kb = parameters_.modulus;
    for (std::size_t j = 0; j + 1 < rowStart_.size(); ++j) {
      for (int p = rowStart_[j]; p < rowStart_[j + 1]; ++p) {
        const int i = column_[static_cast<std::size_t>(p)];
        const Vec3& ni = normal_[static_cast<std::size_t>(i)];
        const double kji = kb * stiffness_[static_cast<std::size_t>(p)] / massBound_[j];
        for (int q = rowStart_[j]; q < rowStart_[j + 1]; ++q) {
          const int l = column_[static_cast<std::size_t>(q)];
          const Vec3& nl = normal_[static_cast<std::size_t>(l)];
          const double s = kji * stiffness_[static_cast<std::size_t>(q)] * ni.dot(nl);
          for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) {
              add(3 * i + a, 3 * l + b, s * ni[a] * nl[b]);
            }
          }
        }
      }
    }
  }

  const BendingParameters& parameters() const { return parameters_; }
  /// c_k per node: c0, or 2 H_k of the reference shape.
  const std::vector<double>& spontaneousCurvature() const { return spontaneous_; }
  const std::vector<double>& referencePositions() const { return reference_; }

private:
  /// Shape-function values and derivatives at one quadrature point of one element (the
  /// reference shape parameters), with the rule's weight, and the components of the
  /// moment-free curvature vector R = c n_e + beta^i a_i there.
  struct QuadraturePoint {
    double weight;
    double phi[6], dXi[6], dEta[6];
    double c = 0.0;
    double beta[2] = {0.0, 0.0};
  };
  void setReferenceCurvature();

  void buildPattern();
  void assembleOperators(const double* positions);
  void solveCurvature(const double* positions);
  void energyAndSpontaneousTerm(const double* positions);
  void addForces(const double* positions);
  void applyLaplacian(const double* v, double* y) const; // y = K v, 3 entries per node

  const mesh::SurfaceMesh* mesh_;
  std::vector<double> reference_;
  BendingParameters parameters_;
  std::vector<mesh::ShapeParameters> referenceParameters_;
  std::vector<QuadraturePoint> points_;                // 7 per element
  std::vector<std::array<double, 12>> nodeDerivative_; // per element node: dXi[6], dEta[6]
  std::vector<double> spontaneous_;
  bool hasSpontaneous_ = false;

  // Nodal coupling pattern (CSR over nodes) and each element entry's place in it.
  std::vector<int> rowStart_, column_;
  std::vector<std::array<int, 36>> entry_;

  // Work arrays, sized once.
  mesh::SurfaceMassMatrix mass_;
  std::vector<double> stiffness_;  // K, CSR values
  std::vector<double> massValues_; // M, CSR values (for D only; the solves use mass_)
  std::vector<double> massBound_;  // D_k = sum_l |M_kl|
  std::vector<double> elementArea_;
  std::vector<double> rhs_, spontaneousForce_, work_, solution_;
  std::vector<Vec3> multiplier_, spontaneousSolution_;

  // Results.
  bool evaluated_ = false;
  double energy_ = 0.0;
  std::vector<Vec3> curvature_;
  std::vector<double> meanCurvature_;
  std::vector<Vec3> normal_;
  std::vector<Vec3> force_;
};

} // namespace capsula::elasticity
