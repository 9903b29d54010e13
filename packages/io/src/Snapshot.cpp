#include "capsula/io/Snapshot.hpp"

#include "capsula/core/Error.hpp"

#include <set>

namespace capsula::io {

bool isValidOutputName(const std::string& name)
{
  if (name.empty() || name == "." || name == "..") {
    return false;
  }
  for (const char ch : name) {
    const bool ok = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '_' ||
                    ch == '-' || ch == '.';
    if (!ok) {
      return false;
    }
  }
  return true;
}

namespace {

void checkFields(const SnapshotBlock& block, const std::vector<Field>& fields, std::size_t count, const char* where)
{
  std::set<std::string> seen;
  for (const auto& f : fields) {
    core::require(isValidOutputName(f.name), "snapshot block '", block.name, "': ", where, " field name '", f.name,
                  "' must be letters, digits, '_', '-' or '.'");
    core::require(seen.insert(f.name).second, "snapshot block '", block.name, "': ", where, " field '", f.name,
                  "' appears twice");
    core::require(f.components >= 1 && f.values.size() == count * static_cast<std::size_t>(f.components),
                  "snapshot block '", block.name, "': ", where, " field '", f.name, "' has ", f.values.size(),
                  " values, expected ", count, " x ", f.components);
  }
}

} // namespace

std::string xdmfTopologyName(Topology topology)
{
  switch (topology) {
  case Topology::QuadraticTriangles:
    return "Triangle_6";
  case Topology::Polylines:
    return "Polyline";
  case Topology::StructuredGrid:
    return "2DSMesh";
  }
  return "Triangle_6";
}

std::size_t SnapshotBlock::nodeCount() const
{
  return dimension > 0 ? positions.size() / static_cast<std::size_t>(dimension) : 0;
}

std::size_t SnapshotBlock::nodesPerCell() const
{
  switch (topology) {
  case Topology::QuadraticTriangles:
    return 6;
  case Topology::Polylines:
    return static_cast<std::size_t>(nodesPerPolyline);
  case Topology::StructuredGrid:
    return 4;
  }
  return 0;
}

std::size_t SnapshotBlock::cellCount() const
{
  if (topology == Topology::StructuredGrid) {
    const auto n0 = static_cast<std::size_t>(gridShape[0]), n1 = static_cast<std::size_t>(gridShape[1]);
    return n0 > 0 && n1 > 0 ? (n0 - 1) * (n1 - 1) : 0;
  }
  const std::size_t k = nodesPerCell();
  return k > 0 ? connectivity.size() / k : 0;
}

void SnapshotBlock::checkConsistency() const
{
  core::require(isValidOutputName(name), "snapshot block name '", name, "' must be letters, digits, '_', '-' or '.'");
  core::require(dimension == 2 || dimension == 3, "snapshot block '", name, "': dimension ", dimension,
                " is not 2 or 3");
  core::require(positions.size() % static_cast<std::size_t>(dimension) == 0, "snapshot block '", name,
                "': ", positions.size(), " coordinates are not a multiple of the dimension ", dimension);
  const std::size_t nodes = nodeCount();
  switch (topology) {
  case Topology::QuadraticTriangles:
  case Topology::Polylines: {
    const std::size_t k = nodesPerCell();
    core::require(k >= 2, "snapshot block '", name, "': a polyline needs nodesPerPolyline >= 2");
    core::require(connectivity.size() % k == 0, "snapshot block '", name, "': connectivity of ", connectivity.size(),
                  " entries is not a multiple of ", k, " nodes per element");
    for (const std::int64_t node : connectivity) {
      core::require(node >= 0 && static_cast<std::size_t>(node) < nodes, "snapshot block '", name,
                    "': connectivity refers to node ", node, " of ", nodes);
    }
    break;
  }
  case Topology::StructuredGrid:
    core::require(gridShape[0] >= 2 && gridShape[1] >= 2 &&
                      static_cast<std::size_t>(gridShape[0] * gridShape[1]) == nodes,
                  "snapshot block '", name, "': grid shape ", gridShape[0], " x ", gridShape[1], " does not match its ",
                  nodes, " nodes (need at least 2 x 2)");
    core::require(connectivity.empty(), "snapshot block '", name, "': a structured grid has no connectivity");
    break;
  }
  checkFields(*this, nodeFields, nodes, "node");
  checkFields(*this, cellFields, cellCount(), "cell");
}

} // namespace capsula::io
