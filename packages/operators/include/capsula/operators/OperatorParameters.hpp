#pragma once
// Deck parameters of the boundary-integral operators: the quadrature of the surface
// integrals ("Discretisation") and the Krylov solve of the lambda != 1 equation ("Solver";
// its method and the Belos sublist: KrylovMethod.hpp).
// Each knob trades accuracy for time; the defaults and their reasons are in the doc
// strings (docs/operators.md has the measurements behind them).
#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <string>

namespace capsula::operators {

class FarFieldBackEnd;

/// How the element integrals are computed (thesis Section 3.6).
struct DiscretisationParameters {
  /// N_Q, points of the symmetric triangle rule on regular elements (eq 3.39).
  int quadraturePoints = 7;
  /// N_GL, Gauss-Legendre points per polar direction on the elements that hold the
  /// target node (eqs 3.42-3.43).
  int singularQuadraturePoints = 6;
  /// Target accuracy of the adaptive subdivision of near-singular elements, relative to
  /// the size of that element's contribution.
  double nearSingularTolerance = 1e-6;
  /// An element is near-singular for a target closer than this many element sizes to it.
  double nearSingularDistance = 1.0;
  /// Rings of elements around those holding a node target that keep the N_Q-point rule
  /// even when near (the node lies in their tangent plane); 0 tests them too.
  int regularNeighbourRings = 2;
  /// The back-end of the regular sums ('Operator/Summation'); null: the direct sums.
  std::shared_ptr<const FarFieldBackEnd> farField;
};

/// The Krylov solve of the second-kind equation for lambda != 1 (thesis Section 3.8).
struct SolverParameters {
  /// The Belos solver manager, by the name Belos's factory takes (KrylovMethod.hpp).
  std::string method = "Block GMRES";
  /// On ||b - A u|| / ||b||. This struct default is the tight value the unit tests and the
  /// 2D contour use; the 3D deck declares kSurfaceSolverTolerance instead.
  double tolerance = 1e-10;
  int restart = 50; ///< Krylov vectors kept between restarts (Belos "Num Blocks")
  int maximumIterations = 300;
  /// Belos parameters of `method` that replace those Capsula derives from the keys above
  /// ('Solver/Belos'; empty: none).
  Teuchos::ParameterList belos;
  /// Start each solve of a time integration from the last solutions (WarmStartHistory.hpp;
  /// scene::Scene keeps the history and its checkpoint carries it). The 3D deck's
  /// 'Solver/Warm start' defaults to true.
  bool warmStart = false;
  /// Solve iteratively even when every viscosity ratio is 1 (for tests; not a deck key).
  bool alwaysIterate = false;
  /// Precondition the solve by each cell's own block, inverted (CellBlockPreconditioner.hpp;
  /// the 3D deck's 'Solver/Preconditioner' = "Cell blocks"): flexible GMRES then replaces
  /// `method` and `belos`.
  bool cellBlockPreconditioner = false;
  /// When the cell blocks are rebuilt: at the first solve after every move of the nodes, or
  /// only after BoundaryIntegralSolver::refreshPreconditioner() (a time integration's step
  /// starts, scene::Scene; not a deck key).
  enum class PreconditionerRefresh { EveryGeometry, OnRequest };
  PreconditionerRefresh preconditionerRefresh = PreconditionerRefresh::EveryGeometry;
};

/// The values of 'Solver/Preconditioner'.
inline constexpr const char* kNoPreconditioner = "None";
inline constexpr const char* kCellBlockPreconditioner = "Cell blocks";

/// Declares Quadrature points, Singular quadrature points, Near-singular tolerance,
/// Near-singular distance and Regular neighbour rings in `discretisation`.
void declareDiscretisationParameters(Teuchos::ParameterList& discretisation);

/// The 3D deck's default 'Solver/Tolerance'. The solve's error moves the nodes by about
/// 0.45 x tolerance by t = 1 (level 2, lambda = 5, h/a = 1.6, measured for 1e-4..1e-8); the
/// RKF45 default tolerance 1e-6 moves them by 2.7e-8 (against RKF45 at 1e-8). 1e-9 keeps
/// the solve's share ~60 times below the integrator's (docs/operators.md, "GMRES tolerance
/// and warm start").
constexpr double kSurfaceSolverTolerance = 1e-9;

/// Declares Method, Tolerance (default: SolverParameters{}.tolerance), Restart, Maximum
/// iterations, Warm start and the Belos sublist in `solver` (the 2D contour's list).
void declareSolverParameters(Teuchos::ParameterList& solver);

/// The 3D surfaces' list: as declareSolverParameters with Tolerance defaulting to
/// kSurfaceSolverTolerance.
void declareSurfaceSolverParameters(Teuchos::ParameterList& solver);

/// Declares the 3D lists, in the sublists "Discretisation" (declareDiscretisationParameters)
/// and "Solver" (declareSurfaceSolverParameters) of `deck`.
void declareOperatorParameters(Teuchos::ParameterList& deck);

/// Reads a validated "Discretisation" sublist. Throws core::InputError for a value a
/// validator cannot check (a triangle rule that does not exist), naming the key.
DiscretisationParameters readDiscretisationParameters(const Teuchos::ParameterList& discretisation);

/// Reads a validated "Solver" sublist (warmStart false where the list has no Warm start,
/// the default method where it has no Method). Throws core::InputError naming
/// 'Solver/Belos/<key>' for an entry the chosen method does not take.
SolverParameters readSolverParameters(const Teuchos::ParameterList& solver);

/// Throws core::InputError naming `key` unless a symmetric triangle rule has `points` points.
void requireTriangleRule(int points, const std::string& key);

/// Throws core::InputError naming the offending field unless the values are usable (for the
/// solver: also the method and its Belos entries, validateKrylovSettings in KrylovMethod.hpp).
void validate(const DiscretisationParameters& parameters);
void validate(const SolverParameters& parameters);

} // namespace capsula::operators
