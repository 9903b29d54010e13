#pragma once
// What a scene run writes, where and when: the "Output" sublist of the cell3d and twocell3d
// decks (Directory, Interval, Snapshots, Snapshot stride, Checkpoint, Progress steps, Flow
// probes, Wall shear stress/, Stability/, Suspension/), declared and read here, by the run that uses it.
// Reading checks what the validators cannot see alone: flow probes given as whole points in
// the fluid, a wall stress map that needs the wall, a mesh regularisation that triggers
// before the stability bound stops the run.
#include <capsula/mesh/Vec3.hpp>
#include <capsula/run/SuspensionOutput.hpp>
#include <capsula/scene/SceneDescription.hpp>

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace capsula::run {

struct WallShearStressOutput {
  bool enabled = false;
  double upstream = 0.0, downstream = 0.0, halfWidth = 0.0, spacing = 1.0;
  double threshold = 1.05;
  bool isolatedRange = false; ///< 'Isolated range' given: compare with it
  double isolatedMinimum = 0.0, isolatedMaximum = 0.0;
};

struct SceneOutputSettings {
  std::string directory;
  double interval = 0.0;
  bool snapshots = true;
  int snapshotStride = 1;
  bool foldIntoBox = false; ///< 'Output/Fold into box': cells drawn in the periodic box
  bool checkpoint = true;
  int progressSteps = 20;
  std::vector<mesh::Vec3> flowProbes;
  WallShearStressOutput wallShearStress;
  double minimumAngle = 5.0; ///< 'Output/Stability/Minimum angle', degrees (0: no bound)
  SuspensionOutputSettings suspension;
};

/// Declares the "Output" sublist.
void declareSceneOutputParameters(Teuchos::ParameterList& output);

/// Reads the "Output" sublist of a validated deck describing `scene`. Throws
/// core::InputError naming the key for the inconsistencies listed above.
SceneOutputSettings readSceneOutputSettings(const Teuchos::ParameterList& deck, const scene::SceneDescription& scene);

} // namespace capsula::run
