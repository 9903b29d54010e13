#include "capsula/scene/ExternalLoadStiffness.hpp"

#include <capsula/adhesion/ContactRepulsion.hpp>

namespace capsula::scene {

bool hasExternalLoadStiffness(const Scene& scene)
{
  const SceneDescription& description = scene.description();
  return scene.hasBonds() || scene.hasTether() || (description.contact.enabled && description.wall);
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
  if (description.contact.enabled && description.wall) {
    adhesion::addWallContactStiffness(description.contact, cell, positions, stiffness);
  }
}

} // namespace capsula::scene
