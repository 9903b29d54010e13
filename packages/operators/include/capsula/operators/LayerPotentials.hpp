#pragma once
// (One class template per Green's function, instantiated in BuiltInKernels.cpp; the
// regular sums, the singular and near-singular corrections and the geometry they share are
// members that the hot loops inline across. Their definitions are in the three headers
// included at the end: LayerPotentialsGeometry.hpp, LayerPotentialsCorrections.hpp and
// LayerPotentialsEvaluation.hpp.)
//
// The single- and double-layer integrals of eq 3.38 for one Green's function (a kernel
// policy, KernelTraits.hpp), on the nodes this rank owns and at arbitrary points.
//
// For a target x0 every element is integrated in one of three ways:
//   regular        the N_Q-point rule (eq 3.39), in the vectorised sums of RegularSums.hpp;
//   singular       x0 is a node of the element: polar coordinates around it (eqs 3.42-3.43);
//   near-singular  x0 (or an image of it, for the wall) is within `Near-singular distance`
//                  element sizes of the element's bounding sphere: adaptive subdivision
//                  (AdaptiveQuadrature.hpp).
// The sums run over ALL points (no branch in the hot loop); the singular and
// near-singular elements then get a correction "special rule minus regular rule". The
// sums go through a FarFieldSummation back-end (FarFieldSummation.hpp): DirectSummation by
// default, or a fast one (a treecode), which then approximates the regular rule only; the
// corrections stay exact.
// A node's own neighbourhood (`Regular neighbour rings` of elements around those holding
// it, 2 by default) is left to the regular rule, as in the thesis: there the target lies
// in the tangent plane of a smooth surface, where the rule is 10-50 times more accurate
// than at the same distance off the surface, and subdividing changes the velocity by less
// than the discretisation error (docs/operators.md). The same elements seen from the
// images, and every farther element of the cell (a cell folding onto itself), are tested
// as usual.
// The single-layer corrections are computed with the load at each evaluation, except for
// a load given at the nodes (singleLayerOfNodalLoadAtNodes, the repeated applications of
// a stiff time step's linear solve), whose corrections are node blocks like the double
// layer's; the double-layer ones are 3x3 blocks on nodes, built once per geometry and
// reused by every application of the GMRES solve. Which elements are near each node target is found once
// per geometry and shared by both layers.
//
// Double layer on a surface (thesis eq 3.44 with the ERRATA sign): with n outward and
// T_ijk = -6 xh_i xh_j xh_k / r^5, PV int_S T_ijk n_k dS = -4 pi delta_ij at a point of a
// smooth surface S, so for x0 on cell c
//   PV int_Sc u_i T_ijk n_k dS = int_Sc [u_i(x) - u_i(x0)] T_ijk n_k dS - 4 pi u_j(x0),
// which holds for the wall kernel too (a closed surface in the fluid). Other cells are
// integrated directly (x0 is outside them: the identity gives 0).
#include <capsula/operators/AdaptiveQuadrature.hpp>
#include <capsula/operators/CellSurfaces.hpp>
#include <capsula/operators/DoubleLayerForm.hpp>
#include <capsula/operators/DirectSummation.hpp>
#include <capsula/operators/ElementIntegrals.hpp>
#include <capsula/operators/FarFieldBackEnd.hpp>
#include <capsula/operators/FarFieldSummation.hpp>
#include <capsula/operators/KernelTraits.hpp>
#include <capsula/operators/LoadDensity.hpp>
#include <capsula/operators/OperatorParameters.hpp>
#include <capsula/operators/PolarRules.hpp>
#include <capsula/operators/RegularSums.hpp>
#include <capsula/operators/SurfaceQuadrature.hpp>

#include <capsula/core/Error.hpp>
#include <capsula/quadrature/GaussLegendre.hpp>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>
#include <limits>
#include <memory>
#include <typeinfo>
#include <vector>

namespace capsula::operators {

template <class Kernel>
class LayerPotentials {
public:
  /// The regular sums go to the back-end of parameters.farField; when that is null, to the
  /// kernel's own summation if the policy has one (kernel.farFieldSummation(), a periodic
  /// kernel's Ewald sum), else to DirectSummation<Kernel>. Throws core::InputError naming
  /// 'Operator/Summation' if the back-end does not support Kernel.
  explicit LayerPotentials(const DiscretisationParameters& parameters, Kernel kernel = Kernel{});

