#include "capsula/adhesion/Tether.hpp"

#include "capsula/adhesion/BondSpring.hpp"
#include "capsula/adhesion/PointForces.hpp"
#include "capsula/adhesion/TetherPlacement.hpp"

#include <capsula/core/Error.hpp>

#include <cmath>
#include <map>
#include <sstream>

namespace capsula::adhesion {

namespace core = capsula::core;

namespace {

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

// The tether's material points: the farthest point along the settings' direction and the
// patch around it, on the shape at `positions`, in the parametrisation of `parametrisation`.
WeightedPoints placePoints(const TetherSettings& settings, const mesh::SurfaceMesh& cell, const double* positions,
                           const ReceptorSet& parametrisation, const std::string& path)
{
  const Receptor centre = farthestMaterialPoint(cell, positions, parametrisation, settings.direction());
  WeightedPoints patch = materialPatch(cell, positions, parametrisation, centre, settings.patchRadius);
  core::require<core::InputError>(
      settings.patchRadius == 0.0 || patch.points.size() >= 3, "'", path, "/Patch radius' = ", settings.patchRadius,
      " holds ", patch.points.size(), " quadrature point(s) of the mesh (", cell.numElements(),
      " elements): give 0 for a point tether, or a radius of about an element's size or more.");
  return patch;
}

} // namespace

Tether::Tether(const TetherSettings& settings, const mesh::SurfaceMesh& cell, const double* positions,
               const std::vector<double>& reference, const std::string& path)
    : settings_(settings), points_(cell, reference, std::vector<Receptor>{})
{
  WeightedPoints patch = placePoints(settings, cell, positions, points_, path);
  points_ = ReceptorSet(cell, reference, std::move(patch.points));
  weights_ = std::move(patch.weights);
  const mesh::Vec3 x = attachment(cell, positions);
  core::require<core::InputError>(x[1] > 0.0, "'", path, "': the attachment point (", x[0], ", ", x[1], ", ", x[2],
                                  ") lies on or below the wall y = 0.");
  anchor_ = settings.anchor ? *settings.anchor : mesh::Vec3(x[0], 0.0, x[2]);
  const double length = (x - anchor_).norm();
  restLength_ = settings.restLength ? *settings.restLength : length;
}

mesh::Vec3 Tether::attachment(const mesh::SurfaceMesh& cell, const double* positions) const
{
  mesh::Vec3 x = mesh::Vec3::Zero();
  for (int i = 0; i < points_.size(); ++i) {
    x += weights_[static_cast<std::size_t>(i)] * points_.position(cell, positions, i);
  }
  return x;
}

TetherState Tether::state(const mesh::SurfaceMesh& cell, const double* positions) const
{
  TetherState s;
  s.attachment = attachment(cell, positions);
  s.anchor = anchor_;
  s.force = springForce(s.attachment, anchor_, settings_.springConstant, restLength_);
  const mesh::Vec3 d = s.attachment - anchor_;
  s.length = d.norm();
  s.inclinationDegrees = std::atan2(d[1], std::hypot(d[0], d[2])) * kDegreesPerRadian;
  return s;
}

mesh::Vec3 Tether::addNodalForces(const mesh::SurfaceMesh& cell, const double* positions, double* nodalForces) const
{
  const mesh::Vec3 force = springForce(attachment(cell, positions), anchor_, settings_.springConstant, restLength_);
  for (int i = 0; i < points_.size(); ++i) {
    double phi[6];
    points_.shapeFunctions(i, phi);
    spreadPointForce(cell.element(points_[i].element), phi, weights_[static_cast<std::size_t>(i)] * force, nodalForces);
  }
  return force;
}

void Tether::addStiffness(const mesh::SurfaceMesh& cell, const double* positions, LoadStiffness& stiffness) const
{
  const mesh::Mat3 spring =
      springStiffness(attachment(cell, positions), anchor_, settings_.springConstant, restLength_);
  std::map<int, double> shares; // node -> c_k, the points of a patch share nodes
  for (int i = 0; i < points_.size(); ++i) {
    double phi[6];
    points_.shapeFunctions(i, phi);
    const auto& nodes = cell.element(points_[i].element);
    for (std::size_t a = 0; a < 6; ++a) {
      shares[nodes[a]] += weights_[static_cast<std::size_t>(i)] * phi[a];
    }
  }
  for (const auto& [k, ck] : shares) {
    for (const auto& [l, cl] : shares) {
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          stiffness.add(3 * k + i, 3 * l + j, ck * cl * spring(i, j));
        }
      }
    }
  }
}

std::string Tether::describe() const
{
  std::ostringstream line;
  line << "tether: Cells/Cell " << settings_.cell << " held at ";
  if (settings_.polarAngle == 0.0) {
    line << "its lowest point";
  } else {
    line << "polar angle " << settings_.polarAngle << ", azimuth " << settings_.azimuth << " degrees";
  }
  if (settings_.patchRadius > 0.0) {
    line << " (a patch of radius " << settings_.patchRadius << " a, " << points_.size() << " points)";
  }
  line << " to the anchor (" << anchor_[0] << ", " << anchor_[1] << ", " << anchor_[2] << ") by a spring of constant "
       << settings_.springConstant << " G and rest length " << restLength_ << " a; permanent";
  return line.str();
}

double pivotAngleDegrees(const mesh::Vec3& anchor, const mesh::Vec3& centroid)
{
  return std::atan2(centroid[1] - anchor[1], centroid[0] - anchor[0]) * kDegreesPerRadian;
}

} // namespace capsula::adhesion
