#include "capsula/io/SnapshotFile.hpp"

#include "Hdf5Support.hpp"
#include "UndoJournal.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/core/Files.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <map>
#include <set>
#include <tuple>

namespace capsula::io {

namespace {

constexpr const char* snapshotFormatName = "Capsula snapshots";
constexpr std::int64_t snapshotFormatVersion = 2;
constexpr const char* meshRoot = "mesh";
constexpr const char* snapshotRoot = "snapshots";

/// One block of a mesh version: what does not move.
struct MeshBlock {
  std::string name;
  Topology topology = Topology::QuadraticTriangles;
  int dimension = 3;
  std::size_t nodes = 0;
  int nodesPerPolyline = 0;
  std::array<std::int64_t, 2> gridShape{0, 0};
  std::vector<std::int64_t> connectivity;

  std::size_t nodesPerCell() const
  {
    return topology == Topology::QuadraticTriangles ? 6
           : topology == Topology::Polylines        ? static_cast<std::size_t>(nodesPerPolyline)
                                                    : 4;
  }
  std::size_t cells() const
  {
    if (topology == Topology::StructuredGrid) {
      return gridShape[0] > 0 && gridShape[1] > 0 ? static_cast<std::size_t>((gridShape[0] - 1) * (gridShape[1] - 1))
                                                  : 0;
    }
    return nodesPerCell() > 0 ? connectivity.size() / nodesPerCell() : 0;
  }
};

using Mesh = std::vector<MeshBlock>;

Mesh meshOf(const Snapshot& snapshot)
{
  Mesh mesh;
  for (const auto& b : snapshot.blocks) {
    mesh.push_back({b.name, b.topology, b.dimension, b.nodeCount(), b.nodesPerPolyline, b.gridShape, b.connectivity});
  }
  return mesh;
}

bool sameMesh(const Mesh& a, const Mesh& b)
{
  if (a.size() != b.size()) {
    return false;
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    const MeshBlock &x = a[i], &y = b[i];
    const bool same = x.name == y.name && x.topology == y.topology && x.dimension == y.dimension &&
                      x.nodes == y.nodes && x.nodesPerPolyline == y.nodesPerPolyline && x.gridShape == y.gridShape &&
                      x.connectivity == y.connectivity;
    if (!same) {
      return false;
    }
  }
  return true;
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

/// The indices of the members of `group` named by snapshotGroupName, in index order; any
/// other member is an error.
std::vector<std::size_t> indexedMembers(hid_t group, const std::string& what, const std::string& path)
{
  std::vector<std::size_t> indices;
  for (const auto& name : hdf5::memberNames(group)) {
    const bool digits =
        !name.empty() && std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
    core::require<core::IoError>(digits, "Snapshot file '", path, "': '/", what, "/", name,
                                 "' is not a numbered group.");
    indices.push_back(static_cast<std::size_t>(std::stoull(name)));
  }
  std::sort(indices.begin(), indices.end());
  for (std::size_t i = 0; i < indices.size(); ++i) {
    core::require<core::IoError>(indices[i] == i, "Snapshot file '", path, "': '/", what, "' lacks number ", i,
                                 " (it has ", indices.size(), " entries).");
  }
  return indices;
}

// ---- writing --------------------------------------------------------------------------

std::vector<hsize_t> fieldShape(std::size_t count, int components)
{
  if (components == 1) {
    return {static_cast<hsize_t>(count)};
  }
  return {static_cast<hsize_t>(count), static_cast<hsize_t>(components)};
}

void writeMeshBlock(hid_t meshGroup, const MeshBlock& block)
{
  hdf5::Handle group = hdf5::createGroup(meshGroup, block.name);
  hdf5::writeAttribute(group.get(), "topology", xdmfTopologyName(block.topology));
  hdf5::writeAttribute(group.get(), "dimension", static_cast<std::int64_t>(block.dimension));
  hdf5::writeAttribute(group.get(), "nodes", static_cast<std::int64_t>(block.nodes));
  if (block.topology == Topology::StructuredGrid) {
    hdf5::writeAttribute(group.get(), "grid_shape", std::vector<std::int64_t>{block.gridShape[0], block.gridShape[1]});
    return;
  }
  if (block.topology == Topology::Polylines) {
    hdf5::writeAttribute(group.get(), "nodes_per_polyline", static_cast<std::int64_t>(block.nodesPerPolyline));
  }
  hdf5::writeIntegers(group.get(), "connectivity", block.connectivity,
                      {static_cast<hsize_t>(block.cells()), static_cast<hsize_t>(block.nodesPerCell())});
}

void writeFields(hid_t blockGroup, const char* groupName, const std::vector<Field>& fields, std::size_t count)
{
  hdf5::Handle group = hdf5::createGroup(blockGroup, groupName);
  for (const auto& f : fields) {
    hdf5::writeDoubles(group.get(), f.name, f.values, fieldShape(count, f.components));
  }
}

void writeSnapshotBlock(hid_t snapshotGroup, const SnapshotBlock& block)
{
  hdf5::Handle group = hdf5::createGroup(snapshotGroup, block.name);
  hdf5::writeDoubles(group.get(), "positions", block.positions,
                     {static_cast<hsize_t>(block.nodeCount()), static_cast<hsize_t>(block.dimension)});
  writeFields(group.get(), "node_fields", block.nodeFields, block.nodeCount());
  writeFields(group.get(), "cell_fields", block.cellFields, block.cellCount());
}

// ---- reading --------------------------------------------------------------------------

Mesh readMesh(hid_t file, std::size_t version, const std::string& path)
{
  const std::string where = std::string("/") + meshRoot + "/" + snapshotGroupName(version);
  core::require<core::IoError>(hdf5::exists(file, meshRoot) && hdf5::exists(file, where), "Snapshot file '", path,
                               "' lacks the mesh version '", where, "'.");
  hdf5::Handle group = hdf5::openGroup(file, where);
  Mesh mesh;
  for (const auto& name : hdf5::memberNames(group.get())) {
    hdf5::Handle b = hdf5::openGroup(group.get(), name);
    MeshBlock block;
    block.name = name;
    block.topology = topologyFromName(hdf5::readStringAttribute(b.get(), "topology"), path);
    block.dimension = static_cast<int>(hdf5::readIntegerAttribute(b.get(), "dimension"));
    block.nodes = static_cast<std::size_t>(hdf5::readIntegerAttribute(b.get(), "nodes"));
    if (block.topology == Topology::StructuredGrid) {
      const auto shape = hdf5::readIntegerArrayAttribute(b.get(), "grid_shape");
      core::require<core::IoError>(shape.size() == 2, "Snapshot file '", path, "': '", where, "/", name,
                                   "' has a malformed grid_shape.");
      block.gridShape = {shape[0], shape[1]};
    } else {
      if (block.topology == Topology::Polylines) {
        block.nodesPerPolyline = static_cast<int>(hdf5::readIntegerAttribute(b.get(), "nodes_per_polyline"));
      }
      std::vector<hsize_t> shape;
      block.connectivity = hdf5::readIntegers(b.get(), "connectivity", &shape);
      core::require<core::IoError>(shape.size() == 2 && shape[1] == block.nodesPerCell(), "Snapshot file '", path,
                                   "': '", where, "/", name, "/connectivity' has the wrong shape.");
    }
    mesh.push_back(std::move(block));
  }
  return mesh;
}

std::vector<SnapshotLayout::FieldLayout> fieldLayouts(hid_t blockGroup, const char* groupName, std::size_t count,
                                                      const std::string& where, const std::string& path)
{
  std::vector<SnapshotLayout::FieldLayout> fields;
  hdf5::Handle group = hdf5::openGroup(blockGroup, groupName);
  for (const auto& name : hdf5::memberNames(group.get())) {
    const std::vector<hsize_t> shape = hdf5::datasetShape(group.get(), name);
    const bool ok = !shape.empty() && shape.size() <= 2 && shape[0] == count;
    core::require<core::IoError>(ok, "Snapshot file '", path, "': '", where, "/", groupName, "/", name,
                                 "' does not have one row per ", groupName[0] == 'n' ? "node" : "cell", ".");
    fields.push_back({name, shape.size() == 2 ? static_cast<int>(shape[1]) : 1});
  }
  return fields;
}

SnapshotLayout readLayout(hid_t file, std::size_t index, std::map<std::size_t, Mesh>& meshes, const std::string& path)
{
  SnapshotLayout layout;
  layout.group = std::string("/") + snapshotRoot + "/" + snapshotGroupName(index);
  hdf5::Handle group = hdf5::openGroup(file, layout.group);
  layout.time = hdf5::readDoubleAttribute(group.get(), "time");
  layout.step = hdf5::readIntegerAttribute(group.get(), "step");
  const std::int64_t version = hdf5::readIntegerAttribute(group.get(), "mesh");
  core::require<core::IoError>(version >= 0, "Snapshot file '", path, "': '", layout.group, "' names mesh version ",
                               version, ".");
  const auto m = static_cast<std::size_t>(version);
  layout.meshGroup = std::string("/") + meshRoot + "/" + snapshotGroupName(m);
  if (meshes.count(m) == 0) {
    meshes[m] = readMesh(file, m, path);
  }
  const Mesh& mesh = meshes[m];
  const std::vector<std::string> names = hdf5::memberNames(group.get());
  core::require<core::IoError>(names.size() == mesh.size(), "Snapshot file '", path, "': '", layout.group, "' has ",
                               names.size(), " blocks, its mesh '", layout.meshGroup, "' ", mesh.size(), ".");
  for (std::size_t b = 0; b < mesh.size(); ++b) {
    const MeshBlock& block = mesh[b];
    const std::string where = layout.group + "/" + block.name;
    core::require<core::IoError>(names[b] == block.name, "Snapshot file '", path, "': '", layout.group,
                                 "' holds block '", names[b], "' where its mesh has '", block.name, "'.");
    hdf5::Handle g = hdf5::openGroup(group.get(), block.name);
    const std::vector<hsize_t> shape = hdf5::datasetShape(g.get(), "positions");
    core::require<core::IoError>(shape.size() == 2 && shape[0] == block.nodes &&
                                     shape[1] == static_cast<hsize_t>(block.dimension),
                                 "Snapshot file '", path, "': '", where, "/positions' has the wrong shape.");
    SnapshotLayout::BlockLayout l;
    l.name = block.name;
    l.topology = block.topology;
    l.dimension = block.dimension;
    l.nodes = block.nodes;
    l.cells = block.cells();
    l.nodesPerCell = block.nodesPerCell();
    l.gridShape = block.gridShape;
    l.nodeFields = fieldLayouts(g.get(), "node_fields", l.nodes, where, path);
    l.cellFields = fieldLayouts(g.get(), "cell_fields", l.cells, where, path);
    layout.blocks.push_back(std::move(l));
  }
  return layout;
}

hdf5::Handle openSnapshotFile(const std::string& path, bool writing)
{
  if (writing) {
    hdf5::undoInterruptedWrite(path);
  }
  hdf5::Handle file =
      writing ? hdf5::openFileWithUndoJournal(path, "snapshot") : hdf5::openFileForReading(path, "snapshot");
  const bool ours =
      hdf5::hasAttribute(file.get(), "format") && hdf5::readStringAttribute(file.get(), "format") == snapshotFormatName;
  core::require<core::IoError>(ours, "'", path, "' is an HDF5 file but not a Capsula snapshot file.");
  const std::int64_t version = hdf5::readIntegerAttribute(file.get(), "version");
  core::require<core::IoError>(version == snapshotFormatVersion, "Snapshot file '", path, "' has format version ",
                               version, "; this Capsula reads version ", snapshotFormatVersion, ".");
  core::require<core::IoError>(hdf5::exists(file.get(), meshRoot) && hdf5::exists(file.get(), snapshotRoot),
                               "Snapshot file '", path, "' lacks '/", meshRoot, "' or '/", snapshotRoot, "'.");
  return file;
}

/// Closes `file` (which flushes it) and forces it to disk.
void closeDurably(hdf5::Handle& file, const std::string& path)
{
  hdf5::flush(file.get());
  file.close();
  hdf5::syncToDisk(path);
}

} // namespace

std::string snapshotGroupName(std::size_t index)
{
  char digits[32];
  std::snprintf(digits, sizeof(digits), "%06zu", index);
  return digits;
}

void createSnapshotFile(const std::string& path)
{
  const std::string temporary = core::temporaryPathFor(path);
  try {
    hdf5::Handle file = hdf5::createFile(temporary, "snapshot");
    hdf5::writeAttribute(file.get(), "format", std::string(snapshotFormatName));
    hdf5::writeAttribute(file.get(), "version", snapshotFormatVersion);
    hdf5::createGroup(file.get(), meshRoot);
    hdf5::createGroup(file.get(), snapshotRoot);
    file.close();
    hdf5::syncToDisk(temporary);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  hdf5::discardUndoJournal(path); // it belongs to the file being replaced
  core::replaceFileAtomically(temporary, path);
}

bool undoInterruptedAppend(const std::string& path)
{
  return hdf5::undoInterruptedWrite(path);
}

SnapshotLayout appendSnapshot(const std::string& path, const Snapshot& snapshot)
{
  std::set<std::string> names;
  for (const auto& block : snapshot.blocks) {
    block.checkConsistency();
    core::require(names.insert(block.name).second, "snapshot block name '", block.name, "' appears twice");
  }
  hdf5::Handle file = openSnapshotFile(path, true);
  hdf5::Handle meshes = hdf5::openGroup(file.get(), meshRoot);
  hdf5::Handle snapshots = hdf5::openGroup(file.get(), snapshotRoot);
  const std::size_t index = indexedMembers(snapshots.get(), snapshotRoot, path).size();
  const std::size_t versions = indexedMembers(meshes.get(), meshRoot, path).size();

  // The latest mesh version if the snapshot's blocks and connectivity are the same, else a
  // new version, linked only once complete.
  const Mesh mesh = meshOf(snapshot);
  std::size_t version = versions;
  if (versions > 0 && sameMesh(readMesh(file.get(), versions - 1, path), mesh)) {
    version = versions - 1;
  } else {
    hdf5::Handle group = hdf5::createAnonymousGroup(file.get());
    for (const auto& block : mesh) {
      writeMeshBlock(group.get(), block);
    }
    hdf5::link(group.get(), meshes.get(), snapshotGroupName(version));
  }

  hdf5::Handle group = hdf5::createAnonymousGroup(file.get());
  hdf5::writeAttribute(group.get(), "time", snapshot.time);
  hdf5::writeAttribute(group.get(), "step", snapshot.step);
  hdf5::writeAttribute(group.get(), "mesh", static_cast<std::int64_t>(version));
  for (const auto& block : snapshot.blocks) {
    writeSnapshotBlock(group.get(), block);
  }
  hdf5::link(group.get(), snapshots.get(), snapshotGroupName(index));
  group.close();
  meshes.close();
  snapshots.close();
  closeDurably(file, path);
  return layoutOf(snapshot, std::string("/") + snapshotRoot + "/" + snapshotGroupName(index),
                  std::string("/") + meshRoot + "/" + snapshotGroupName(version));
}

std::vector<SnapshotLayout> readSnapshotLayouts(const std::string& path)
{
  hdf5::Handle file = openSnapshotFile(path, false);
  hdf5::Handle snapshots = hdf5::openGroup(file.get(), snapshotRoot);
  std::map<std::size_t, Mesh> meshes;
  std::vector<SnapshotLayout> layouts;
  for (const std::size_t index : indexedMembers(snapshots.get(), snapshotRoot, path)) {
    layouts.push_back(readLayout(file.get(), index, meshes, path));
  }
  return layouts;
}

Snapshot readSnapshot(const std::string& path, std::size_t index)
{
  hdf5::Handle file = openSnapshotFile(path, false);
  const std::string where = std::string("/") + snapshotRoot + "/" + snapshotGroupName(index);
  core::require<core::IoError>(hdf5::exists(file.get(), where), "Snapshot file '", path, "' has no snapshot ", index,
                               ".");
  std::map<std::size_t, Mesh> meshes;
  const SnapshotLayout layout = readLayout(file.get(), index, meshes, path);
  const Mesh& mesh = meshes.begin()->second;
  hdf5::Handle group = hdf5::openGroup(file.get(), where);
  Snapshot snapshot;
  snapshot.time = layout.time;
  snapshot.step = layout.step;
  for (std::size_t b = 0; b < mesh.size(); ++b) {
    const MeshBlock& m = mesh[b];
    const SnapshotLayout::BlockLayout& l = layout.blocks[b];
    hdf5::Handle g = hdf5::openGroup(group.get(), m.name);
    SnapshotBlock block;
    block.name = m.name;
    block.topology = m.topology;
    block.dimension = m.dimension;
    block.connectivity = m.connectivity;
    block.nodesPerPolyline = m.nodesPerPolyline;
    block.gridShape = m.gridShape;
    block.positions = hdf5::readDoubles(g.get(), "positions", nullptr);
    for (const auto& [fields, name, layouts] : {std::tuple{&block.nodeFields, "node_fields", &l.nodeFields},
                                                std::tuple{&block.cellFields, "cell_fields", &l.cellFields}}) {
      hdf5::Handle f = hdf5::openGroup(g.get(), name);
      for (const auto& field : *layouts) {
        fields->push_back({field.name, field.components, hdf5::readDoubles(f.get(), field.name, nullptr)});
      }
    }
    try {
      block.checkConsistency();
    } catch (const core::Error& e) {
      throw core::IoError("Snapshot file '" + path + "' is inconsistent: " + e.what() + ".");
    }
    snapshot.blocks.push_back(std::move(block));
  }
  return snapshot;
}

void truncateSnapshots(const std::string& path, std::size_t count)
{
  hdf5::undoInterruptedWrite(path);
  const std::string temporary = core::temporaryPathFor(path);
  {
    hdf5::Handle file = openSnapshotFile(path, false);
    hdf5::Handle snapshots = hdf5::openGroup(file.get(), snapshotRoot);
    hdf5::Handle meshes = hdf5::openGroup(file.get(), meshRoot);
    const std::size_t total = indexedMembers(snapshots.get(), snapshotRoot, path).size();
    if (count >= total) {
      return;
    }
    // Mesh versions are numbered in the order the snapshots first use them: keep those up
    // to the last kept snapshot's.
    std::size_t keptVersions = 0;
    if (count > 0) {
      hdf5::Handle last = hdf5::openGroup(snapshots.get(), snapshotGroupName(count - 1));
      keptVersions = static_cast<std::size_t>(hdf5::readIntegerAttribute(last.get(), "mesh")) + 1;
    }
    try {
      hdf5::Handle copy = hdf5::createFile(temporary, "snapshot");
      hdf5::writeAttribute(copy.get(), "format", std::string(snapshotFormatName));
      hdf5::writeAttribute(copy.get(), "version", snapshotFormatVersion);
      hdf5::Handle copiedMeshes = hdf5::createGroup(copy.get(), meshRoot);
      hdf5::Handle copiedSnapshots = hdf5::createGroup(copy.get(), snapshotRoot);
      for (std::size_t m = 0; m < keptVersions; ++m) {
        hdf5::copyObject(meshes.get(), snapshotGroupName(m), copiedMeshes.get());
      }
      for (std::size_t k = 0; k < count; ++k) {
        hdf5::copyObject(snapshots.get(), snapshotGroupName(k), copiedSnapshots.get());
      }
      copiedMeshes.close();
      copiedSnapshots.close();
      copy.close();
      hdf5::syncToDisk(temporary);
    } catch (...) {
      std::remove(temporary.c_str());
      throw;
    }
  }
  hdf5::discardUndoJournal(path); // none: undone above, and this reader wrote none
  core::replaceFileAtomically(temporary, path);
}

} // namespace capsula::io