  /// Sets the node targets, the global nodes [firstTargetNode, firstTargetNode +
  /// numTargetNodes) (the rows this rank owns), and the topology of `surfaces`, then
  /// calls update(surfaces).
  void setTopology(const CellSurfaces& surfaces, int firstTargetNode, int numTargetNodes);

  /// Rebuilds the quadrature caches from the current positions of `surfaces` (the
  /// topology given to setTopology) and drops the node corrections.
  void update(const CellSurfaces& surfaces);

  const SurfaceQuadrature& quadrature() const { return quadrature_; }
  const DiscretisationParameters& parameters() const { return parameters_; }
  const FarFieldSummation& farField() const { return *farField_; }
  /// The policy instance every kernel evaluation goes through, and its traits.
  const Kernel& kernel() const { return kernel_; }
  const KernelTraits<Kernel>& traits() const { return traits_; }
  int firstTargetNode() const { return firstTarget_; }
  int numTargetNodes() const { return numTargets_; }

  /// Builds the singular and near-singular corrections of the double layer at the node
  /// targets (doubleLayerAtNodes calls it when needed).
  void prepareDoubleLayerCorrections();

  /// result[3 t + j] = sum_m int_Em Delta f_i G_ij(x, x_t) dS (eq 3.36) at the target
  /// nodes, Delta f interpolated from its values at the element nodes (LoadDensity.hpp).
  void singleLayerAtNodes(const LoadDensity& load, double* result);

  /// The same for a load continuous across the elements, given by its values at the nodes
  /// (3 per node, global numbering). The singular and near-singular corrections are node
  /// blocks built on the first call after update() and reused until the next (the result
  /// agrees with singleLayerAtNodes to the near-singular tolerance).
  void singleLayerOfNodalLoadAtNodes(const double* nodalLoad, double* result);

  /// result[3 t + j] = sum over all cells of PV int u_i T_ijk(x, x_t) n_k dS at the target
  /// nodes, for the density u given at every node (3 per node, global numbering) and
  /// interpolated over each element with its shape functions.
  void doubleLayerAtNodes(const double* density, DoubleLayerForm form, double* result);

  /// The double layer (Subtracted form) of cell c's density alone, at the node targets of
  /// c this rank owns, as a dense block: doubleLayerAtNodes with the density of every other
  /// cell 0. Row 3 r + j is owned target `first + r` of c (first = the first owned node of
  /// c), column 3 b + i node nodeOffset(c) + b; `block` is resized to (3 rows) x (3 n_c),
  /// row-major, and returns the number of rows' nodes. The regular rule takes the pointwise
  /// kernel, as the corrections do, so for a kernel whose regular sums are another function
  /// (a periodic kernel's Ewald sums) the block leaves out the smooth difference between the
  /// two: the cell's interaction with its own periodic images. For the cell-block
  /// preconditioner of the viscosity-ratio equation (CellBlockPreconditioner.hpp).
  int cellDoubleLayerBlock(int cell, std::vector<double>& block);

  /// The single layer at n arbitrary points (3 each) off the surfaces (a point on a
  /// surface gets the subdivision down to its depth limit and a meaningless value).
  void singleLayerAtPoints(const double* points, int n, const LoadDensity& load, double* result);

  /// The double layer at n arbitrary points off the surfaces.
  void doubleLayerAtPoints(const double* points, int n, const double* density, double* result);

  /// omega[numCells() p + c]: the solid angle of cell c seen from point p (4 pi inside,
  /// 0 outside).
  void solidAnglesAtPoints(const double* points, int n, double* omega);

  /// Near-singular (target, element) pairs of the last node evaluation (diagnostics).
  long long nearSingularElementCount() const { return nearCount_; }

private:
  struct TargetCorrections {
    std::vector<int> nodes;  // node b ...
    std::vector<double> dbl; // ... and its block: result_j += u_b,i B_ij, [9 k + 3 i + j]
    double self[9] = {};     // the subtraction's block on u(x0), own cell only
  };

  // A node target's neighbourhood on its own cell: the elements holding it, and those
  // within parameters_.regularNeighbourRings rings of them (sharing a node, ring after ring).
  struct Neighbourhood {
    std::vector<std::pair<int, int>> incident; // (element, local node of the target)
    std::vector<int> ring;                     // sorted; includes the incident elements
  };

  struct CellRange {
    int firstNode, endNode, firstElement, endElement;
  };

