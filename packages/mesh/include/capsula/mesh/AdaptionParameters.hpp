#pragma once
// The deck's "Mesh adaption" sublist: when a running cell's mesh is refined where its
// shape curves most (eq 4.3, Adaption.hpp). Declared here because the mesh package reads
// it; the scene puts the sublist at the top of its decks.
#include <capsula/mesh/Adaption.hpp>

#include <Teuchos_ParameterList.hpp>

namespace capsula::mesh {

struct AdaptionSettings {
  bool enabled = false;
  int checkInterval = 20; ///< accepted steps between two checks of Q_e
  int maxElements = 5120; ///< per cell; no refinement past it
  AdaptionOptions options;
};

/// Declares Enabled, Threshold, Curvature, Check interval and Maximum elements.
void declareAdaptionParameters(Teuchos::ParameterList& list);

/// Reads a validated sublist.
AdaptionSettings readAdaptionParameters(const Teuchos::ParameterList& list);

} // namespace capsula::mesh
