#pragma once
// Elastic tensions and the load on the fluids of a 3D capsule membrane (thesis
// Section 3.5.2): one object per cell, built once, evaluated every right-hand side.
//
// evaluate(x) computes, without allocating:
//  1. per element: current area A_m and centroid (N_Q-point rule, current-node shape
//     parameters, as mesh::elementAreas), and at each of its six nodes the surface
//     deformation gradient A_e (eqs 3.33-3.35). A_e uses the REFERENCE shape
//     parameters for both configurations, so (xi, eta) are material coordinates;
//  2. per node: the area-weighted average normal n (as mesh::nodeNormals) and the
//     area-weighted average of A_e (Section 3.5.2: A is multi-valued at the nodes of a
//     C0 mesh). Each A_e maps the element's own tangent planes, which are tilted from
//     the nodal ones by the C0 kinks, so before averaging it is carried into the nodal
//     planes by the smallest rotations taking the element normals onto the nodal
//     normals (reference side: N_e -> N, current side: n_e -> n). A plain average of
//     A_e would see strain in the reference state itself (O(kink^2): max |lambda - 1| =
//     3.9e-4, 9.1e-6, 1.6e-7 on icosphere levels 1-3); the carried average is exact at
//     rest and under uniform dilation, and frame indifferent. Then A <- (I - nn) A (I - NN)
//     (eq 3.26), B = A A^T, principal stretches, invariants, the law's dw/dI and the
//     tension T (eq 3.30) with its principal values;
//  3. the load, by one of two methods (MembraneForceMethod):
//     - ContourIntegral, the thesis's: per edge the force int T . b dl across it
//       (EdgeTensionForce.hpp), added to the two elements with opposite signs, so that
//       A_m <Delta f>_m = -oint_{C_m} T . b dl (eq 3.37, ERRATA) and sum_m A_m <Delta f>_m
//       = 0 exactly on a closed membrane. The load is constant per element.
//     - VirtualWork: nodal forces F_k = dE/dx_k of the strain energy (element-wise exact
//       deformation at the N_Q points, MembraneEnergyGradient.hpp), and the continuous
//       load Delta f = sum_k phi_k f_k with M f = F (M the consistent mass matrix,
//       mesh::SurfaceMassMatrix): int phi_k Delta f dS = dE/dx_k, the weak form of
//       Delta f = -div_s T. Unlike the contour integral, which sees the kinks of a C0
//       mesh only through averaged nodal normals, it has no zero-energy modes: the
//       element-averaged load lets a prestressed or stiff-dilation membrane fold within
//       a few shear times (docs/validation-cell3d.md), the virtual-work load does not.
//     Both give elementLoads() (the average over each element); VirtualWork also gives
//     nodalLoads() for the single layer to interpolate.
//  4. with a bending modulus (VirtualWork only): the nodal forces of the Helfrich energy
//     (HelfrichBending.hpp) are added to the strain energy's before the density M^-1 F
//     is formed; nodalForces() holds both. The bending term is built with the membrane and uses its reference
//     shape (material coordinates, and the curvature of a BendingReference::InitialShape).
// Sign (ERRATA): Delta f = (sigma_ext - sigma_int) . n = -div_s T, n outward; a sphere
// of radius r under isotropic tension T carries Delta f = (2 T / r) n.
#include "capsula/elasticity/BendingParameters.hpp"
#include "capsula/elasticity/HelfrichBending.hpp"
#include "capsula/elasticity/MembraneEnergyGradient.hpp"
#include "capsula/elasticity/MembraneLaw.hpp"
#include "capsula/elasticity/MembraneTension.hpp"
#include "capsula/elasticity/SurfaceKinematics.hpp"
#include "capsula/elasticity/TangentStiffness.hpp"

#include <capsula/mesh/SurfaceMassMatrix.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/quadrature/Rule1D.hpp>
#include <capsula/quadrature/TriangleRule.hpp>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace capsula::elasticity {

/// How the load on the fluids is computed from the membrane's deformation.
enum class MembraneForceMethod {
  ContourIntegral, ///< thesis eq 3.37: element-averaged, from nodal tensions
  VirtualWork      ///< nodal forces dE/dx_k and a continuous load M^-1 F
};

/// "Contour integral" / "Virtual work" (the deck's names) and back; throws
/// core::InputError for an unknown name.
MembraneForceMethod membraneForceMethod(const std::string& name);
std::string to_string(MembraneForceMethod method);