  // A sphere about a cell that holds every element's near-singular zone (bounding sphere
  // plus `Near-singular distance` sizes): a target outside it, and its images too, is near
  // none of the cell's elements, which findNearElements then skips without testing them.
  struct CellReach {
    double centre[3];
    double radius;
  };

  int cellOfNode(int node) const;
  // Elements near x0 or one of its images; for a node target (neighbourhood given) its
  // incident elements are left out and its ring is tested from the images only.
  void findNearElements(const double* x0, const Neighbourhood* neighbourhood, std::vector<int>& near) const;
  // The elements [begin, end) near one of the poles (x0 and its images), appended to near.
  void addNearElements(const double (*poles)[3], int numPoles, int begin, int end, const Neighbourhood* neighbourhood,
                       std::vector<int>& near) const;
  // The regular rule over element m, as the sums do it, for one integrand.
  template <class Integrand>
  typename Integrand::Value regularRule(int m, const Integrand& integrand) const;
  // special - regular over element m for the target of `integrand`.
  template <class Integrand>
  typename Integrand::Value nearCorrection(int m, const Integrand& integrand) const;
  template <class Integrand>
  typename Integrand::Value singularCorrection(int m, int localNode, const Integrand& integrand,
                                               ParametricRule& rule) const;
  // The corrections of one node target as node blocks (special - regular of the element
  // integrals of `integrand`, summed per node); with `subtractOwn` also the own cell's
  // blocks, negated, on u(x0) (the double layer's subtraction).
  template <class Integrand>
  void correctTarget(int target, const Integrand& integrand, bool subtractOwn, TargetCorrections& out,
                     ParametricRule& rule) const;
  // The corrections of every node target with `Integrand` (once per geometry).
  template <class Integrand>
  void prepareCorrections(bool subtractOwn, std::vector<TargetCorrections>& corrections);
  void prepareNodalSingleLayerCorrections();
  // The near elements of every node target for the current geometry (findNearElements
  // with the target's neighbourhood), found on first use after update().
  void findNodeNearElements();
  void buildSingleLayerSources(const LoadDensity& load);
  void buildDoubleLayerSources(const double* density);
  SingleLayerSources singleLayerSources() const;
  DoubleLayerSources doubleLayerSources() const;
  // The block of points [first, first + targetBlockSize) of n, each moved to its periodic
  // image nearest to `reference` (itself for a kernel without periods).
  void startPointBlock(TargetBlock& block, const double* points, int first, int n, const double* reference) const;
  // result = far + the near-singular corrections at each of n points; addNear(m, x0, u)
  // adds element m's correction for the target x0 to u[3].
  template <class AddNear>
  void addNearCorrectionsAtPoints(const double* points, int n, const std::vector<double>& far, double* result,
                                  const AddNear& addNear) const;

  Kernel kernel_;
  KernelTraits<Kernel> traits_;
  DiscretisationParameters parameters_;
  SurfaceQuadrature quadrature_;
  std::vector<ElementMap> elementMaps_; // per element, for the special rules
  quadrature::Rule1D gauss_;
  ParametricRule vertexRules_[3];
  std::vector<CellRange> cells_;
  std::vector<CellReach> cellReach_;          // per cell, for the current geometry
  std::vector<Neighbourhood> neighbourhoods_; // per node target
  int firstTarget_ = 0;
  int numTargets_ = 0;

  bool hasDoubleCorrections_ = false;
  std::vector<TargetCorrections> corrections_;
  bool hasSingleCorrections_ = false;
  std::vector<TargetCorrections> singleCorrections_; // nodal loads; .self unused
  bool hasNodeNear_ = false;
  std::vector<std::vector<int>> nodeNear_; // per node target
  long long nearCount_ = 0;

  // Per-evaluation source arrays (kept to avoid reallocation).
  std::vector<double> fx_, fy_, fz_, vx_, vy_, vz_;

  std::unique_ptr<FarFieldSummation> farField_;
  std::vector<double> nodeTargets_;  // positions of the target nodes (3 each)
  std::vector<int> nodeTargetCells_; // their cells
  std::vector<double> far_;          // the back-end's sums (3 per target)
};

} // namespace capsula::operators

#include <capsula/operators/LayerPotentialsGeometry.hpp>
#include <capsula/operators/LayerPotentialsCorrections.hpp>
#include <capsula/operators/LayerPotentialsEvaluation.hpp>
