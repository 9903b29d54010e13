#pragma once
// The scene of a run: the Scene the time integration moves, rebuilt when a mesh adaption
// changes the meshes, and what changes it between steps:
//
//   after every step   Mesh regularisation: the cells whose mesh has degraded below 'Mesh
//                      regularisation/Minimum angle' get their nodes redistributed
//                      (Scene::regulariseMeshes); the state jumps, so a first-same-as-last
//                      slope no longer belongs to it.
//   every 'Mesh adaption/Check interval' accepted steps
//                      Mesh adaption: the cells whose shape curves more than their elements
//                      resolve are refined (Scene::adaptedCells) and the run goes on with a
//                      scene built on the refined meshes (new operators and maps).
//   after every accepted step
//                      Adhesion: the bonds form and break over the step just taken
//                      (Scene::updateBonds, Monte Carlo or mean field, keyed by the step's
//                      number); the right-hand side changes with them, so a
//                      first-same-as-last slope no longer belongs to the state.
//
// Each event is a line in the log. Its checkpoint section holds what the deck alone cannot
// rebuild: GMRES's warm start (the next solve's start), and after regularisations or
// adaptions the reference shapes, the meshes' connectivity and the event counts:
//   scene.gmresWarmStart.rhs, scene.gmresWarmStart.solutions, scene.reference.<c>,
//   scene.connectivity.<c>, scene.regularisations, scene.adaptions; with adhesion the bond
//   states, occupancy and anchor per receptor, scene.bonds.<c>; and a tabulated shear
// rate's samples, flow.shearRate.waveform, so that a restart whose waveform file changed is
// refused.
// Loading it rebuilds the scene on the checkpoint's meshes, at the positions of the
// integration state (loaded before it).
#include <capsula/io/CheckpointSection.hpp>
#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/scene/Scene.hpp>
#include <capsula/scene/SceneDescription.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>

#include <cstdint>
#include <iosfwd>
#include <memory>

namespace capsula::run {

class RunScene final : public timeint::IntegrationObserver, public io::CheckpointSection {
public:
  /// `state` is the integration state whose positions a checkpoint's meshes carry; `log`
  /// receives the event lines.
  RunScene(const scene::SceneDescription& description, const Teuchos::ParameterList& deck,
           Teuchos::RCP<const Teuchos::Comm<int>> comm, const operators::KernelRegistry& kernels,
           const timeint::IntegrationState& state, std::ostream& log);

  /// The scene the deck describes, unless load() built one from a checkpoint.
  void build();
  const Teuchos::ParameterList& deck() const { return deck_; }
  scene::Scene& scene() { return *scene_; }
  const scene::Scene& scene() const { return *scene_; }

  std::int64_t regularisations() const { return regularisations_; }
  std::int64_t adaptions() const { return adaptions_; }

  timeint::ObserverVerdict afterStep(timeint::IntegrationState& state, const timeint::StepReport& report,
                                     bool atOutputTime) override;

  void save(io::Checkpoint& checkpoint) const override;
  void load(const io::Checkpoint& checkpoint, const std::string& source) override;

private:
  void regulariseMeshes(timeint::IntegrationState& state);
  void adaptMeshes(timeint::IntegrationState& state);
  void updateBonds(timeint::IntegrationState& state, double step);
  std::unique_ptr<scene::Scene> restoredScene(const io::Checkpoint& checkpoint, const std::string& source) const;

  const scene::SceneDescription& description_;
  const Teuchos::ParameterList& deck_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  const operators::KernelRegistry& kernels_;
  const timeint::IntegrationState& state_;
  std::ostream& log_;
  std::unique_ptr<scene::Scene> scene_;
  std::int64_t regularisations_ = 0; // node redistributions of a cell, over the whole run
  std::int64_t adaptions_ = 0;       // mesh refinements of a cell, over the whole run
};

} // namespace capsula::run
