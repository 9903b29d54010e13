#pragma once
// The domain of a scene's membranes: a state where some element of a membrane is folded
// against its neighbours (elasticity::MembraneMechanics::requireUnfolded) has no membrane
// load, so it is outside the model.
//
// requireUnfoldedMembranes is part of the 3D runs' domain check (timeint
// TimeIntegrator::setDomainCheck), next to requireNodesAboveWall: the result of a step too
// large for the membrane's fastest mode can fold it although smaller steps do not, and
// accepting it would end the run at the next right-hand side. The attempt is rejected and
// retried with half the step; the run fails only when the step falls below
// 'Time integration/Minimum step'.
#include "capsula/scene/Scene.hpp"

#include <vector>

namespace capsula::scene {

/// Throws timeint::StateOutsideDomain naming the cell, the node and the element where
/// `positions` (3 per node, the scene's numbering) fold a membrane.
void requireUnfoldedMembranes(const Scene& scene, const std::vector<double>& positions);

} // namespace capsula::scene
