#pragma once
// What a validated deck asks for, in plain values (SceneParameters.hpp lists the keys).
// Reading it checks what the validators cannot see alone: cells numbered 0..N-1 without
// gaps, flow probes given as whole points, outputs that need the wall.
#include <capsula/mesh/AdaptionParameters.hpp>
#include <capsula/mesh/RedistributionParameters.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace capsula::scene {

struct CellDescription {
  std::string path;                  ///< "Cells/Cell 0", for messages
  Teuchos::ParameterList surface;    ///< the cell's sublist (mesh::buildCellSurface reads it)
  std::string membraneLaw;           ///< "NeoHookean" or "Skalak"
  std::string membraneForces;        ///< "Virtual work" or "Contour integral"
  double shearModulus = 1.0;         ///< relative to the G of the capillary number
  double areaDilation = 0.0;         ///< C (Skalak)
  double prestress = 0.0;            ///< alpha (eq 3.45)
  bool fixedHeight = false;
  int meshLevel = 0;
};

struct WallShearStressOutput {
  bool enabled = false;
  double upstream = 0.0, downstream = 0.0, halfWidth = 0.0, spacing = 1.0;
  double threshold = 1.05;
  bool isolatedRange = false;        ///< 'Isolated range' given: compare with it
  double isolatedMinimum = 0.0, isolatedMaximum = 0.0;
};

struct OutputDescription {
  std::string directory;
  double interval = 0.0;
  bool snapshots = true;
  int snapshotStride = 1;
  bool checkpoint = true;
  int progressSteps = 20;
  std::vector<mesh::Vec3> flowProbes;
  WallShearStressOutput wallShearStress;
  double minimumAngle = 5.0;         ///< 'Output/Stability/Minimum angle', degrees (0: no bound)
};

struct SceneDescription {
  double capillaryNumber = 1.0;
  double viscosityRatio = 1.0;
  bool wall = true;
  std::vector<CellDescription> cells;
  double minimumGap = 0.05;          ///< 'Cells/Minimum gap': closer surfaces stop the run
  mesh::RedistributionSettings meshRegularisation;   ///< 'Mesh regularisation'
  mesh::AdaptionSettings meshAdaption;               ///< 'Mesh adaption'
  OutputDescription output;

  int numCells() const { return static_cast<int>(cells.size()); }
  bool anyFixedHeight() const;
};

/// Reads a validated scene deck. Throws core::InputError naming the key for the
/// inconsistencies listed above.
SceneDescription describeScene(const Teuchos::ParameterList& deck);

} // namespace capsula::scene
