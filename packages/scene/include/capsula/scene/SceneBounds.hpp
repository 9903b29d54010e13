#pragma once
// Upper bounds that the scene's own sizes set on deck values. A value beyond one makes no
// physical or numerical sense in this scene (a repulsion reaching across the cell, bending
// loads beyond the range of doubles, a step error as large as the cell), and is refused at
// start-up with core::InputError naming the key, its value and the bound.
#include "capsula/scene/SceneDescription.hpp"

#include <capsula/mesh/SurfaceMesh.hpp>

#include <string>
#include <vector>

namespace capsula::scene {

/// The smallest semi-axis of each cell's equivalent ellipsoid (in cell radii): a sphere's
/// radius, a red cell's half thickness.
std::vector<double> smallestSemiAxes(const std::vector<mesh::SurfaceMesh>& cells);

/// 'Contact/Range' (with contact enabled) below every cell's smallest semi-axis: a wider
/// repulsion acts across the cell, on the membrane facing away from the wall or the other
/// cell too, and folds it.
void requireContactRangeWithinCells(const SceneDescription& description, const std::vector<double>& semiAxes);

/// Each cell's bending within elasticity::kBendingLoadScaleBound, the curvature of its shape
/// taken as 1 / its smallest semi-axis (elasticity/BendingLoadBound.hpp).
void requireRepresentableBending(const SceneDescription& description, const std::vector<double>& semiAxes);

/// Both checks above, on the cells as the deck builds them (the state at t = 0).
void requireSceneWithinBounds(const SceneDescription& description, const std::vector<mesh::SurfaceMesh>& cells);

/// The largest 'Time integration/Tolerance' for the cells: kToleranceFraction of the smallest
/// semi-axis of any cell. The tolerance is the error a step may make in the node positions,
/// in cell radii; one of order the cell accepts steps whose error is the deformation itself
/// (D12 34% low at t = 0.1 with Tolerance 2, ROS34PW2, level 1).
constexpr double kToleranceFraction = 0.01;
void requireToleranceBelowCellSize(double tolerance, const std::string& key, const SceneDescription& description,
                                   const std::vector<double>& semiAxes);

} // namespace capsula::scene