/// Accuracy knobs of MembraneMechanics.
struct MembraneDiscretisation {
  /// N_Q of the triangle rule for element areas and centroids (the averaging weights
  /// and A_m of eq 3.37) and for the strain energy.
  int numQuadraturePoints = 7;
  /// Gauss-Legendre points along each curved edge for the contour integral (eq 3.37).
  int numEdgePoints = 4;
  /// How the load is computed (the scene's default is VirtualWork, see SceneParameters).
  MembraneForceMethod forceMethod = MembraneForceMethod::ContourIntegral;
};

/// What MembraneMechanics::evaluate computes.
enum class MembraneEvaluation {
  Everything, ///< loads and the nodal kinematics and tensions (outputs)
  LoadOnly    ///< VirtualWork: the load and the fold check only; the nodal stretches and
              ///< tensions keep the values of the last full evaluation (a right-hand side
              ///< needs none of them). ContourIntegral needs the tensions: same as Everything.
};

/// The node where the smallest principal tension sits, and its value.
struct MostCompressiveTension {
  int node;
  double tension;
};

/// The node where the law's smallest principal stiffness d2w/dlambda_i^2 sits, and its value
/// (PrincipalStiffness.hpp; negative: the law softens there as it is compressed further).
struct LeastPrincipalStiffness {
  int node;
  double stiffness;
};

class MembraneMechanics {
public:
  /// `mesh` gives the topology (it must outlive this object; its positions are not
  /// used); `referencePositions` (3 per node, the mesh's numbering) is the unstressed
  /// shape. `bending` with a modulus > 0 adds the Helfrich bending term (VirtualWork
  /// only). Throws InputError for a wrong size, a null law, a bad N_Q or edge-point
  /// count, a reference element folded against its neighbours, or bending with the
  /// contour-integral load.
  MembraneMechanics(const mesh::SurfaceMesh& mesh, std::vector<double> referencePositions,
                    std::shared_ptr<const MembraneLaw> law, const MembraneDiscretisation& discretisation = {},
                    const BendingParameters& bending = {});

  /// Computes everything below for the current positions (3 * numNodes doubles), or with
  /// LoadOnly what the load needs. Throws NumericalError if the membrane is folded or
  /// crushed somewhere.
  void evaluate(const double* positions, MembraneEvaluation what = MembraneEvaluation::Everything);
  /// The same with forces acting on the membrane from outside it (contact, bonds: 3 per
  /// node, virtual-work nodal forces, int phi_k f_ext dS): the membrane in equilibrium
  /// passes them to the fluids, so they are taken from F before the mass solve
  /// (Delta f = -div_s T - f_ext). VirtualWork only (throws InputError otherwise).
  void evaluate(const double* positions, MembraneEvaluation what, const double* externalForces);
  /// The fold check of evaluate() alone (allocates its nodal normals; no member changes):
  /// throws NumericalError naming the first node where an element's material normal and
  /// the node's averaged normal point to opposite sides.
  void requireUnfolded(const double* positions) const;

  // --- per node (after evaluate) --------------------------------------------
  const std::vector<Mat3>& nodalTensions() const { return tension_; } ///< T, eq 3.30
  const std::vector<PrincipalStretches>& nodalStretches() const { return stretch_; }
  const std::vector<PrincipalTensions>& nodalPrincipalTensions() const { return principal_; }
  const std::vector<Vec3>& nodeNormals() const { return normal_; } ///< current, area-averaged
  /// The smallest principal tension over the nodes (negative: compression, buckling).
  MostCompressiveTension mostCompressiveTension() const;
  /// The smallest principal stiffness of the law over the nodes, at their stretches.
  LeastPrincipalStiffness leastPrincipalStiffness() const;

  // --- per element (after evaluate) -----------------------------------------
  const std::vector<double>& elementAreas() const { return area_; }       ///< A_m, current
  const std::vector<Vec3>& elementCentroids() const { return centroid_; } ///< int x dS / A_m
  /// A_m <Delta f>_m = -oint_{C_m} T . b dl, the element's total load on the fluids.
  const std::vector<Vec3>& elementForces() const { return force_; }
  /// <Delta f>_m (eq 3.37), what multiplies int_{E_m} G dS in the single layer (eq 3.38).
  const std::vector<Vec3>& elementLoads() const { return load_; }
  /// VirtualWork only: the nodal values f_k of the continuous load Delta f = sum phi_k f_k.
  const std::vector<Vec3>& nodalLoads() const { return nodalLoad_; }
  /// VirtualWork only: F_k = dE/dx_k, the nodal forces of virtual work (sum_k F_k = 0).
  const std::vector<Vec3>& nodalForces() const { return nodalForce_; }
  /// Writes Delta f at the six nodes of every element, 18 numbers per element (the layout
  /// the single layer integrates, operators::LoadDensity): the nodal values of the
  /// continuous load (VirtualWork) or the element's constant load six times (ContourIntegral).
  void writeElementNodeLoads(double* out) const;

