#include "capsula/run/SceneSnapshot.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <string>

namespace capsula::run {

namespace {

std::vector<double> slice(const std::vector<double>& values, std::size_t first, std::size_t count)
{
  return std::vector<double>(values.begin() + static_cast<std::ptrdiff_t>(first),
                             values.begin() + static_cast<std::ptrdiff_t>(first + count));
}

// Entry `which` of the pairs of nodes [first, first + count).
std::vector<double> component(const std::vector<double>& pairs, std::size_t first, std::size_t count, int which)
{
  std::vector<double> values(count);
  for (std::size_t i = 0; i < count; ++i) {
    values[i] = pairs[2 * (first + i) + static_cast<std::size_t>(which)];
  }
  return values;
}

// The bonds of cell c as segments from the receptor to its ligand, or nothing without bonds
// (an empty block would give ParaView an empty topology).
std::optional<io::SnapshotBlock> bondBlock(const scene::Scene& scene, int c, const double* positions)
{
  const auto records = scene.bonds().bonds(c).records(scene.cell(c), scene.bonds().receptors(c), positions);
  if (records.empty()) {
    return std::nullopt;
  }
  io::SnapshotBlock block;
  block.name = "bonds" + std::to_string(c);
  block.topology = io::Topology::Polylines;
  block.nodesPerPolyline = 2;
  block.dimension = 3;
  io::Field force{"force", 3, {}}, occupancy{"occupancy", 1, {}}, receptor{"receptor", 1, {}};
  for (const auto& bond : records) {
    const auto first = static_cast<std::int64_t>(block.positions.size() / 3);
    block.positions.insert(block.positions.end(), {bond.position[0], bond.position[1], bond.position[2]});
    block.positions.insert(block.positions.end(), {bond.anchor[0], bond.anchor[1], bond.anchor[2]});
    block.connectivity.insert(block.connectivity.end(), {first, first + 1});
    force.values.insert(force.values.end(), {bond.force[0], bond.force[1], bond.force[2]});
    occupancy.values.push_back(bond.occupancy);
    receptor.values.push_back(static_cast<double>(bond.receptor));
  }
  block.cellFields = {std::move(force), std::move(occupancy), std::move(receptor)};
  return block;
}

// The tether as one segment from its attachment to its anchor, with its force on the membrane.
io::SnapshotBlock tetherBlock(const scene::Scene& scene, const double* positions)
{
  const adhesion::Tether& tether = scene.tether();
  const adhesion::TetherState state = tether.state(scene.cell(tether.cell()), positions);
  io::SnapshotBlock block;
  block.name = "tether";
  block.topology = io::Topology::Polylines;
  block.nodesPerPolyline = 2;
  block.dimension = 3;
  block.positions = {state.attachment[0], state.attachment[1], state.attachment[2],
                     state.anchor[0],     state.anchor[1],     state.anchor[2]};
  block.connectivity = {0, 1};
  block.cellFields = {{"force", 3, {state.force[0], state.force[1], state.force[2]}}, {"length", 1, {state.length}}};
  return block;
}

// The mean of n nodes' positions (3 per node).
std::array<double, 3> nodeMean(const double* positions, int n)
{
  std::array<double, 3> mean{};
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < 3; ++i) {
      mean[static_cast<std::size_t>(i)] += positions[3 * k + i] / n;
    }
  }
  return mean;
}

void shift(io::SnapshotBlock& block, const std::array<double, 3>& by)
{
  for (std::size_t k = 0; k < block.positions.size(); ++k) {
    block.positions[k] += by[k % 3];
  }
}

} // namespace

