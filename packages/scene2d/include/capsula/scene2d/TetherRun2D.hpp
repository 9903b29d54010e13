#pragma once
// A run of the 2D tethered-cell study (thesis Chapter 4) from a validated deck: the
// preparation stage and the tethered stage (TetherStages2D.hpp), or the free stage alone,
// each a time loop of timeint::TimeIntegrator::integrate with the stages and the outputs
// (TetherOutputs2D.hpp) as observers, a model the run backbone drives (RunBackbone.hpp:
// restart checks, the checkpoint, summary.json, Auto's switches, interruption). Writes into
// the output directory:
//   preparation.csv, metrics.csv, preparation.h5, contour.h5 (+ .xdmf)   TetherOutputs2D.hpp
//   checkpoint.h5      every 'Output/Checkpoint every' outputs and at the end: everything
//                      needed to continue bit for bit (the sections of the integration
//                      state, the stages, the model and the outputs)
//   summary.json       RunSummary.hpp; the results: tethered, preparation time, final
//                      values, maxima
//   deck.xml, run.json the validated deck and the run record
// Restart: the deck must equal the checkpoint's except for 'Time integration/End time' and
// 'Output/Directory' (RestartDeck.hpp); a changed key is refused before anything is written.
#include "capsula/scene2d/CapsuleModel2D.hpp"
#include "capsula/scene2d/TetherOutputs2D.hpp"
#include "capsula/scene2d/TetherProcedure2D.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <iosfwd>
#include <optional>
#include <string>

namespace capsula::scene2d {

class TetherRun2D {
public:
  /// Builds the model from a validated deck (Tether2DDeck.hpp). `log` receives progress
  /// lines (may be null); `deckSource` names the deck file in run.json.
  TetherRun2D(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const Teuchos::ParameterList& deck, std::ostream* log,
              std::string deckSource = "");

  /// Runs to the end, writing into `outputDirectory` (empty: no files) on rank 0, or
  /// continues from `restartDirectory`/checkpoint.h5. Collective.
  TetherRunResult2D run(const std::string& outputDirectory, const std::optional<std::string>& restartDirectory);

  CapsuleModel2D& model() { return model_; }

private:
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  Teuchos::ParameterList deck_;
  std::ostream* log_;
  std::string deckSource_;
  TetherSettings2D tether_;
  OutputSettings2D output_;
  CapsuleModel2D model_;
};

} // namespace capsula::scene2d
