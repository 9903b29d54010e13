#pragma once
// The domain of a scene with walls: every node strictly inside the fluid (above y = 0, and
// below y = H in a channel; domain/Domain.hpp). The wall kernels meet their own images there, and the contact repulsion diverges as a node approaches it, so a state with a
// node on or below the wall is outside the model.
//
// requireNodesAboveWall is the 3D runs' domain check (timeint TimeIntegrator::setDomainCheck):
// a stage state of a step too large for the fast motion near the wall (a node pulled down by
// its bonds, pushed back by the repulsion) puts a node through the wall although smaller
// steps stay above it, so the attempt is rejected and retried with half the step; the run
// fails only when the step falls below 'Time integration/Minimum step'.
#include "capsula/scene/Scene.hpp"

#include <vector>

namespace capsula::scene {

/// Throws timeint::StateOutsideDomain naming the first node (its cell, its index, its
/// height) of `positions` (3 per node, the scene's numbering) on or through a wall of the
/// scene's domain or with a non-finite height. Nothing to check without a wall.
void requireNodesAboveWall(const Scene& scene, const std::vector<double>& positions);

} // namespace capsula::scene