io::Snapshot sceneSnapshot(const scene::Scene& scene, const scene::SceneFields& fields, double time, std::int64_t step,
                           bool foldIntoBox)
{
  io::Snapshot snapshot;
  snapshot.time = time;
  snapshot.step = step;
  // The lattice shift that draws each cell in the box (zero unless folded).
  std::vector<std::array<double, 3>> shifts(static_cast<std::size_t>(scene.numCells()), {0.0, 0.0, 0.0});
  for (int c = 0; foldIntoBox && c < scene.numCells(); ++c) {
    shifts[static_cast<std::size_t>(c)] = scene.description().domain.foldingShift(
        nodeMean(fields.positions.data() + 3 * static_cast<std::size_t>(scene.nodeOffset(c)), scene.cell(c).numNodes())
            .data());
  }
  for (int c = 0; c < scene.numCells(); ++c) {
    const mesh::SurfaceMesh& cell = scene.cell(c);
    const auto nodes = static_cast<std::size_t>(cell.numNodes());
    const auto elements = static_cast<std::size_t>(cell.numElements());
    const auto firstNode = static_cast<std::size_t>(scene.nodeOffset(c));
    const auto firstElement = static_cast<std::size_t>(scene.elementOffset(c));
    io::SnapshotBlock block;
    block.name = "cell" + std::to_string(c);
    block.topology = io::Topology::QuadraticTriangles;
    block.dimension = 3;
    block.positions = slice(fields.positions, 3 * firstNode, 3 * nodes);
    shift(block, shifts[static_cast<std::size_t>(c)]);
    block.connectivity.reserve(6 * elements);
    for (const auto& element : cell.elements()) {
      block.connectivity.insert(block.connectivity.end(), element.begin(), element.end());
    }
    block.nodeFields.push_back({"velocity", 3, slice(fields.velocities, 3 * firstNode, 3 * nodes)});
    // Pairs as separate scalars: ParaView reads 3-component vectors, not 2.
    block.nodeFields.push_back({"tension_major", 1, component(fields.principalTensions, firstNode, nodes, 0)});
    block.nodeFields.push_back({"tension_minor", 1, component(fields.principalTensions, firstNode, nodes, 1)});
    block.nodeFields.push_back({"stretch_major", 1, component(fields.stretches, firstNode, nodes, 0)});
    block.nodeFields.push_back({"stretch_minor", 1, component(fields.stretches, firstNode, nodes, 1)});
    const std::vector<double> loads = slice(fields.elementLoads, 3 * firstElement, 3 * elements);
    std::vector<double> magnitude(elements);
    for (std::size_t e = 0; e < elements; ++e) {
      magnitude[e] = std::sqrt(loads[3 * e] * loads[3 * e] + loads[3 * e + 1] * loads[3 * e + 1] +
                               loads[3 * e + 2] * loads[3 * e + 2]);
    }
    block.cellFields.push_back({"load", 3, loads});
    block.cellFields.push_back({"shear_stress", 1, magnitude});
    snapshot.blocks.push_back(std::move(block));
  }
  for (int c = 0; scene.hasBonds() && c < scene.numCells(); ++c) {
    const double* positions = fields.positions.data() + 3 * static_cast<std::size_t>(scene.nodeOffset(c));
    if (auto bonds = bondBlock(scene, c, positions)) {
      shift(*bonds, shifts[static_cast<std::size_t>(c)]);
      snapshot.blocks.push_back(std::move(*bonds));
    }
  }
  if (scene.hasTether()) {
    const int c = scene.tether().cell();
    io::SnapshotBlock tether =
        tetherBlock(scene, fields.positions.data() + 3 * static_cast<std::size_t>(scene.nodeOffset(c)));
    shift(tether, shifts[static_cast<std::size_t>(c)]);
    snapshot.blocks.push_back(std::move(tether));
  }
  return snapshot;
}

io::SnapshotBlock wallSnapshotBlock(const WallGrid& grid, const operators::WallShearStress& stress)
{
  // The lower wall keeps the names it always had (n = e_y there, so du/dn is du/dy); the
  // upper wall's grid is a block of its own, its derivatives named for the normal n = -e_y.
  const bool lower = grid.wall.fluidSide > 0;
  io::SnapshotBlock block;
  block.name = lower ? "wall" : "upper_wall";
  block.topology = io::Topology::StructuredGrid;
  block.dimension = 3;
  // Row-major with the x index fastest: shape (nz, nx), as WallGrid::index numbers them.
  block.gridShape = {grid.nz, grid.nx};
  for (const auto& p : grid.nodes()) {
    block.positions.insert(block.positions.end(), {p[0], p[1], p[2]});
  }
  block.nodeFields.push_back({"shear_stress", 1, stress.magnitude});
  block.nodeFields.push_back({lower ? "dudy" : "dudn", 1, stress.dudy});
  block.nodeFields.push_back({lower ? "dwdy" : "dwdn", 1, stress.dwdy});
  return block;
}

} // namespace capsula::run
