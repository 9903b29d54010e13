#include "capsula/io/SnapshotFile.hpp"

#include "Hdf5Support.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/core/Files.hpp"

#include <cstdio>
#include <set>

namespace capsula::io {

namespace {

constexpr const char* formatName = "Capsula snapshot";
constexpr std::int64_t formatVersion = 1;

std::vector<hsize_t> fieldShape(std::size_t count, int components)
{
  if (components == 1) {
    return {static_cast<hsize_t>(count)};
  }
  return {static_cast<hsize_t>(count), static_cast<hsize_t>(components)};
}

void writeFields(hid_t blockGroup, const char* groupName, const std::vector<Field>& fields,
                 std::size_t count)
{
  hdf5::Handle group = hdf5::createGroup(blockGroup, groupName);
  for (const auto& f : fields) {
    hdf5::writeDoubles(group.get(), f.name, f.values, fieldShape(count, f.components));
  }
}

std::vector<Field> readFields(hid_t blockGroup, const char* groupName, std::size_t count,
                              const std::string& path)
{
  std::vector<Field> fields;
  hdf5::Handle group = hdf5::openGroup(blockGroup, groupName);
  for (const auto& name : hdf5::memberNames(group.get())) {
    Field f;
    f.name = name;
    std::vector<hsize_t> shape;
    f.values = hdf5::readDoubles(group.get(), name, &shape);
    const bool ok = !shape.empty() && shape.size() <= 2 && shape[0] == count;
    core::require<core::IoError>(ok, "Snapshot file '", path, "': field '", groupName, "/", name,
                                 "' does not have one row per ", groupName[0] == 'n' ? "node" : "cell", ".");
    f.components = shape.size() == 2 ? static_cast<int>(shape[1]) : 1;
    fields.push_back(std::move(f));
  }
  return fields;
}

void writeBlock(hid_t file, const SnapshotBlock& block)
{
  hdf5::Handle group = hdf5::createGroup(file, block.name);
  hdf5::writeAttribute(group.get(), "topology", xdmfTopologyName(block.topology));
  hdf5::writeAttribute(group.get(), "dimension", static_cast<std::int64_t>(block.dimension));
  const std::size_t nodes = block.nodeCount();
  hdf5::writeDoubles(group.get(), "positions", block.positions,
                     {static_cast<hsize_t>(nodes), static_cast<hsize_t>(block.dimension)});
  if (block.topology == Topology::StructuredGrid) {
    hdf5::writeAttribute(group.get(), "grid_shape",
                         std::vector<std::int64_t>{block.gridShape[0], block.gridShape[1]});
  } else {
    if (block.topology == Topology::Polylines) {
      hdf5::writeAttribute(group.get(), "nodes_per_polyline",
                           static_cast<std::int64_t>(block.nodesPerPolyline));
    }
    hdf5::writeIntegers(group.get(), "connectivity", block.connectivity,
                        {static_cast<hsize_t>(block.cellCount()), static_cast<hsize_t>(block.nodesPerCell())});
  }
  writeFields(group.get(), "node_fields", block.nodeFields, nodes);
  writeFields(group.get(), "cell_fields", block.cellFields, block.cellCount());
}

Topology topologyFromName(const std::string& name, const std::string& path)
{
  for (const auto t : {Topology::QuadraticTriangles, Topology::Polylines, Topology::StructuredGrid}) {
    if (xdmfTopologyName(t) == name) {
      return t;
    }
  }
  throw core::IoError("Snapshot file '" + path + "' has an unknown topology '" + name + "'.");
}

SnapshotBlock readBlock(hid_t file, const std::string& name, const std::string& path)
{
  SnapshotBlock block;
  block.name = name;
  hdf5::Handle group = hdf5::openGroup(file, name);
  block.topology = topologyFromName(hdf5::readStringAttribute(group.get(), "topology"), path);
  block.dimension = static_cast<int>(hdf5::readIntegerAttribute(group.get(), "dimension"));
  std::vector<hsize_t> shape;
  block.positions = hdf5::readDoubles(group.get(), "positions", &shape);
  core::require<core::IoError>(shape.size() == 2 && shape[1] == static_cast<hsize_t>(block.dimension),
                               "Snapshot file '", path, "': block '", name,
                               "' has positions of the wrong shape.");
  if (block.topology == Topology::StructuredGrid) {
    const auto gridShape = hdf5::readIntegerArrayAttribute(group.get(), "grid_shape");
    core::require<core::IoError>(gridShape.size() == 2, "Snapshot file '", path, "': block '", name,
                                 "' has a malformed grid_shape.");
    block.gridShape = {gridShape[0], gridShape[1]};
  } else {
    if (block.topology == Topology::Polylines) {
      block.nodesPerPolyline = static_cast<int>(hdf5::readIntegerAttribute(group.get(), "nodes_per_polyline"));
    }
    block.connectivity = hdf5::readIntegers(group.get(), "connectivity", nullptr);
  }
  block.nodeFields = readFields(group.get(), "node_fields", block.nodeCount(), path);
  block.cellFields = readFields(group.get(), "cell_fields", block.cellCount(), path);
  try {
    block.checkConsistency();
  } catch (const core::Error& e) {
    throw core::IoError("Snapshot file '" + path + "' is inconsistent: " + e.what() + ".");
  }
  return block;
}

} // namespace

void writeSnapshotFile(const std::string& path, const Snapshot& snapshot)
{
  std::set<std::string> names;
  for (const auto& block : snapshot.blocks) {
    block.checkConsistency();
    core::require(names.insert(block.name).second, "snapshot block name '", block.name,
                  "' appears twice");
  }
  const std::string temporary = core::temporaryPathFor(path);
  try {
    hdf5::Handle file = hdf5::createFile(temporary, "snapshot");
    hdf5::writeAttribute(file.get(), "format", std::string(formatName));
    hdf5::writeAttribute(file.get(), "version", formatVersion);
    hdf5::writeAttribute(file.get(), "time", snapshot.time);
    hdf5::writeAttribute(file.get(), "step", snapshot.step);
    for (const auto& block : snapshot.blocks) {
      writeBlock(file.get(), block);
    }
    file.close();
    hdf5::syncToDisk(temporary);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  core::replaceFileAtomically(temporary, path);
}

Snapshot readSnapshotFile(const std::string& path)
{
  hdf5::Handle file = hdf5::openFileForReading(path, "snapshot");
  const bool ours = hdf5::hasAttribute(file.get(), "format") &&
                    hdf5::readStringAttribute(file.get(), "format") == formatName;
  core::require<core::IoError>(ours, "'", path, "' is an HDF5 file but not a Capsula snapshot.");
  const std::int64_t version = hdf5::readIntegerAttribute(file.get(), "version");
  core::require<core::IoError>(version == formatVersion, "Snapshot file '", path, "' has format version ",
                               version, "; this Capsula reads version ", formatVersion, ".");
  Snapshot snapshot;
  snapshot.time = hdf5::readDoubleAttribute(file.get(), "time");
  snapshot.step = hdf5::readIntegerAttribute(file.get(), "step");
  for (const auto& name : hdf5::memberNames(file.get())) {
    snapshot.blocks.push_back(readBlock(file.get(), name, path));
  }
  return snapshot;
}

} // namespace capsula::io
