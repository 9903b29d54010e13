#include "capsula/adhesion/TetherParameters.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>

#include <Teuchos_Array.hpp>

#include <cmath>

namespace capsula::adhesion {

namespace core = capsula::core;

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

void require(bool condition, const std::string& path, const std::string& key, const std::string& why)
{
  core::require<core::InputError>(condition, "'", path, "/", key, "' ", why);
}

std::string listed(const Teuchos::Array<double>& values)
{
  std::string text;
  for (const double v : values) {
    text += (text.empty() ? "" : ", ") + core::message(v);
  }
  return "{" + text + "}";
}

void declarePlacement(Teuchos::ParameterList& list)
{
  core::declareInt(list, "Cell", 0, "The tethered cell: 'Cells/Cell <this>'.", 0);
  core::declareReal(list, "Polar angle", 0.0,
                    "Where the tether holds the membrane: the material point of the cell at t = 0 that lies "
                    "farthest along the direction at this angle (degrees) from the downward vertical -y, i.e. "
                    "where the outward normal points that way on a sphere or ellipsoid. 0: the lowest point; "
                    "90 with 'Azimuth' = 180: the upstream equator.",
                    core::atLeast(0.0), core::atMost(180.0));
  core::declareReal(list, "Azimuth", 0.0,
                    "The direction of that tilt in the wall plane, in degrees from the flow direction +x "
                    "towards +z (0: downstream, 180: upstream). No effect at 'Polar angle' = 0.",
                    core::atLeast(-360.0), core::atMost(360.0));
  core::declareRealArray(list, "Anchor", {}, 0,
                         "The tether's fixed end on the wall: {x, y, z} with y = 0, in cell radii, or {} "
                         "(default) for the point of the wall directly below the attachment point at t = 0.");
  core::declareReal(list, "Patch radius", 0.0,
                    "rho / a: the tether's foot on the membrane. 0: one material point (a point force, "
                    "spread onto its element's six nodes). > 0: the force is shared by the membrane's "
                    "quadrature points within rho of the attachment point at t = 0 with the weights of a "
                    "smooth bump (1 - r^2/rho^2)^2 dA, and the spring pulls at their weighted mean, so that "
                    "force and torque are those of the spring at that point. A membrane tether 2 um wide "
                    "on a 6 um leukocyte radius is rho ~ 0.17 (Ramachandran et al., PNAS 101:13519, 2004).",
                    core::atLeast(0.0));
}

void declareSpring(Teuchos::ParameterList& list)
{
  core::declareReal(list, "Spring constant", 100.0,
                    "sigma / G: the tether's spring constant over the membrane shear modulus (a tether of "
                    "length L pulls with |F| = sigma |L - lambda|, in units of G a). It never breaks. The "
                    "default, 100, stretches it by 0.01 a under a force of G a: nearly inextensible for the "
                    "forces of Ca <= 0.1. Must be > 0 with the tether enabled.",
                    core::atLeast(0.0));
  core::declareRealArray(list, "Rest length", {}, 0,
                         "lambda / a: the unstressed length of the tether, {lambda} with lambda >= 0, or {} "
                         "(default) for its length at t = 0, so that it starts unstressed.",
                         core::atLeast(0.0));
}

} // namespace

mesh::Vec3 TetherSettings::direction() const
{
  const double theta = polarAngle * kDegree, phi = azimuth * kDegree;
  return mesh::Vec3(std::sin(theta) * std::cos(phi), -std::cos(theta), std::sin(theta) * std::sin(phi));
}

void declareTetherParameters(Teuchos::ParameterList& tether)
{
  core::declareBool(tether, "Enabled", false,
                    "One permanent bond, a linear spring that never breaks, from a material point of one "
                    "cell's membrane to a fixed anchor on the wall y = 0 (the 3D counterpart of the tethered "
                    "2D cell, thesis Chapter 4). Lengths in cell radii a, the spring constant in G, forces "
                    "in G a. Needs the wall and 'Membrane forces' = 'Virtual work'.");
  declarePlacement(tether);
  declareSpring(tether);
}

TetherSettings readTetherParameters(const Teuchos::ParameterList& tether, const std::string& path)
{
  TetherSettings s;
  s.enabled = tether.get<bool>("Enabled");
  s.cell = tether.get<int>("Cell");
  s.polarAngle = tether.get<double>("Polar angle");
  s.azimuth = tether.get<double>("Azimuth");
  s.springConstant = tether.get<double>("Spring constant");
  s.patchRadius = tether.get<double>("Patch radius");
  // The validators check these too; a list built in code has not been through them.
  require(s.cell >= 0, path, "Cell", core::message("= ", s.cell, " is negative: give a cell index >= 0."));
  require(s.polarAngle >= 0.0 && s.polarAngle <= 180.0, path, "Polar angle",
          core::message("= ", s.polarAngle, " is outside [0, 180] degrees."));
  require(std::isfinite(s.azimuth), path, "Azimuth", "is not a finite number.");
  require(s.springConstant >= 0.0 && std::isfinite(s.springConstant), path, "Spring constant",
          core::message("= ", s.springConstant, " is invalid: give a finite spring constant > 0."));
  require(s.patchRadius >= 0.0 && std::isfinite(s.patchRadius), path, "Patch radius",
          core::message("= ", s.patchRadius, " is invalid: give 0 (a point) or a finite radius > 0."));

  const auto& rest = tether.get<Teuchos::Array<double>>("Rest length");
  require(rest.size() <= 1, path, "Rest length",
          core::message("= ", listed(rest), " has ", rest.size(),
                        " entries: give one length {lambda}, or {} for the length at t = 0."));
  if (rest.size() == 1) {
    require(rest[0] >= 0.0 && std::isfinite(rest[0]), path, "Rest length",
            core::message("= ", listed(rest), " is invalid: give a finite length >= 0."));
    s.restLength = rest[0];
  }
  const auto& anchor = tether.get<Teuchos::Array<double>>("Anchor");
  require(anchor.empty() || anchor.size() == 3, path, "Anchor",
          core::message("= ", listed(anchor), " has ", anchor.size(),
                        " entries: give a point {x, y, z} of the wall, or {} for the point below the attachment."));
  if (anchor.size() == 3) {
    for (const double v : anchor) {
      require(std::isfinite(v), path, "Anchor",
              core::message("= ", listed(anchor), " has an entry that is not finite."));
    }
    require(anchor[1] == 0.0, path, "Anchor",
            core::message("= ", listed(anchor),
                          " lies off the wall y = 0: give y = 0 (the anchor is a point of the wall)."));
    s.anchor = mesh::Vec3(anchor[0], anchor[1], anchor[2]);
  }
  if (s.enabled) {
    require(
        s.springConstant > 0.0, path, "Spring constant",
        core::message("= ", s.springConstant,
                      " with the tether enabled: a tether needs a spring constant > 0 (or set 'Enabled' = false)."));
  }
  return s;
}

} // namespace capsula::adhesion
