#pragma once
// How the 2D boundary integrals over a spline contour are computed (thesis App. A.6), and
// the deck keys of the "Discretisation" sublist of the 2D apps.
#include <Teuchos_ParameterList.hpp>

namespace capsula::scene2d {

struct ContourDiscretisation2D {
  /// N_GL, Gauss-Legendre points per segment (eq A.40); the thesis used 6 (Table 3.2).
  int gaussLegendrePoints = 6;
  /// Points of the Gauss rule for the weight -ln(t) that integrates the single layer's
  /// logarithm on the two segments holding the target node (eqs A.46-A.47, ERRATA).
  int logWeightedPoints = 6;
  /// A piece of a segment closer than this many of its lengths to the target or to its
  /// image below the wall is bisected (adaptive subdivision); 0 turns it off, as in the
  /// thesis. At the thesis's gap 0.005 plain Gauss-Legendre misses the double-layer
  /// identity by 2e-3 at N = 256; 2 brings it to 2e-9 (tests/unit/scene2d).
  double nearSingularDistance = 2.0;
  /// Most bisections of one segment (2^levels pieces at most).
  int nearSingularLevels = 8;
};

/// Declares Gauss-Legendre points, Log-weighted points, Near-singular distance and
/// Near-singular levels in `discretisation`.
void declareContourDiscretisation2D(Teuchos::ParameterList& discretisation);

/// Reads a validated "Discretisation" sublist.
ContourDiscretisation2D readContourDiscretisation2D(const Teuchos::ParameterList& discretisation);

/// Throws core::InputError naming the field unless the values are usable.
void validate(const ContourDiscretisation2D& parameters);

} // namespace capsula::scene2d
