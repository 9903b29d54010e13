#include "capsula/scene2d/CellContour2D.hpp"

#include <capsula/contour/InitialShapes.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/elasticity/MembraneLawChoice.hpp>

#include <cmath>
#include <string>

namespace capsula::scene2d {

void declareCellParameters2D(Teuchos::ParameterList& cell, const MembraneLawRegistry2D& laws)
{
  namespace core = capsula::core;
  const CellSettings2D defaults;
  core::declareReal(cell, "Aspect ratio", defaults.aspectRatio,
                    "a/b of the initial ellipse, a along the flow (x) and b across it (y); the area "
                    "is pi L^2 for every a/b (L = sqrt(ab) = 1, thesis Fig. 4.1). The thesis studied "
                    "0.25, 0.5 and 1.",
                    core::greaterThan(0.0));
  core::declareInt(cell, "Number of points", defaults.numberOfPoints,
                   "Marker points (= spline segments) of the contour; the thesis used 256 (Section "
                   "3.12.1).",
                   8, 100000);
  core::declareReal(cell, "Lowest point height", defaults.lowestPointHeight,
                    "Height of the cell's lowest point above y = 0 at the start (the thesis's 0.005). "
                    "With the wall it must be > 0; without it y = 0 is only where the shear flow is "
                    "at rest (-1 centres a circle there).");
  core::declareReal(cell, "Prestress", defaults.prestress,
                    "Membrane prestress alpha: the cell starts stretched by 1 + alpha over its unstressed "
                    "reference (the initial contour shrunk by 1 + alpha about its centroid), with the "
                    "uniform tension alpha E of the Hookean law. The thesis's 2D study has 0, with which "
                    "the free cell's membrane starts in compression in shear and wrinkles at the grid "
                    "scale on fine contours; a prestress that keeps it in tension makes the mesh study "
                    "converge (docs/tether2d-results.md).",
                    core::atLeast(0.0), core::lessThan(1.0));
  core::declareChoice(cell, "Tether spline ends", "Natural", {"Natural", "NotAKnot"},
                      "End conditions of the tethered contour's position splines at the tether node. "
                      "Natural (x'' = y'' = 0, thesis A.31-A.32) makes the tangents there, hence the "
                      "tether force, first-order accurate; NotAKnot makes them third-order, but without "
                      "Cell/Prestress the tethered run is unstable on fine contours "
                      "(docs/tether2d-results.md).");
  core::declareReal(cell, "Bending modulus", defaults.bendingModulus,
                    "Bending stiffness k_b / (E L^2) of the membrane: the moment k_b (kappa - kappa_ref) with the "
                    "energy (k_b/2) int (kappa - kappa_ref)^2 dl adds its load to the tension's "
                    "(scene2d/BendingLoad2D.hpp). It resists the grid-scale wrinkles of a compressed "
                    "membrane; 0 (the thesis's) builds no bending term. Use it with Tether spline ends = "
                    "NotAKnot: Natural ends force kappa = 0 at the tether, which the bending load turns into a "
                    "spurious tether force (refused).",
                    core::atLeast(0.0));
  core::declareChoice(cell, "Bending reference", "Flat", {"Flat", "Initial shape"},
                      "The curvature kappa_ref at which the membrane carries no bending moment: Flat (0), or "
                      "Initial shape: the curvature of the membrane's unstressed reference contour at each "
                      "material point (the initial contour, shrunk by 1 + Cell/Prestress), so that the "
                      "initial cell is free of bending moment when unstressed. Only read when Bending "
                      "modulus > 0 (refused without it, as a key without effect).");
  // Last, so that a law's key that would replace one of the cell's is refused.
  elasticity::declareMembraneLawParameters(cell, laws.infos(), HookeanLaw2D::registeredName,
                                           "The membrane's tension against its stretch omega = dl / dl0, in units "
                                           "of the elastic modulus E of the capillary number.");
}

CellSettings2D readCellSettings2D(const Teuchos::ParameterList& cell, const MembraneLawRegistry2D& laws)
{
  CellSettings2D s;
  s.aspectRatio = cell.get<double>("Aspect ratio");
  s.numberOfPoints = cell.get<int>("Number of points");
  s.lowestPointHeight = cell.get<double>("Lowest point height");
  s.prestress = cell.get<double>("Prestress");
  const elasticity::MembraneLawChoice law = elasticity::readMembraneLawChoice(cell, laws.infos(), "Cell");
  s.membraneLaw = laws.create(law.name, 1.0, law.parameters);
  s.tetherEnds = cell.get<std::string>("Tether spline ends") == "Natural" ? contour::TetherEnds::Natural
                                                                          : contour::TetherEnds::NotAKnot;
  s.bendingModulus = cell.get<double>("Bending modulus");
  core::require<core::InputError>(s.bendingModulus == 0.0 || s.tetherEnds == contour::TetherEnds::NotAKnot,
                                  "'Cell/Bending modulus' = ", s.bendingModulus,
                                  " needs 'Cell/Tether spline ends' = NotAKnot: Natural ends force kappa = 0 at "
                                  "the tether, which the bending load turns into a spurious tether force that grows "
                                  "with the number of points (docs/tether2d.md)");
  // Keys without effect are refused (docs/user-guide.md, "Keys without effect").
  core::require<core::InputError>(s.bendingModulus > 0.0 || cell.get<std::string>("Bending reference") == "Flat",
                                  "'Cell/Bending reference' = '", cell.get<std::string>("Bending reference"),
                                  "' has no effect without bending: set 'Cell/Bending modulus' > 0 or the reference to "
                                  "'Flat'.");
  s.bendingReference = cell.get<std::string>("Bending reference") == "Flat" ? BendingReference2D::Flat
                                                                            : BendingReference2D::InitialShape;
  return s;
}

double flowSemiAxis(const CellSettings2D& cell)
{
  return std::sqrt(cell.aspectRatio);
}

Eigen::Matrix2Xd initialCellNodes(const CellSettings2D& cell)
{
  contour::EllipseShape shape;
  shape.aspectRatio = cell.aspectRatio;
  shape.lengthScale = 1.0;
  const double b = 1.0 / std::sqrt(cell.aspectRatio);
  shape.centre = Eigen::Vector2d(0.0, cell.lowestPointHeight + b);
  shape.firstNodeAngle = -M_PI / 2.0; // node 0 at the bottom: the lowest point is a node
  return contour::ellipseNodes(cell.numberOfPoints, shape);
}

} // namespace capsula::scene2d
