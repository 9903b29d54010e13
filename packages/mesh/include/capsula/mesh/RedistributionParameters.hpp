#pragma once
// The deck's "Mesh regularisation" sublist: when and how a running cell's nodes are
// redistributed along its surface (NodeRedistribution.hpp). Declared here because the
// mesh package reads it; the scene puts the sublist at the top of its decks.
#include <capsula/mesh/NodeRedistribution.hpp>

#include <Teuchos_ParameterList.hpp>

namespace capsula::mesh {

struct RedistributionSettings {
  bool enabled = false;
  /// Redistribute a cell's nodes after a step that leaves an element angle below this
  /// many degrees.
  double triggerAngle = 25.0;
  RedistributionOptions options;
};

/// Declares Enabled, Minimum angle, Passes, Relaxation and Preserve volume.
void declareRedistributionParameters(Teuchos::ParameterList& list);

/// Reads a validated sublist.
RedistributionSettings readRedistributionParameters(const Teuchos::ParameterList& list);

} // namespace capsula::mesh
