#include "capsula/scene/SceneBonds.hpp"

#include "capsula/scene/ReceptorBounds.hpp"

#include <capsula/core/Error.hpp>

#include <Teuchos_CommHelpers.hpp>

#include <sstream>

namespace capsula::scene {

namespace core = capsula::core;

SceneBonds::SceneBonds(const adhesion::AdhesionSettings& settings, const std::vector<mesh::SurfaceMesh>& cells,
                       const std::vector<std::vector<double>>& references)
    : settings_(settings)
{
  core::require(cells.size() == references.size(), "SceneBonds: ", references.size(), " reference shapes for ",
                cells.size(), " cells");
  requireReceptorsFit(settings_, cells, references);
  receptors_.reserve(cells.size());
  bonds_.reserve(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const auto stream = static_cast<std::uint64_t>(c);
    receptors_.emplace_back(cells[c], references[c], settings_.receptorDensity, settings_.seed, stream);
    if (settings_.patchRadius > 0.0) {
      receptors_.back().spreadOverPatches(cells[c], references[c], settings_.patchRadius, "Adhesion/Patch radius");
      requirePatchesWithinReach(settings_, receptors_.back(), cells[c], references[c]);
    }
    bonds_.emplace_back(settings_, stream, receptors_.back().size());
  }
}

double SceneBonds::bondCount() const
{
  double count = 0.0;
  for (const auto& bonds : bonds_) {
    count += bonds.bondCount();
  }
  return count;
}

mesh::Vec3 SceneBonds::addNodalForces(int c, const mesh::SurfaceMesh& cell, const double* positions,
                                      double* nodalForces) const
{
  return bonds(c).addNodalForces(cell, receptors(c), positions, nodalForces);
}

adhesion::BondEvents SceneBonds::update(int c, const mesh::SurfaceMesh& cell, const double* positions, double dt,
                                        std::uint64_t step, const Teuchos::Comm<int>& comm)
{
  adhesion::BondPopulation& population = bonds(c);
  const adhesion::ReceptorRange mine = adhesion::ownedReceptors(population.size(), comm.getRank(), comm.getSize());
  const adhesion::BondEvents local = population.update(cell, receptors(c), positions, dt, step, mine.first, mine.last);
  // Gathered on one rank too: every run takes the same path through the same arithmetic.
  adhesion::shareBondStates(population, comm);
  int counts[2] = {local.formed, local.broken}, totals[2] = {0, 0};
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 2, counts, totals);
  return {totals[0], totals[1]};
}

adhesion::AdhesionSummary SceneBonds::summary(int c, const mesh::SurfaceMesh& cell, const double* positions) const
{
  return adhesion::summariseAdhesion(bonds(c), cell, receptors(c), positions);
}

std::vector<double> SceneBonds::states(int c) const
{
  std::vector<double> out;
  out.reserve(4 * static_cast<std::size_t>(bonds(c).size()));
  for (const adhesion::BondState& s : bonds(c).states()) {
    out.insert(out.end(), {s.occupancy, s.anchor[0], s.anchor[1], s.anchor[2]});
  }
  return out;
}

void SceneBonds::restoreStates(int c, const std::vector<double>& states, const std::string& source)
{
  adhesion::BondPopulation& population = bonds(c);
  core::require<core::InputError>(states.size() == 4 * static_cast<std::size_t>(population.size()), "The checkpoint '",
                                  source, "' holds ", states.size() / 4, " bond states of cell ", c, " for ",
                                  population.size(), " receptors: it belongs to other 'Adhesion' settings.");
  for (int r = 0; r < population.size(); ++r) {
    const double* s = states.data() + 4 * static_cast<std::size_t>(r);
    population.setState(r, adhesion::BondState{s[0], mesh::Vec3(s[1], s[2], s[3])});
  }
}

std::string SceneBonds::describe() const
{
  const adhesion::AdhesionSettings& s = settings_;
  std::ostringstream line;
  line << "adhesion: " << adhesion::to_string(s.model) << " bonds, " << adhesion::to_string(s.kinetics)
       << " kinetics (seed " << s.seed << "), sigma " << s.springConstant << " G, lambda " << s.equilibriumLength
       << " a, r_0 " << s.reactionDistance << " a, k_on0 n_L " << s.onRate * s.ligandDensity << " k, k_off0 "
       << s.offRate << " k; receptors";
  for (const auto& receptors : receptors_) {
    line << " " << receptors.size();
  }
  line << " (per cell)";
  if (s.patchRadius > 0.0) {
    line << ", each a patch of radius " << s.patchRadius << " a";
  }
  line << "; bonds updated after each accepted step";
  return line.str();
}

} // namespace capsula::scene
