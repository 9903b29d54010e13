#include "capsula/mesh/CellSurfaceParameters.hpp"

#include "capsula/mesh/Placement.hpp"
#include "capsula/mesh/Shapes.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>

#include <cmath>

namespace capsula::mesh {

namespace core = capsula::core;

void declareCellSurfaceParameters(Teuchos::ParameterList& cell, const std::array<double, 3>& center)
{
  core::declareChoice(cell, "Shape", "Sphere", {"Sphere", "Spheroid", "Ellipsoid", "Biconcave"},
                      "Initial shape. Sphere uses Radius; Spheroid and Ellipsoid use Semi-axes "
                      "(a spheroid has its symmetry axis along body z and Semi-axes[0] = Semi-axes[1]); "
                      "Biconcave is the Evans-Fung red cell with disc radius Radius.");
  core::declareReal(cell, "Radius", 1.0,
                    "Sphere radius, or the disc radius R0 of a biconcave cell (lengths are in units "
                    "of the cell radius a of the capillary number).",
                    core::greaterThan(0.0));
  core::declareRealArray(cell, "Semi-axes", {1.0, 1.0, 1.0}, 3,
                         "Semi-axes (a, b, c) along body x, y, z for Spheroid and Ellipsoid.", core::greaterThan(0.0));
  core::declareRealArray(cell, "Center", {center[0], center[1], center[2]}, 3, "Centre of the cell in the lab frame.");
  core::declareRealArray(cell, "Orientation axis", {0.0, 0.0, 1.0}, 3,
                         "Axis of the rotation from body to lab frame (any nonzero length).");
  core::declareReal(cell, "Orientation angle", 0.0,
                    "Angle in degrees of the rotation about Orientation axis (right-handed).");
  core::declareInt(cell, "Mesh level", 2,
                   "Icosahedron subdivision level n: N_E = 20 * 4^n elements, N_P = 2 N_E + 2 nodes "
                   "(thesis Table 3.1).",
                   0, 5);
}

SurfaceMesh buildCellSurface(const Teuchos::ParameterList& cell, const std::string& path)
{
  const auto& center = cell.get<Teuchos::Array<double>>("Center");
  const auto& axis = cell.get<Teuchos::Array<double>>("Orientation axis");
  const auto& semi = cell.get<Teuchos::Array<double>>("Semi-axes");
  const Vec3 axisVector(axis[0], axis[1], axis[2]);
  core::require<core::InputError>(axisVector.norm() > 0.0, "'", path,
                                  "/Orientation axis' is the zero vector; give a direction such as {0, 0, 1}.");
  Placement placement;
  placement.centre = Vec3(center[0], center[1], center[2]);
  const double angle = cell.get<double>("Orientation angle") * M_PI / 180.0;
  placement.rotation = rotationAboutAxis(axisVector, angle);

  const int level = cell.get<int>("Mesh level");
  const std::string& shape = cell.get<std::string>("Shape");
  if (shape == "Sphere") {
    return makeSphere(level, cell.get<double>("Radius"), placement);
  }
  if (shape == "Ellipsoid") {
    return makeEllipsoid(level, Vec3(semi[0], semi[1], semi[2]), placement);
  }
  if (shape == "Spheroid") {
    core::require<core::InputError>(semi[0] == semi[1], "'", path, "/Semi-axes' = {", semi[0], ", ", semi[1], ", ",
                                    semi[2],
                                    "}: a Spheroid needs equal first two semi-axes (equatorial); "
                                    "use Shape = Ellipsoid for three different semi-axes.");
    return makeSpheroid(level, semi[0], semi[2], placement);
  }
  BiconcaveProfile profile;
  profile.radius = cell.get<double>("Radius");
  return makeBiconcaveCell(level, profile, placement);
}

} // namespace capsula::mesh
