#pragma once
// The volume of a closed cell surface between heights y_k < y_{k+1} (the hematocrit
// profile across a channel is these volumes summed over the cells, HematocritProfile.hpp).
//
// By the divergence theorem with F = (x, 0, 0), the volume of the part of the cell below the
// plane y = c is the flux of F through the part of the surface below c: the plane's cut
// carries no flux, since F is parallel to it. On a flat triangle with area vector A, that flux
// is A_x / |A| times the integral of x over the triangle's part below c: a clipped polygon,
// exact by its centroid. So the volumes are exact for the flat-faceted surface
// (FlatFacets.hpp) and sum to its volume.
#include <capsula/mesh/SurfaceMesh.hpp>

#include <vector>

namespace capsula::suspension {

/// The volume of the part of the closed surface `surface` (at its own positions) below the
/// plane y = height.
double volumeBelow(const mesh::SurfaceMesh& surface, double height);

/// volumes[k] = the volume between heights[k] and heights[k + 1] (heights increasing).
std::vector<double> volumesBetweenHeights(const mesh::SurfaceMesh& surface, const std::vector<double>& heights);

} // namespace capsula::suspension
