#include "capsula/run/RunScene.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/Timers.hpp>

#include <iomanip>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace capsula::run {

namespace core = capsula::core;
using scene::Scene;

RunScene::RunScene(const scene::SceneDescription& description, const Teuchos::ParameterList& deck,
                   Teuchos::RCP<const Teuchos::Comm<int>> comm, const operators::KernelRegistry& kernels,
                   const timeint::IntegrationState& state, std::ostream& log)
    : description_(description), deck_(deck), comm_(std::move(comm)), kernels_(kernels), state_(state), log_(log)
{}

void RunScene::build()
{
  if (!scene_) {
    scene_ = std::make_unique<Scene>(description_, deck_, comm_, kernels_);
  }
}

timeint::ObserverVerdict RunScene::afterStep(timeint::IntegrationState& state, const timeint::StepReport& report, bool)
{
  regulariseMeshes(state);
  adaptMeshes(state);
  updateBonds(state, report.stepSize);
  scene_->startStep();
  return timeint::ObserverVerdict::Continue;
}

void RunScene::updateBonds(timeint::IntegrationState& state, double step)
{
  if (!scene_->hasBonds()) {
    return;
  }
  {
    Teuchos::TimeMonitor guard(*core::timer("Bond kinetics"));
    // Numbered by the accepted steps so far: the same number after a restart.
    scene_->updateBonds(state.y, step, static_cast<std::uint64_t>(state.statistics.acceptedSteps));
  }
  // The positions did not move, so the stability limit still holds (it is estimated again
  // every 'Stability interval' steps anyway); only the slope of the old bond set is stale.
  state.firstStageDerivative.clear();
}

void RunScene::regulariseMeshes(timeint::IntegrationState& state)
{
  if (!scene_->regularisesMeshes()) {
    return;
  }
  std::vector<scene::MeshRegularisation> done;
  {
    Teuchos::TimeMonitor guard(*core::timer("Mesh regularisation"));
    done = scene_->regulariseMeshes(state.time, state.y);
  }
  if (done.empty()) {
    return;
  }
  timeint::stateChangedOutside(state); // new slopes, and the stability limit again
  for (const auto& event : done) {
    ++regularisations_;
    log_ << std::setprecision(5) << "t = " << state.time << ": redistributed the nodes of '"
         << description_.cells[static_cast<std::size_t>(event.cell)].path << "' (smallest angle "
         << event.minAngleBefore << " -> " << event.minAngleAfter << " degrees, reference " << event.referenceMinAngle
         << ", " << event.passes << " passes, largest move " << event.maxDisplacement << ", volume offset "
         << event.volumeOffset << ")\n";
  }
}

void RunScene::adaptMeshes(timeint::IntegrationState& state)
{
  if (!scene_->adaptsMeshes() || state.statistics.acceptedSteps % description_.meshAdaption.checkInterval != 0) {
    return;
  }
  Teuchos::TimeMonitor guard(*core::timer("Mesh adaption"));
  std::optional<scene::AdaptedCells> adapted = scene_->adaptedCells(state.y);
  if (!adapted) {
    return;
  }
  std::vector<int> before;
  for (int c = 0; c < scene_->numCells(); ++c) {
    before.push_back(scene_->cell(c).numElements());
  }
  const std::vector<int> marked = adapted->markedElements;
  scene_ = std::make_unique<Scene>(description_, deck_, comm_, kernels_, std::move(adapted->cells),
                                   std::move(adapted->references));
  state.y = scene_->initialPositions();
  timeint::stateChangedOutside(state);
  for (int c = 0; c < scene_->numCells(); ++c) {
    const auto k = static_cast<std::size_t>(c);
    if (marked[k] == 0) {
      continue;
    }
    ++adaptions_;
    log_ << "t = " << state.time << ": refined the mesh of '" << description_.cells[k].path << "' (" << marked[k]
         << " elements over the curvature threshold; " << before[k] << " -> " << scene_->cell(c).numElements()
         << " elements, " << scene_->cell(c).numNodes() << " nodes)\n";
  }
}

