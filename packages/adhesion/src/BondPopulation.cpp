#include "capsula/adhesion/BondPopulation.hpp"

#include "capsula/adhesion/BondKinetics.hpp"
#include "capsula/adhesion/BondSpring.hpp"
#include "capsula/adhesion/CounterRandom.hpp"

#include <capsula/core/Error.hpp>

#include <algorithm>
#include <cmath>

namespace capsula::adhesion {

namespace core = capsula::core;

namespace {

// One key word for (cell, receptor): the cell in the high 32 bits, the receptor in the low.
std::uint64_t streamOf(std::uint64_t cell, std::uint64_t receptor)
{
  return (cell << 32) ^ receptor;
}

} // namespace

BondPopulation::BondPopulation(const AdhesionSettings& settings, std::uint64_t stream, int numReceptors)
    : settings_(settings), stream_(stream), states_(static_cast<std::size_t>(std::max(numReceptors, 0)))
{}

void BondPopulation::setState(int r, const BondState& state)
{
  core::require<core::InputError>(r >= 0 && r < size(), "BondPopulation: no receptor ", r, ".");
  const bool valid = settings_.kinetics == BondKinetics::MeanField ? state.occupancy >= 0.0 && state.occupancy <= 1.0
                                                                   : state.occupancy == 0.0 || state.occupancy == 1.0;
  core::require<core::InputError>(valid, "BondPopulation: receptor ", r, " cannot have occupancy ", state.occupancy,
                                  ".");
  states_[static_cast<std::size_t>(r)] = state;
}

void BondPopulation::stochasticStep(BondState& state, const mesh::Vec3& x, double dt, std::uint64_t receptor,
                                    std::uint64_t step, BondEvents& events) const
{
  const std::uint64_t key = streamOf(stream_, receptor);
  // A free receptor (from the start of the step, or from its bond's breakage at time s)
  // binds a fresh bond to the point below it: the chain free <-> bound with that bond's rates.
  const double gap = settings_.ligandWall.gap(x[1]);
  const double kOn = onRate(settings_, gap, x[0], x[2]);
  const auto binds = [&](double interval) {
    return kOn > 0.0 && counterUniform(settings_.seed, key, step, static_cast<std::uint64_t>(DrawPurpose::Formation)) <
                            bindingProbability(kOn, offRate(settings_, std::abs(gap)), interval);
  };
  if (state.occupancy > 0.0) {
    const double kOff = offRate(settings_, (x - state.anchor).norm());
    const double u = counterUniform(settings_.seed, key, step, static_cast<std::uint64_t>(DrawPurpose::Breakage));
    if (u >= eventProbability(kOff, dt)) {
      return; // survives the step
    }
    ++events.broken;
    state = BondState{};
    if (!binds(dt - breakageTime(kOff, u))) {
      return;
    }
  } else if (!binds(dt)) {
    return;
  }
  state.occupancy = 1.0;
  state.anchor = settings_.ligandWall.foot(x);
  ++events.formed;
}

void BondPopulation::meanFieldStep(BondState& state, const mesh::Vec3& x, double dt) const
{
  const double p = state.occupancy;
  // Without bonds yet, the bonds this step forms have the length of a bond to the foot.
  const double gap = settings_.ligandWall.gap(x[1]);
  const double kOff = offRate(settings_, p > 0.0 ? (x - state.anchor).norm() : std::abs(gap));
  const double kOn = onRate(settings_, gap, x[0], x[2]);
  if (kOn <= 0.0 && p <= 0.0) {
    return;
  }
  const double k = kOn + kOff;
  if (k <= 0.0) {
    return; // no rate: nothing changes
  }
  const double equilibrium = kOn / k;
  const double next = equilibrium + (p - equilibrium) * std::exp(-k * dt);
  // Occupancy kept by the old bonds, and what formed anew: the anchor's weights.
  const double survived = std::min(p * std::exp(-kOff * dt), next);
  const double formed = next - survived;
  if (next <= 0.0) {
    state = BondState{};
    return;
  }
  state.anchor = (survived * state.anchor + formed * settings_.ligandWall.foot(x)) / next;
  state.occupancy = std::clamp(next, 0.0, 1.0);
}

BondEvents BondPopulation::update(const mesh::SurfaceMesh& mesh, const ReceptorSet& receptors, const double* positions,
                                  double dt, std::uint64_t step, int first, int last)
{
  core::require<core::InputError>(receptors.size() == size(), "BondPopulation: ", size(), " states for ",
                                  receptors.size(), " receptors.");
  core::require<core::InputError>(first >= 0 && first <= last && last <= size(), "BondPopulation: receptors ", first,
                                  "..", last, " are not within 0..", size(), ".");
  BondEvents events;
  for (int r = first; r < last; ++r) {
    const mesh::Vec3 x = receptors.position(mesh, positions, r);
    BondState& state = states_[static_cast<std::size_t>(r)];
    if (settings_.kinetics == BondKinetics::MeanField) {
      meanFieldStep(state, x, dt);
    } else {
      stochasticStep(state, x, dt, static_cast<std::uint64_t>(r), step, events);
    }
  }
  return events;
}

double BondPopulation::bondCount() const
{
  double count = 0.0;
  for (const BondState& s : states_) {
    count += s.occupancy;
  }
  return count;
}

mesh::Vec3 BondPopulation::force(int r, const mesh::Vec3& x) const
{
  const BondState& s = state(r);
  if (s.occupancy <= 0.0) {
    return mesh::Vec3::Zero();
  }
  return s.occupancy * springForce(x, s.anchor, settings_.springConstant, settings_.equilibriumLength);
}

mesh::Vec3 BondPopulation::addNodalForces(const mesh::SurfaceMesh& mesh, const ReceptorSet& receptors,
                                          const double* positions, double* nodalForces, int first, int last) const
{
  mesh::Vec3 total = mesh::Vec3::Zero();
  std::vector<NodeWeight> weights;
  for (int r = first; r < last; ++r) {
    if (state(r).occupancy <= 0.0) {
      continue;
    }
    const mesh::Vec3 f = force(r, receptors.position(mesh, positions, r));
    receptors.nodeWeights(mesh, r, weights);
    for (const NodeWeight& c : weights) {
      double* F = nodalForces + 3 * c.node;
      F[0] += c.weight * f[0];
      F[1] += c.weight * f[1];
      F[2] += c.weight * f[2];
    }
    total += f;
  }
  return total;
}

void BondPopulation::addStiffness(const mesh::SurfaceMesh& mesh, const ReceptorSet& receptors, const double* positions,
                                  LoadStiffness& stiffness) const
{
  std::vector<NodeWeight> weights;
  for (int r = 0; r < size(); ++r) {
    const BondState& s = state(r);
    if (s.occupancy <= 0.0) {
      continue;
    }
    const mesh::Mat3 bond = springStiffness(receptors.position(mesh, positions, r), s.anchor,
                                            s.occupancy * settings_.springConstant, settings_.equilibriumLength);
    receptors.nodeWeights(mesh, r, weights);
    for (const NodeWeight& a : weights) {
      for (const NodeWeight& b : weights) {
        const double weight = a.weight * b.weight;
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) {
            stiffness.add(3 * a.node + i, 3 * b.node + j, weight * bond(i, j));
          }
        }
      }
    }
  }
}

std::vector<BondRecord> BondPopulation::records(const mesh::SurfaceMesh& mesh, const ReceptorSet& receptors,
                                                const double* positions) const
{
  std::vector<BondRecord> out;
  for (int r = 0; r < size(); ++r) {
    const BondState& s = state(r);
    if (s.occupancy > 0.0) {
      const mesh::Vec3 x = receptors.position(mesh, positions, r);
      out.push_back({r, s.occupancy, x, s.anchor, force(r, x)});
    }
  }
  return out;
}

} // namespace capsula::adhesion
