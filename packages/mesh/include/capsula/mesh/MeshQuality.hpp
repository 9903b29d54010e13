#pragma once
// Element shape measures, to watch a mesh deform (and to decide where to adapt it).
#include <capsula/mesh/SurfaceMesh.hpp>

namespace capsula::mesh {

/// Shape of one element. Angles and edge lengths are those of the flat triangle of
/// its three vertices; distortion measures how far the midside nodes sit from the
/// middle of their edges: max(|alpha - 1/2|, |beta - 1/2|, |gamma - 1/2|) (eq 3.17).
struct ElementQuality {
  double minAngle;   ///< degrees
  double maxAngle;   ///< degrees
  double edgeRatio;  ///< longest / shortest vertex-to-vertex edge, >= 1
  double distortion; ///< 0 for midside nodes at the edge middles, -> 1/2 when degenerate
};

ElementQuality elementQuality(const SurfaceMesh& mesh, int element);

/// Extremes over all elements.
struct MeshQuality {
  double minAngle; ///< degrees
  double maxAngle; ///< degrees
  double maxEdgeRatio;
  double maxDistortion;
};

MeshQuality meshQuality(const SurfaceMesh& mesh);

} // namespace capsula::mesh
