#pragma once
// The stiffness of the forces that act on a scene's membranes from outside (adhesion
// LoadStiffness.hpp), for the stiff Jacobian (VelocityJacobian.hpp): the bonds of the
// cell, as they are (they only change between steps), the tether, and the wall's repulsion.
//
// Left out: the repulsion between cells. Its force acts along the line from a node to the
// closest point of the other cell's facets, which jumps from facet to facet as the nodes
// move; two cells rarely press on each other long enough for it to hold the step.
#include "capsula/scene/Scene.hpp"

#include <capsula/adhesion/LoadStiffness.hpp>

namespace capsula::scene {

/// True if the scene has forces from outside whose stiffness externalLoadStiffness gives.
bool hasExternalLoadStiffness(const Scene& scene);

/// The stiffness -dF/dx of cell c's bond, tether and wall-contact nodal forces at `positions` (3
/// per node of cell c), the area shares of the contact frozen there. Replaces `stiffness`.
void externalLoadStiffness(const Scene& scene, int c, const double* positions, adhesion::LoadStiffness& stiffness);

} // namespace capsula::scene
