#include "capsula/suspension/HematocritProfile.hpp"

#include "capsula/suspension/SlabVolumes.hpp"

#include <capsula/core/Error.hpp>

namespace capsula::suspension {

namespace {

void requirePeriodicChannel(const domain::Domain& domain, const char* what)
{
  core::require<core::InputError>(domain.hasUpperWall() && domain.isPeriodic(domain::flowAxis) &&
                                      domain.isPeriodic(domain::vorticityAxis),
                                  "The ", what,
                                  " is measured in a channel periodic along x and z ('Wall/Channel "
                                  "height', 'Domain/Periodic length x' and 'z' all > 0), not in ",
                                  domain.describe(), ".");
}

} // namespace

HematocritProfile hematocritProfile(const std::vector<const mesh::SurfaceMesh*>& cells, const domain::Domain& domain,
                                    int numSlabs)
{
  requirePeriodicChannel(domain, "hematocrit profile");
  core::require<core::InputError>(numSlabs >= 1, "The hematocrit profile needs at least one slab, not ", numSlabs, ".");
  const double height = domain.channelHeight();
  const double area = domain.period(domain::flowAxis) * domain.period(domain::vorticityAxis);
  HematocritProfile profile;
  for (int k = 0; k <= numSlabs; ++k) {
    profile.heights.push_back(height * k / numSlabs);
  }
  profile.fraction.assign(static_cast<std::size_t>(numSlabs), 0.0);
  double total = 0.0;
  for (const mesh::SurfaceMesh* cell : cells) {
    const std::vector<double> volumes = volumesBetweenHeights(*cell, profile.heights);
    for (std::size_t k = 0; k < volumes.size(); ++k) {
      profile.fraction[k] += volumes[k];
      total += volumes[k];
    }
  }
  const double slab = area * height / numSlabs;
  for (double& f : profile.fraction) {
    f /= slab;
  }
  profile.mean = total / (area * height);
  return profile;
}

} // namespace capsula::suspension