void RunScene::save(io::Checkpoint& checkpoint) const
{
  if (auto waveform = description_.shearRate.waveformSamples(); !waveform.empty()) {
    checkpoint.arrays["flow.shearRate.waveform"] = std::move(waveform);
  }
  if (const auto* warm = scene_->gmresWarmStart(); warm && !warm->empty()) { // the next solve's start
    checkpoint.arrays["scene.gmresWarmStart.rhs"] = warm->rightHandSides();
    checkpoint.arrays["scene.gmresWarmStart.solutions"] = warm->solutions();
  }
  if (scene_->hasBonds()) { // which receptor is bound, and where its ligand is
    for (int c = 0; c < scene_->numCells(); ++c) {
      checkpoint.arrays["scene.bonds." + std::to_string(c)] = scene_->bonds().states(c);
    }
  }
  if (!scene_->regularisesMeshes() && !scene_->adaptsMeshes()) {
    return;
  }
  // The material points moved with the nodes, and with adaption the topology may have changed.
  checkpoint.integers["scene.regularisations"] = regularisations_;
  checkpoint.integers["scene.adaptions"] = adaptions_;
  for (int c = 0; c < scene_->numCells(); ++c) {
    checkpoint.arrays["scene.reference." + std::to_string(c)] = scene_->referencePositions(c);
    if (scene_->adaptsMeshes()) {
      std::vector<double> connectivity;
      for (const auto& element : scene_->cell(c).elements()) {
        connectivity.insert(connectivity.end(), element.begin(), element.end());
      }
      checkpoint.arrays["scene.connectivity." + std::to_string(c)] = std::move(connectivity);
    }
  }
}

void RunScene::load(const io::Checkpoint& checkpoint, const std::string& source)
{
  const auto* waveform = io::optionalArray(checkpoint, "flow.shearRate.waveform");
  core::require<core::InputError>(waveform ? *waveform == description_.shearRate.waveformSamples()
                                           : description_.shearRate.waveformSamples().empty(),
                                  "The checkpoint ", source,
                                  " was written with another waveform than 'Flow/Shear rate/Waveform file' holds "
                                  "now: restart with the run's waveform file.");
  scene_ = restoredScene(checkpoint, source);
  const auto* rhs = io::optionalArray(checkpoint, "scene.gmresWarmStart.rhs");
  const auto* solutions = io::optionalArray(checkpoint, "scene.gmresWarmStart.solutions");
  if (rhs && solutions) { // lambda != 1: the next solve starts where the interrupted run's would
    scene_->restoreGmresWarmStart(*rhs, *solutions);
  }
  if (scene_->hasBonds()) {
    for (int c = 0; c < scene_->numCells(); ++c) {
      const std::string name = "scene.bonds." + std::to_string(c);
      const auto* states = io::optionalArray(checkpoint, name);
      core::require<core::InputError>(states != nullptr, "The checkpoint '", source, "' lacks '", name,
                                      "': it was written without 'Adhesion'.");
      scene_->bonds().restoreStates(c, *states, source);
    }
  }
  const auto count = [&](const char* name) {
    const auto it = checkpoint.integers.find(name);
    return it == checkpoint.integers.end() ? std::int64_t{0} : it->second;
  };
  regularisations_ = count("scene.regularisations");
  adaptions_ = count("scene.adaptions");
}

// The deck's scene, or, where redistributions or adaptions changed the cells, their meshes
// (connectivity from the checkpoint, positions from its state) and reference shapes.
std::unique_ptr<Scene> RunScene::restoredScene(const io::Checkpoint& checkpoint, const std::string& source) const
{
  const int n = description_.numCells();
  if (!io::optionalArray(checkpoint, "scene.connectivity.0")) {
    auto scene = std::make_unique<Scene>(description_, deck_, comm_, kernels_);
    for (int c = 0; c < n; ++c) {
      if (const auto* reference = io::optionalArray(checkpoint, "scene.reference." + std::to_string(c))) {
        scene->setReferencePositions(c, *reference);
      }
    }
    return scene;
  }
  std::vector<mesh::SurfaceMesh> cells;
  std::vector<std::vector<double>> references;
  std::size_t offset = 0;
  for (int c = 0; c < n; ++c) {
    const std::string suffix = std::to_string(c);
    const auto* connectivity = io::optionalArray(checkpoint, "scene.connectivity." + suffix);
    const auto* reference = io::optionalArray(checkpoint, "scene.reference." + suffix);
    core::require<core::InputError>(connectivity && reference, "The checkpoint '", source,
                                    "' lacks the adapted mesh of cell ", c, ": it is incomplete.");
    std::vector<mesh::ElementConnectivity> elements(connectivity->size() / 6);
    for (std::size_t k = 0; k < connectivity->size(); ++k) {
      elements[k / 6][k % 6] = static_cast<int>((*connectivity)[k]);
    }
    const std::size_t values = reference->size();
    core::require<core::InputError>(offset + values <= state_.y.size(), "The checkpoint '", source,
                                    "' is inconsistent: its state is too short for its meshes.");
    std::vector<double> positions(state_.y.begin() + static_cast<std::ptrdiff_t>(offset),
                                  state_.y.begin() + static_cast<std::ptrdiff_t>(offset + values));
    offset += values;
    cells.emplace_back(std::move(positions), std::move(elements));
    references.push_back(*reference);
  }
  return std::make_unique<Scene>(description_, deck_, comm_, kernels_, std::move(cells), std::move(references));
}

} // namespace capsula::run