  /// sum_m A_m <Delta f>_m: zero to round-off (shared edges cancel exactly).
  Vec3 netForce() const;
  /// int_{E_m} x x Delta f dS = -oint_{C_m} x x (T . b) dl (exact for Delta f = -div_s T
  /// with T symmetric and tangent): the element's moment about the origin.
  const std::vector<Vec3>& elementMoments() const { return moment_; }
  /// sum_m [M_m - about x A_m <Delta f>_m]: the membrane's net torque on the fluids, zero
  /// to round-off for any deformation (shared edges cancel exactly).
  Vec3 netTorque(const Vec3& about = Vec3::Zero()) const;
  /// sum_m (c_m - about) x A_m <Delta f>_m, c_m the element centroids: the torque of the
  /// piecewise-constant load the single layer sees (eq 3.36); zero only up to the
  /// discretisation error (second order).
  Vec3 loadTorque(const Vec3& about = Vec3::Zero()) const;

  /// int_{S0} w dS0 at `positions`, from the element-wise A at the quadrature points
  /// (no nodal averaging). Independent of evaluate().
  double strainEnergy(const double* positions) const;

  /// The bending term, or null where the membrane has none.
  const HelfrichBending* bending() const { return bending_.get(); }
  /// The Helfrich energy at the last evaluate() (0 without bending).
  double bendingEnergy() const { return bending_ ? bending_->energy() : 0.0; }

  /// VirtualWork only: H = d2E/dx dx at `positions`, the derivative of nodalForces()
  /// (MembraneEnergyHessian.hpp), with the bending term's stiffness on the normal modes
  /// where there is one (HelfrichBending::applyStiffness). Independent of evaluate(). Throws InputError for the
  /// contour-integral load, which is not the gradient of an energy, and NumericalError
  /// for a crushed element.
  TangentStiffness tangentStiffness(const double* positions) const;

  /// The same membrane (mesh, law, discretisation) with another reference shape: what a
  /// tangential redistribution of the nodes (mesh::redistributeNodes) leaves behind, the
  /// nodes' new material points. Throws as the constructor does.
  MembraneMechanics withReference(std::vector<double> referencePositions) const
  {
    return MembraneMechanics(*mesh_, std::move(referencePositions), law_, discretisation_,
                             bending_ ? bending_->parameters() : BendingParameters{});
  }

  const MembraneLaw& law() const { return *law_; }
  const std::vector<double>& referencePositions() const { return reference_; }
  const std::vector<Vec3>& referenceNodeNormals() const { return referenceNormal_; }
  const MembraneDiscretisation& discretisation() const { return discretisation_; }

private:
  const mesh::SurfaceMesh* mesh_;
  std::vector<double> reference_;
  std::shared_ptr<const MembraneLaw> law_;
  MembraneDiscretisation discretisation_;
  const quadrature::TriangleRule* areaRule_;
  quadrature::Rule1D edgeRule_;

  void contourIntegralLoads(const double* positions);
  void virtualWorkLoads(const double* positions, const double* externalForces);

  // Reference data, per element (shape parameters) and per element node (6 e + j).
  std::vector<mesh::ShapeParameters> referenceParameters_;
  std::vector<Vec3> referenceNormal_;              // per node, area-averaged N
  std::vector<std::array<Vec3, 2>> referenceDual_; // G^xi, G^eta carried into the nodal plane

  // Work arrays, sized once.
  std::vector<std::array<Vec3, 2>> currentTangent_;       // x_xi, x_eta per element node (material)
  std::vector<double> weight_;                            // per node: sum of incident areas
  std::vector<Mat3> gradient_;                            // per node: averaged A
  std::vector<ReferenceQuadraturePoint> referencePoints_; // VirtualWork: N_Q per element
  std::unique_ptr<mesh::SurfaceMassMatrix> mass_;         // VirtualWork only
  std::unique_ptr<HelfrichBending> bending_;              // with a bending modulus only

  // Results.
  std::vector<double> area_;
  std::vector<Vec3> centroid_;
  std::vector<Vec3> moment_;
  std::vector<Vec3> normal_;
  std::vector<Mat3> tension_;
  std::vector<PrincipalStretches> stretch_;
  std::vector<PrincipalTensions> principal_;
  std::vector<Vec3> force_;
  std::vector<Vec3> load_;
  std::vector<Vec3> nodalForce_;
  std::vector<Vec3> nodalLoad_;
};

} // namespace capsula::elasticity
