#include "capsula/scene/ExternalLoadStiffness.hpp"

#include "capsula/scene/ExternalForces.hpp"

#include <capsula/adhesion/ContactRepulsion.hpp>

namespace capsula::scene {

bool hasExternalLoadStiffness(const Scene& scene)
{
  const SceneDescription& description = scene.description();
  return scene.hasBonds() || scene.hasTether() || (description.contact.enabled && description.domain.hasWalls());
}

void externalLoadStiffness(const Scene& scene, int c, const double* positions, adhesion::LoadStiffness& stiffness)
{
  stiffness.clear();
  const mesh::SurfaceMesh& cell = scene.cell(c);
  if (scene.hasBonds()) {
    scene.bonds().bonds(c).addStiffness(cell, scene.bonds().receptors(c), positions, stiffness);
  }
  if (scene.hasTether() && scene.tether().cell() == c) {
    scene.tether().addStiffness(cell, positions, stiffness);
  }
  const SceneDescription& description = scene.description();
  if (description.contact.enabled) {
    for (const adhesion::ContactWall& wall : contactWalls(description.domain)) {
      adhesion::addWallContactStiffness(description.contact, cell, positions, stiffness, wall);
    }
  }
}

} // namespace capsula::scene
