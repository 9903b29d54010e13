#include "capsula/elasticity/MembraneMechanics.hpp"

#include "capsula/elasticity/EdgeTensionForce.hpp"
#include "capsula/elasticity/PrincipalStiffness.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/NodeNormals.hpp>
#include <capsula/quadrature/GaussLegendre.hpp>

#include <cmath>
#include <cstddef>
#include <utility>

namespace capsula::elasticity {

using mesh::ElementNodes;
using mesh::ShapeParameters;
using mesh::SurfacePoint;

namespace {

std::size_t slot(int element, int localNode)
{
  return 6 * static_cast<std::size_t>(element) + localNode;
}

// The fold criterion of evaluate() and requireUnfolded(): the material normal n_e of an
// element at one of its nodes points to the same side as the node's averaged normal n.
void requireSameSide(const Vec3& elementNormal, const Vec3& nodeNormal, int node, int element)
{
  const double product = elementNormal.dot(nodeNormal);
  core::require<core::NumericalError>(product > 0.0, "the membrane is folded at node ", node, " of element ", element,
                                      " (element normal . nodal normal = ", product, ")");
}

} // namespace

MembraneForceMethod membraneForceMethod(const std::string& name)
{
  if (name == "Contour integral") {
    return MembraneForceMethod::ContourIntegral;
  }
  core::require<core::InputError>(name == "Virtual work", "unknown membrane force method '", name,
                                  "': use 'Virtual work' or 'Contour integral'");
  return MembraneForceMethod::VirtualWork;
}

std::string to_string(MembraneForceMethod method)
{
  return method == MembraneForceMethod::ContourIntegral ? "Contour integral" : "Virtual work";
}

MembraneMechanics::MembraneMechanics(const mesh::SurfaceMesh& mesh, std::vector<double> referencePositions,
                                     std::shared_ptr<const MembraneLaw> law,
                                     const MembraneDiscretisation& discretisation, const BendingParameters& bending)
    : mesh_(&mesh),
      reference_(std::move(referencePositions)),
      law_(std::move(law)),
      discretisation_(discretisation),
      areaRule_(&quadrature::triangleRule(discretisation.numQuadraturePoints))
{
  const int numNodes = mesh.numNodes();
  const int numElements = mesh.numElements();
  core::require<core::InputError>(reference_.size() == 3 * static_cast<std::size_t>(numNodes),
                                  "the membrane reference has ", reference_.size(), " coordinates but the mesh has ",
                                  numNodes, " nodes (", 3 * numNodes, " coordinates expected)");
  core::require<core::InputError>(law_ != nullptr, "the membrane needs a constitutive law");
  core::require<core::InputError>(discretisation.numEdgePoints >= 1,
                                  "the membrane contour integral needs numEdgePoints >= 1, got ",
                                  discretisation.numEdgePoints);
  edgeRule_ = quadrature::gaussLegendre(discretisation.numEdgePoints, 0.0, 1.0);

  // Reference geometry: nodal normals N and, per element node, the dual tangents
  // carried from the element's tangent plane into the nodal one (N_e -> N).
  referenceNormal_ = mesh::nodeNormals(mesh, reference_.data(), discretisation.numQuadraturePoints);
  referenceParameters_.resize(numElements);
  referenceDual_.resize(6 * static_cast<std::size_t>(numElements));
  for (int e = 0; e < numElements; ++e) {
    const ElementNodes X = mesh.elementNodes(e, reference_.data());
    const ShapeParameters p = mesh::shapeParameters(X);
    referenceParameters_[e] = p;
    for (int j = 0; j < 6; ++j) {
      const int node = mesh.element(e)[j];
      const SurfacePoint S = mesh::evaluateAtNode(X, p, j);
      const Vec3& N = referenceNormal_[node];
      core::require<core::InputError>(std::isfinite(S.metric) && S.metric > 0.0 && S.normal.dot(N) > 0.0,
                                      "the membrane reference is degenerate or folded at node ", node, " of element ",
                                      e, " (element normal . nodal normal = ", S.normal.dot(N), ")");
      const auto dual = dualTangents(S.tangentXi, S.tangentEta);
      referenceDual_[slot(e, j)] = {rotateOnto(dual[0], S.normal, N), rotateOnto(dual[1], S.normal, N)};
    }
  }

  if (discretisation.forceMethod == MembraneForceMethod::VirtualWork) {
    // Material coordinates: the reference shape parameters at the N_Q points.
    const quadrature::TriangleRule& rule = *areaRule_;
    referencePoints_.reserve(static_cast<std::size_t>(numElements) * rule.weight.size());
    for (int e = 0; e < numElements; ++e) {
      const ElementNodes X = mesh.elementNodes(e, reference_.data());
      for (std::size_t q = 0; q < rule.weight.size(); ++q) {
        referencePoints_.push_back(
            referenceQuadraturePoint(X, referenceParameters_[e], rule.xi[q], rule.eta[q], rule.weight[q]));
      }
    }
    mass_ = std::make_unique<mesh::SurfaceMassMatrix>(mesh);
    nodalForce_.assign(numNodes, Vec3::Zero());
    nodalLoad_.assign(numNodes, Vec3::Zero());
  }
  if (bending.modulus != 0.0 || bending.spontaneousCurvature != 0.0) {
    core::require<core::InputError>(discretisation.forceMethod == MembraneForceMethod::VirtualWork,
                                    "bending ('Bending modulus' > 0) needs the virtual-work load ('Membrane "
                                    "forces' = 'Virtual work'): it enters as the nodal forces of its energy");
    bending_ = std::make_unique<HelfrichBending>(mesh, reference_, bending);
  }

  currentTangent_.resize(6 * static_cast<std::size_t>(numElements));
  weight_.resize(numNodes);
  gradient_.resize(numNodes);
  area_.assign(numElements, 0.0);
  centroid_.assign(numElements, Vec3::Zero());
  normal_.assign(numNodes, Vec3::Zero());
  tension_.assign(numNodes, Mat3::Zero());
  stretch_.assign(numNodes, PrincipalStretches{1.0, 1.0});
  principal_.assign(numNodes, PrincipalTensions{0.0, 0.0});
  force_.assign(numElements, Vec3::Zero());
  moment_.assign(numElements, Vec3::Zero());
  load_.assign(numElements, Vec3::Zero());
}

void MembraneMechanics::requireUnfolded(const double* positions) const
{
  const mesh::SurfaceMesh& mesh = *mesh_;
  const std::vector<Vec3> normals = mesh::nodeNormals(mesh, positions, discretisation_.numQuadraturePoints);
  for (int e = 0; e < mesh.numElements(); ++e) {
    const ElementNodes x = mesh.elementNodes(e, positions);
    for (int j = 0; j < 6; ++j) {
      const int node = mesh.element(e)[j];
      const SurfacePoint m = mesh::evaluateAtNode(x, referenceParameters_[e], j);
      requireSameSide(m.tangentXi.cross(m.tangentEta).normalized(), normals[node], node, e);
    }
  }
}

void MembraneMechanics::evaluate(const double* positions, MembraneEvaluation what)
{
  evaluate(positions, what, nullptr);
}

void MembraneMechanics::evaluate(const double* positions, MembraneEvaluation what, const double* externalForces)
{
  core::require<core::InputError>(externalForces == nullptr ||
                                      discretisation_.forceMethod == MembraneForceMethod::VirtualWork,
                                  "forces from outside the membrane (contact, bonds) need the virtual-work load "
                                  "('Membrane forces' = 'Virtual work')");
  // The virtual-work load needs neither the nodal average of A nor the nodal tensions
  // (steps 2-3 below, a third of this function's time at level 3); the fold check of
  // step 2 is kept.
  const bool nodal =
      what == MembraneEvaluation::Everything || discretisation_.forceMethod == MembraneForceMethod::ContourIntegral;
  const mesh::SurfaceMesh& mesh = *mesh_;
  const quadrature::TriangleRule& rule = *areaRule_;
  const int numNodes = mesh.numNodes();
  const int numElements = mesh.numElements();

  for (int i = 0; i < numNodes; ++i) {
    normal_[i].setZero();
    gradient_[i].setZero();
    weight_[i] = 0.0;
  }

  // 1. Element areas, centroids and node normals (current shape parameters), and the
  //    material tangents x_xi, x_eta at the nodes (reference shape parameters).
  for (int e = 0; e < numElements; ++e) {
    const ElementNodes x = mesh.elementNodes(e, positions);
    const ShapeParameters p = mesh::shapeParameters(x);
    double area = 0.0;
    Vec3 moment = Vec3::Zero();
    for (std::size_t q = 0; q < rule.weight.size(); ++q) {
      const SurfacePoint s = mesh::evaluateSurfacePoint(x, p, rule.xi[q], rule.eta[q]);
      area += rule.weight[q] * s.metric;
      moment += (rule.weight[q] * s.metric) * s.position;
    }
    area_[e] = area;
    centroid_[e] = moment / area;
    for (int j = 0; j < 6; ++j) {
      const int node = mesh.element(e)[j];
      normal_[node] += area * mesh::evaluateAtNode(x, p, j).normal;
      weight_[node] += area;
      const SurfacePoint m = mesh::evaluateAtNode(x, referenceParameters_[e], j);
      currentTangent_[slot(e, j)] = {m.tangentXi, m.tangentEta};
    }
  }
  for (Vec3& n : normal_) {
    n.normalize();
  }

  // 2. Area-weighted average of A_e carried into the nodal planes (n_e -> n).
  for (int e = 0; e < numElements; ++e) {
    for (int j = 0; j < 6; ++j) {
      const int node = mesh.element(e)[j];
      const auto& t = currentTangent_[slot(e, j)];
      const Vec3 ne = t[0].cross(t[1]).normalized();
      const Vec3& n = normal_[node];
      requireSameSide(ne, n, node, e);
      if (!nodal) {
        continue;
      }
      const auto& dual = referenceDual_[slot(e, j)];
      gradient_[node] +=
          area_[e] * (rotateOnto(t[0], ne, n) * dual[0].transpose() + rotateOnto(t[1], ne, n) * dual[1].transpose());
    }
  }

  // 3. Nodal kinematics and tension (eqs 3.26, 3.28-3.30).
  const MembraneLaw& law = *law_;
  for (int i = 0; i < (nodal ? numNodes : 0); ++i) {
    const Vec3& n = normal_[i];
    const Mat3 A = tangentProjector(n) * (gradient_[i] / weight_[i]) * tangentProjector(referenceNormal_[i]);
    const Mat3 B = A * A.transpose();
    const PrincipalStretches s = principalStretches(B, n);
    core::require<core::NumericalError>(std::isfinite(s.minor) && s.minor > 0.0, "the membrane is crushed at node ", i,
                                        " (principal stretches ", s.major, ", ", s.minor, ")");
    const StrainInvariants I = strainInvariants(s);
    const EnergyDerivatives dw = law.energyDerivatives(I.I1, I.I2);
    stretch_[i] = s;
    tension_[i] = membraneTension(B, n, s, dw);
    principal_[i] = principalTensions(s, dw);
  }

  // 4. The load.
  if (discretisation_.forceMethod == MembraneForceMethod::VirtualWork) {
    virtualWorkLoads(positions, externalForces);
  } else {
    contourIntegralLoads(positions);
  }
}

void MembraneMechanics::contourIntegralLoads(const double* positions)
{
  // Contour integrals (eq 3.37): each edge once, opposite signs on its two elements.
  const mesh::SurfaceMesh& mesh = *mesh_;
  const int numElements = mesh.numElements();
  for (int e = 0; e < numElements; ++e) {
    force_[e].setZero();
    moment_[e].setZero();
  }
  EdgeNodalData edge;
  for (const mesh::Edge& ed : mesh.edges()) {
    const std::array<int, 3> nodes = {ed.vertices[0], ed.midNode, ed.vertices[1]};
    for (int k = 0; k < 3; ++k) {
      edge.position[k] = mesh::nodeAt(positions, nodes[k]);
      edge.normal[k] = normal_[nodes[k]];
      edge.tension[k] = tension_[nodes[k]];
    }
    const double midParameter = edgeMidParameter(edge.position[0], edge.position[1], edge.position[2]);
    // b points out of elements[0], which traverses the edge in this direction.
    const EdgeResultant transmitted = edgeTensionResultant(edge, midParameter, edgeRule_);
    force_[ed.elements[0]] -= transmitted.force;
    force_[ed.elements[1]] += transmitted.force;
    moment_[ed.elements[0]] -= transmitted.moment;
    moment_[ed.elements[1]] += transmitted.moment;
  }
  for (int e = 0; e < numElements; ++e) {
    load_[e] = force_[e] / area_[e];
  }
}

void MembraneMechanics::virtualWorkLoads(const double* positions, const double* externalForces)
{
  const mesh::SurfaceMesh& mesh = *mesh_;
  const quadrature::TriangleRule& rule = *areaRule_;
  const std::size_t nq = rule.weight.size();
  const MembraneLaw& law = *law_;
  for (Vec3& F : nodalForce_) {
    F.setZero();
  }
  // F_k = dE/dx_k, element by element (MembraneEnergyGradient.hpp).
  for (int e = 0; e < mesh.numElements(); ++e) {
    const ElementNodes x = mesh.elementNodes(e, positions);
    Vec3 gradient[6];
    for (Vec3& g : gradient) {
      g.setZero();
    }
    for (std::size_t q = 0; q < nq; ++q) {
      const double energy = addEnergyGradient(referencePoints_[static_cast<std::size_t>(e) * nq + q], x, law, gradient);
      core::require<core::NumericalError>(std::isfinite(energy), "the membrane is crushed in element ", e,
                                          " (degenerate tangents at a quadrature point)");
    }
    for (int k = 0; k < 6; ++k) {
      nodalForce_[static_cast<std::size_t>(mesh.element(e)[k])] += gradient[k];
    }
  }
  if (externalForces != nullptr) { // Delta f = -div_s T - f_ext
    for (std::size_t k = 0; k < nodalForce_.size(); ++k) {
      nodalForce_[k] -= mesh::nodeAt(externalForces, static_cast<int>(k));
    }
  }
  if (bending_) {
    // The Helfrich energy's nodal forces join the strain energy's before the one density
    // solve below: with the same Galerkin map for both, the power of the forces on the
    // moving nodes is the power of the load on the fluid (up to how the nodal velocities
    // interpolate the fluid's), which the fluid dissipates. A separate map for the bending forces
    // breaks that balance and lets grid-scale wrinkles grow at small moduli
    // (docs/membrane-forces.md, "Bending").
    bending_->evaluate(positions);
    const std::vector<Vec3>& bendingForce = bending_->nodalForces();
    for (std::size_t k = 0; k < nodalForce_.size(); ++k) {
      nodalForce_[k] += bendingForce[k];
    }
  }
  // The load density: int phi_k Delta f dS = F_k, i.e. M f = F.
  mass_->assemble(positions);
  mass_->solve(nodalForce_.front().data(), nodalLoad_.front().data());
  // Element totals and moments of the continuous load: elementLoads() for the outputs
  // (membrane stress metrics, snapshots) and netForce()/netTorque() for the checks.
  for (int e = 0; e < mesh.numElements(); ++e) {
    const ElementNodes x = mesh.elementNodes(e, positions);
    const ShapeParameters p = mesh::shapeParameters(x);
    Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
    for (std::size_t q = 0; q < nq; ++q) {
      const SurfacePoint s = mesh::evaluateSurfacePoint(x, p, rule.xi[q], rule.eta[q]);
      double phi[6];
      mesh::shapeFunctions(p, rule.xi[q], rule.eta[q], phi);
      Vec3 f = Vec3::Zero();
      for (int k = 0; k < 6; ++k) {
        f += phi[k] * nodalLoad_[static_cast<std::size_t>(mesh.element(e)[k])];
      }
      const double w = rule.weight[q] * s.metric;
      force += w * f;
      moment += w * s.position.cross(f);
    }
    force_[e] = force;
    moment_[e] = moment;
    load_[e] = force / area_[e];
  }
}

void MembraneMechanics::writeElementNodeLoads(double* out) const
{
  const mesh::SurfaceMesh& mesh = *mesh_;
  const bool continuous = discretisation_.forceMethod == MembraneForceMethod::VirtualWork;
  for (int e = 0; e < mesh.numElements(); ++e) {
    double* element = out + 18 * static_cast<std::size_t>(e);
    for (int a = 0; a < 6; ++a) {
      const Vec3& f = continuous ? nodalLoad_[static_cast<std::size_t>(mesh.element(e)[a])] : load_[e];
      for (int d = 0; d < 3; ++d) {
        element[3 * a + d] = f[d];
      }
    }
  }
}

MostCompressiveTension MembraneMechanics::mostCompressiveTension() const
{
  MostCompressiveTension most{0, principal_.empty() ? 0.0 : principal_[0].minor};
  for (std::size_t i = 1; i < principal_.size(); ++i) {
    if (principal_[i].minor < most.tension) {
      most = {static_cast<int>(i), principal_[i].minor};
    }
  }
  return most;
}

LeastPrincipalStiffness MembraneMechanics::leastPrincipalStiffness() const
{
  LeastPrincipalStiffness least{0, stretch_.empty() ? 0.0 : elasticity::leastPrincipalStiffness(*law_, stretch_[0])};
  for (std::size_t i = 1; i < stretch_.size(); ++i) {
    const double k = elasticity::leastPrincipalStiffness(*law_, stretch_[i]);
    if (k < least.stiffness) {
      least = {static_cast<int>(i), k};
    }
  }
  return least;
}

Vec3 MembraneMechanics::netForce() const
{
  Vec3 sum = Vec3::Zero();
  for (const Vec3& f : force_) {
    sum += f;
  }
  return sum;
}

Vec3 MembraneMechanics::netTorque(const Vec3& about) const
{
  Vec3 sum = Vec3::Zero();
  for (std::size_t e = 0; e < moment_.size(); ++e) {
    sum += moment_[e] - about.cross(force_[e]);
  }
  return sum;
}

Vec3 MembraneMechanics::loadTorque(const Vec3& about) const
{
  Vec3 sum = Vec3::Zero();
  for (std::size_t e = 0; e < force_.size(); ++e) {
    sum += (centroid_[e] - about).cross(force_[e]);
  }
  return sum;
}

double MembraneMechanics::strainEnergy(const double* positions) const
{
  const mesh::SurfaceMesh& mesh = *mesh_;
  const quadrature::TriangleRule& rule = *areaRule_;
  double energy = 0.0;
  for (int e = 0; e < mesh.numElements(); ++e) {
    const ElementNodes X = mesh.elementNodes(e, reference_.data());
    const ElementNodes x = mesh.elementNodes(e, positions);
    const ShapeParameters& p = referenceParameters_[e];
    for (std::size_t q = 0; q < rule.weight.size(); ++q) {
      const SurfacePoint S = mesh::evaluateSurfacePoint(X, p, rule.xi[q], rule.eta[q]);
      const SurfacePoint s = mesh::evaluateSurfacePoint(x, p, rule.xi[q], rule.eta[q]);
      const Mat3 A = surfaceDeformationGradient(s.tangentXi, s.tangentEta, dualTangents(S.tangentXi, S.tangentEta));
      // Element-wise A is exact: tr B = |A|_F^2 and J = h_s / H_s.
      const double J = s.metric / S.metric;
      const double I1 = A.squaredNorm() - 2.0;
      const double I2 = J * J - 1.0;
      energy += rule.weight[q] * S.metric * law_->energyDensity(I1, I2);
    }
  }
  return energy;
}

TangentStiffness MembraneMechanics::tangentStiffness(const double* positions) const
{
  core::require<core::InputError>(discretisation_.forceMethod == MembraneForceMethod::VirtualWork,
                                  "the membrane's tangent stiffness is the second variation of its strain "
                                  "energy, so it needs the virtual-work load (the contour-integral load is not "
                                  "an energy gradient)");
  const mesh::SurfaceMesh& mesh = *mesh_;
  const std::size_t nq = areaRule_->weight.size();
  std::vector<ElementStiffness> elements(static_cast<std::size_t>(mesh.numElements()));
  for (int e = 0; e < mesh.numElements(); ++e) {
    const ElementNodes x = mesh.elementNodes(e, positions);
    ElementStiffness& K = elements[static_cast<std::size_t>(e)];
    K.fill(0.0);
    for (std::size_t q = 0; q < nq; ++q) {
      core::require<core::NumericalError>(
          addEnergyHessian(referencePoints_[static_cast<std::size_t>(e) * nq + q], x, *law_, K),
          "the membrane is crushed in element ", e, " (degenerate tangents at a quadrature point)");
    }
  }
  std::shared_ptr<HelfrichBending> bending;
  if (bending_) { // a copy linearised at `positions`: the membrane's own keeps its state
    bending = std::make_shared<HelfrichBending>(*bending_);
    bending->evaluate(positions);
  }
  return TangentStiffness(mesh, std::move(elements), std::move(bending));
}

} // namespace capsula::elasticity
