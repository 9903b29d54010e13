// The snapshot file (one HDF5 file for a whole series) and the XDMF sidecar: datasets read
// back with the plain HDF5 C API (independently of the writer's helpers), shapes and
// values exact; the mesh written once per version; the XDMF is well-formed XML whose every
// data reference names an existing dataset of the stated shape; restart drops the
// snapshots written after the checkpoint and continues into the same file; a run that
// stops mid-way leaves a readable file. (Length: the writer, its XDMF index and their
// crash recovery share one temporary-file fixture and the raw HDF5 readers below.)
#include "capsula/testing/Constants.hpp"
#include "TemporaryDirectory.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/core/Files.hpp"
#include "capsula/io/SnapshotFile.hpp"
#include "capsula/io/SnapshotSeries.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cctype>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

using capsula::testing::pi;

namespace io = capsula::io;
namespace core = capsula::core;
using io::testing::TemporaryDirectory;

namespace {

/// Two quadratic triangles forming the unit square (9 nodes), nodes ordered
/// v0, v1, v2, m01, m12, m20; node fields "velocity" (3) and "tension" (1), a cell
/// field "load" (3). Positions shifted by `t` so snapshots differ.
io::SnapshotBlock squareSurface(double t)
{
  io::SnapshotBlock b;
  b.name = "cell0";
  b.topology = io::Topology::QuadraticTriangles;
  const double xy[9][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0}, {1, 0.5}, {0.5, 0.5}, {0.5, 1}, {0, 0.5}};
  for (const auto& p : xy) {
    b.positions.insert(b.positions.end(), {p[0] + t, p[1], 0.1 * t});
  }
  b.connectivity = {0, 1, 2, 4, 5, 6,  // lower right triangle
                    0, 2, 3, 6, 7, 8}; // upper left triangle
  io::Field velocity{"velocity", 3, {}}, tension{"tension", 1, {}}, load{"load", 3, {}};
  for (int i = 0; i < 9; ++i) {
    velocity.values.insert(velocity.values.end(), {1.0 / (i + 1), -0.5 * i, t});
    tension.values.push_back(std::sqrt(2.0) * i);
  }
  load.values = {0.25, -1e-17, 3.0, 7.0, 8.0, 9.0};
  b.nodeFields = {velocity, tension};
  b.cellFields = {load};
  return b;
}

/// A closed 2D contour of 5 nodes as one polyline.
io::SnapshotBlock contour()
{
  io::SnapshotBlock b;
  b.name = "contour";
  b.topology = io::Topology::Polylines;
  b.dimension = 2;
  for (int i = 0; i < 5; ++i) {
    b.positions.insert(b.positions.end(), {std::cos(0.4 * pi * i), std::sin(0.4 * pi * i)});
  }
  b.nodesPerPolyline = 6;
  b.connectivity = {0, 1, 2, 3, 4, 0};
  b.nodeFields = {{"shear_stress", 1, {1, 2, 3, 4, 5}}};
  return b;
}

/// A 3 x 4 wall grid on y = 0 with a scalar wall shear stress.
io::SnapshotBlock wallGrid()
{
  io::SnapshotBlock b;
  b.name = "wall";
  b.topology = io::Topology::StructuredGrid;
  b.gridShape = {3, 4};
  io::Field stress{"wall_shear_stress", 1, {}};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 4; ++j) {
      b.positions.insert(b.positions.end(), {0.5 * j, 0.0, 0.25 * i});
      stress.values.push_back(i + 0.1 * j);
    }
  }
  b.nodeFields = {stress};
  b.cellFields = {{"cell_index", 1, {0, 1, 2, 3, 4, 5}}};
  return b;
}

io::Snapshot sampleSnapshot(double t, std::int64_t step)
{
  io::Snapshot s;
  s.time = t;
  s.step = step;
  s.blocks = {squareSurface(t), contour(), wallGrid()};
  return s;
}

// ---- Reading with the plain HDF5 C API -------------------------------------------------

struct RawDataset {
  std::vector<hsize_t> shape;
  std::vector<double> values; // integers converted by HDF5 on read
};

bool pathExists(hid_t file, const std::string& path)
{
  // H5Lexists needs every intermediate link to exist: test the prefixes in turn.
  std::size_t pos = 1;
  while (true) {
    const std::size_t next = path.find('/', pos);
    const std::string prefix = path.substr(0, next);
    if (H5Lexists(file, prefix.c_str(), H5P_DEFAULT) <= 0) {
      return false;
    }
    if (next == std::string::npos) {
      return true;
    }
    pos = next + 1;
  }
}

RawDataset readRaw(const std::string& fileName, const std::string& path)
{
  RawDataset d;
  const hid_t file = H5Fopen(fileName.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) {
    throw std::runtime_error("cannot open " + fileName);
  }
  if (!pathExists(file, path)) {
    H5Fclose(file);
    throw std::runtime_error("no dataset " + path + " in " + fileName);
  }
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  const hid_t space = H5Dget_space(set);
  d.shape.resize(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
  H5Sget_simple_extent_dims(space, d.shape.data(), nullptr);
  d.values.resize(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, d.values.data());
  H5Sclose(space);
  H5Dclose(set);
  H5Fclose(file);
  return d;
}

double rawAttribute(const std::string& fileName, const std::string& object, const std::string& name)
{
  const hid_t file = H5Fopen(fileName.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t attribute = H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  double value = std::nan("");
  H5Aread(attribute, H5T_NATIVE_DOUBLE, &value);
  H5Aclose(attribute);
  H5Fclose(file);
  return value;
}

/// Names of the members of a group, sorted.
std::vector<std::string> rawMembers(const std::string& fileName, const std::string& group)
{
  std::vector<std::string> names;
  const hid_t file = H5Fopen(fileName.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) {
    throw std::runtime_error("cannot open " + fileName);
  }
  H5G_info_t info;
  H5Gget_info_by_name(file, group.c_str(), &info, H5P_DEFAULT);
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    char name[256] = {};
    H5Lget_name_by_idx(file, group.c_str(), H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof(name), H5P_DEFAULT);
    names.emplace_back(name);
  }
  H5Fclose(file);
  return names;
}

// ---- A minimal XML reader for the XDMF ----------------------------------------------

struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;
  std::vector<XmlElement> children;
};

/// Parses elements, attributes and text (no comments, CDATA or entities other than the
/// five predefined ones); throws std::runtime_error on any nesting or syntax error.
class XmlReader {
public:
  explicit XmlReader(std::string text) : s_(std::move(text)) {}

  XmlElement document()
  {
    skipSpace();
    if (s_.compare(pos_, 5, "<?xml") == 0) {
      pos_ = s_.find("?>", pos_);
      if (pos_ == std::string::npos) {
        fail("unterminated declaration");
      }
      pos_ += 2;
    }
    skipSpace();
    XmlElement root = element();
    skipSpace();
    if (pos_ != s_.size()) {
      fail("content after the root element");
    }
    return root;
  }

private:
  [[noreturn]] void fail(const std::string& why)
  {
    throw std::runtime_error("XML error at " + std::to_string(pos_) + ": " + why);
  }
  void skipSpace()
  {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_])) != 0) {
      ++pos_;
    }
  }
  std::string name()
  {
    const std::size_t start = pos_;
    while (pos_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[pos_])) != 0 || s_[pos_] == '_' ||
                                s_[pos_] == ':' || s_[pos_] == '-')) {
      ++pos_;
    }
    if (pos_ == start) {
      fail("expected a name");
    }
    return s_.substr(start, pos_ - start);
  }
  std::string unescape(const std::string& t)
  {
    std::string out;
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (t[i] == '<') {
        fail("'<' in text");
      }
      if (t[i] != '&') {
        out += t[i];
        continue;
      }
      const std::size_t end = t.find(';', i);
      const std::string entity = t.substr(i, end - i + 1);
      const std::map<std::string, char> known = {
          {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
      if (end == std::string::npos || known.count(entity) == 0) {
        fail("unknown entity");
      }
      out += known.at(entity);
      i = end;
    }
    return out;
  }
  XmlElement element()
  {
    if (s_[pos_] != '<') {
      fail("expected '<'");
    }
    ++pos_;
    XmlElement e;
    e.name = name();
    while (true) {
      skipSpace();
      if (s_.compare(pos_, 2, "/>") == 0) {
        pos_ += 2;
        return e;
      }
      if (s_[pos_] == '>') {
        ++pos_;
        break;
      }
      const std::string key = name();
      skipSpace();
      if (s_[pos_++] != '=' || s_[pos_++] != '"') {
        fail("expected =\"");
      }
      const std::size_t end = s_.find('"', pos_);
      if (!e.attributes.emplace(key, unescape(s_.substr(pos_, end - pos_))).second) {
        fail("duplicate attribute " + key);
      }
      pos_ = end + 1;
    }
    while (true) {
      const std::size_t lt = s_.find('<', pos_);
      if (lt == std::string::npos) {
        fail("unterminated element " + e.name);
      }
      e.text += unescape(s_.substr(pos_, lt - pos_));
      pos_ = lt;
      if (s_.compare(pos_, 2, "</") == 0) {
        pos_ += 2;
        if (name() != e.name) {
          fail("mismatched closing tag for " + e.name);
        }
        skipSpace();
        if (s_[pos_++] != '>') {
          fail("expected '>'");
        }
        return e;
      }
      e.children.push_back(element());
    }
  }

  std::string s_;
  std::size_t pos_ = 0;
};

void collect(const XmlElement& e, const std::string& name, std::vector<const XmlElement*>& out)
{
  if (e.name == name) {
    out.push_back(&e);
  }
  for (const auto& c : e.children) {
    collect(c, name, out);
  }
}

std::string trimmed(const std::string& t)
{
  const auto b = t.find_first_not_of(" \n\t");
  const auto e = t.find_last_not_of(" \n\t");
  return b == std::string::npos ? "" : t.substr(b, e - b + 1);
}

std::string shapeText(const std::vector<hsize_t>& shape)
{
  std::ostringstream out;
  for (std::size_t i = 0; i < shape.size(); ++i) {
    out << (i > 0 ? " " : "") << shape[i];
  }
  return out.str();
}

std::size_t valueCount(const std::vector<hsize_t>& shape)
{
  std::size_t n = 1;
  for (const hsize_t d : shape) {
    n *= static_cast<std::size_t>(d);
  }
  return n;
}

std::vector<hsize_t> shapeOf(const std::string& dimensions)
{
  std::istringstream in(dimensions);
  std::vector<hsize_t> shape;
  for (hsize_t d = 0; in >> d;) {
    shape.push_back(d);
  }
  return shape;
}

/// Every DataItem names "file.h5:/path" of an existing dataset and as many values: with the
/// dataset's own shape, except a structured grid's attributes, whose Dimensions are the
/// grid's (SnapshotSeries.StructuredGridAttributesHaveTheGridShape); returns how many were
/// checked.
std::size_t checkXdmfReferences(const std::string& directory, const XmlElement& root)
{
  std::vector<const XmlElement*> items;
  collect(root, "DataItem", items);
  for (const XmlElement* item : items) {
    EXPECT_EQ(item->attributes.at("Format"), "HDF");
    const std::string reference = trimmed(item->text);
    const auto colon = reference.find(':');
    EXPECT_NE(colon, std::string::npos) << reference;
    const std::string file = directory + "/" + reference.substr(0, colon);
    const RawDataset d = readRaw(file, reference.substr(colon + 1));
    const std::string& dimensions = item->attributes.at("Dimensions");
    EXPECT_EQ(valueCount(shapeOf(dimensions)), valueCount(d.shape)) << reference;
    if (reference.find("/wall/") == std::string::npos || reference.find("_fields/") == std::string::npos) {
      EXPECT_EQ(dimensions, shapeText(d.shape)) << reference;
    }
  }
  return items.size();
}

/// Every value of `b` equals `a` (bit for bit: nothing is converted on the way).
void expectSameSnapshot(const io::Snapshot& a, const io::Snapshot& b)
{
  EXPECT_EQ(b.time, a.time);
  EXPECT_EQ(b.step, a.step);
  ASSERT_EQ(b.blocks.size(), a.blocks.size());
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    const auto& x = a.blocks[i];
    const auto& y = b.blocks[i];
    EXPECT_EQ(y.name, x.name);
    EXPECT_EQ(y.topology, x.topology);
    EXPECT_EQ(y.dimension, x.dimension);
    EXPECT_EQ(y.positions, x.positions);
    EXPECT_EQ(y.connectivity, x.connectivity);
    EXPECT_EQ(y.nodesPerPolyline, x.nodesPerPolyline);
    EXPECT_EQ(y.gridShape, x.gridShape);
    for (const auto& [xs, ys] : {std::pair{&x.nodeFields, &y.nodeFields}, std::pair{&x.cellFields, &y.cellFields}}) {
      ASSERT_EQ(ys->size(), xs->size());
      for (std::size_t f = 0; f < xs->size(); ++f) {
        EXPECT_EQ((*ys)[f].name, (*xs)[f].name); // in write order
        EXPECT_EQ((*ys)[f].components, (*xs)[f].components);
        EXPECT_EQ((*ys)[f].values, (*xs)[f].values);
      }
    }
  }
}

/// The Time values of an XDMF document, in order.
std::vector<std::string> xdmfTimes(const std::string& xdmfPath)
{
  const XmlElement root = XmlReader(io::testing::readText(xdmfPath)).document();
  std::vector<const XmlElement*> times;
  collect(root, "Time", times);
  std::vector<std::string> values;
  for (const XmlElement* t : times) {
    values.push_back(t->attributes.at("Value"));
  }
  return values;
}

} // namespace

TEST(SnapshotFile, DatasetsReadBackExactlyWithThePlainHdf5Api)
{
  TemporaryDirectory dir("snapshot_raw");
  const std::string path = dir.file("snapshots.h5");
  io::createSnapshotFile(path);
  const io::Snapshot s = sampleSnapshot(0.75, 42);
  const io::SnapshotLayout layout = io::appendSnapshot(path, s);
  EXPECT_EQ(layout.group, "/snapshots/000000");
  EXPECT_EQ(layout.meshGroup, "/mesh/000000");
  EXPECT_EQ(dir.entryCount(), 1u); // no temporary left behind

  EXPECT_EQ(rawAttribute(path, "/snapshots/000000", "time"), 0.75);
  EXPECT_EQ(rawAttribute(path, "/snapshots/000000", "step"), 42.0);
  EXPECT_EQ(rawAttribute(path, "/snapshots/000000", "mesh"), 0.0);

  const auto& cell = s.blocks[0];
  const RawDataset positions = readRaw(path, "/snapshots/000000/cell0/positions");
  EXPECT_EQ(positions.shape, (std::vector<hsize_t>{9, 3}));
  EXPECT_EQ(positions.values, cell.positions);
  const RawDataset connectivity = readRaw(path, "/mesh/000000/cell0/connectivity");
  EXPECT_EQ(connectivity.shape, (std::vector<hsize_t>{2, 6}));
  for (std::size_t i = 0; i < cell.connectivity.size(); ++i) {
    EXPECT_EQ(connectivity.values[i], static_cast<double>(cell.connectivity[i]));
  }
  const RawDataset velocity = readRaw(path, "/snapshots/000000/cell0/node_fields/velocity");
  EXPECT_EQ(velocity.shape, (std::vector<hsize_t>{9, 3}));
  EXPECT_EQ(velocity.values, cell.nodeFields[0].values);
  const RawDataset tension = readRaw(path, "/snapshots/000000/cell0/node_fields/tension");
  EXPECT_EQ(tension.shape, (std::vector<hsize_t>{9}));
  EXPECT_EQ(tension.values, cell.nodeFields[1].values);
  const RawDataset load = readRaw(path, "/snapshots/000000/cell0/cell_fields/load");
  EXPECT_EQ(load.shape, (std::vector<hsize_t>{2, 3}));
  EXPECT_EQ(load.values, cell.cellFields[0].values);

  EXPECT_EQ(readRaw(path, "/snapshots/000000/contour/positions").shape, (std::vector<hsize_t>{5, 2}));
  EXPECT_EQ(readRaw(path, "/mesh/000000/contour/connectivity").shape, (std::vector<hsize_t>{1, 6}));
  EXPECT_EQ(readRaw(path, "/snapshots/000000/wall/positions").shape, (std::vector<hsize_t>{12, 3}));
  EXPECT_EQ(readRaw(path, "/snapshots/000000/wall/cell_fields/cell_index").shape, (std::vector<hsize_t>{6}));
}

TEST(SnapshotFile, SeveralSnapshotsRoundTripWithTheMeshWrittenOnce)
{
  TemporaryDirectory dir("snapshot_roundtrip");
  const std::string path = dir.file("snapshots.h5");
  io::createSnapshotFile(path);
  std::vector<io::Snapshot> written;
  for (int k = 0; k < 4; ++k) {
    written.push_back(sampleSnapshot(0.25 * k, 3 * k));
    io::appendSnapshot(path, written.back());
  }
  EXPECT_EQ(rawMembers(path, "/mesh"), (std::vector<std::string>{"000000"}));
  EXPECT_EQ(rawMembers(path, "/snapshots"), (std::vector<std::string>{"000000", "000001", "000002", "000003"}));
  const auto layouts = io::readSnapshotLayouts(path);
  ASSERT_EQ(layouts.size(), 4u);
  for (std::size_t k = 0; k < written.size(); ++k) {
    EXPECT_EQ(layouts[k].time, written[k].time);
    EXPECT_EQ(layouts[k].meshGroup, "/mesh/000000");
    expectSameSnapshot(written[k], io::readSnapshot(path, k));
  }
  EXPECT_THROW(io::readSnapshot(path, 4), core::IoError);
}

TEST(SnapshotFile, ChangedConnectivityGetsANewMeshVersion)
{
  TemporaryDirectory dir("snapshot_remesh");
  const std::string path = dir.file("snapshots.h5");
  io::createSnapshotFile(path);
  const io::Snapshot before = sampleSnapshot(0.0, 0);
  io::Snapshot after = sampleSnapshot(0.5, 1);
  after.blocks[0].connectivity = {0, 1, 3, 4, 6, 8, // the square split along the other diagonal
                                  1, 2, 3, 5, 7, 6};
  io::appendSnapshot(path, before);
  EXPECT_EQ(io::appendSnapshot(path, after).meshGroup, "/mesh/000001");
  EXPECT_EQ(io::appendSnapshot(path, after).meshGroup, "/mesh/000001"); // unchanged again: reused
  EXPECT_EQ(rawMembers(path, "/mesh"), (std::vector<std::string>{"000000", "000001"}));
  expectSameSnapshot(before, io::readSnapshot(path, 0));
  expectSameSnapshot(after, io::readSnapshot(path, 1));
  expectSameSnapshot(after, io::readSnapshot(path, 2));
}

TEST(SnapshotFile, InconsistentBlocksAreRefusedBeforeWriting)
{
  TemporaryDirectory dir("snapshot_bad");
  const std::string path = dir.file("snapshots.h5");
  io::createSnapshotFile(path);
  io::appendSnapshot(path, sampleSnapshot(0.0, 0));
  const std::string before = io::testing::readText(path);
  io::Snapshot s = sampleSnapshot(0.5, 1);
  s.blocks[0].connectivity[3] = 9; // node 9 of 9
  try {
    io::appendSnapshot(path, s);
    FAIL() << "a connectivity index out of range was written";
  } catch (const core::Error& e) {
    EXPECT_TRUE(io::testing::contains(e.what(), "'cell0'")) << e.what();
  }
  s = sampleSnapshot(0.5, 1);
  s.blocks[0].nodeFields[0].values.pop_back();
  EXPECT_THROW(io::appendSnapshot(path, s), core::Error);
  s = sampleSnapshot(0.5, 1);
  s.blocks[1].name = "contour/0";
  EXPECT_THROW(io::appendSnapshot(path, s), core::Error);
  s = sampleSnapshot(0.5, 1);
  s.blocks[1].name = s.blocks[0].name;
  EXPECT_THROW(io::appendSnapshot(path, s), core::Error);
  EXPECT_EQ(io::testing::readText(path), before); // the file was not even opened for writing
  EXPECT_EQ(dir.entryCount(), 1u);
}

TEST(SnapshotFile, ReadingSomethingElseNamesTheFile)
{
  TemporaryDirectory dir("snapshot_other");
  const std::string text = dir.file("notes.h5");
  std::ofstream(text) << "not hdf5";
  const std::string other = dir.file("other.h5");
  const hid_t file = H5Fcreate(other.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  H5Fclose(file);
  for (const auto& path : {text, other, dir.file("missing.h5")}) {
    try {
      io::readSnapshotLayouts(path);
      FAIL() << path << " was read as a snapshot file";
    } catch (const core::IoError& e) {
      EXPECT_TRUE(io::testing::contains(e.what(), path)) << e.what();
    }
    EXPECT_THROW(io::appendSnapshot(path, sampleSnapshot(0.0, 0)), core::IoError);
  }
}

TEST(SnapshotSeries, XdmfIsWellFormedAndReferencesExistingDatasets)
{
  TemporaryDirectory dir("series_xdmf");
  io::SnapshotSeries series(dir.path().string(), "snapshots");
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(series.write(sampleSnapshot(0.5 * k, 10 * k)), static_cast<std::size_t>(k));
  }
  EXPECT_EQ(dir.entryCount(), 2u); // snapshots.h5 and snapshots.xdmf, no temporaries
  const XmlElement root = XmlReader(io::testing::readText(series.xdmfPath())).document();
  EXPECT_EQ(root.name, "Xdmf");
  std::vector<const XmlElement*> topologies, grids;
  collect(root, "Topology", topologies);
  collect(root, "Grid", grids);
  EXPECT_EQ(xdmfTimes(series.xdmfPath()), (std::vector<std::string>{"0", "0.5", "1"}));
  EXPECT_EQ(grids.size(), 1u + 3u * (1u + 3u)); // temporal, 3 spatial, 3 blocks each
  ASSERT_EQ(topologies.size(), 9u);
  EXPECT_EQ(topologies[0]->attributes.at("TopologyType"), "Triangle_6");
  EXPECT_EQ(topologies[0]->attributes.at("NumberOfElements"), "2");
  EXPECT_EQ(trimmed(topologies[0]->children.at(0).text), "snapshots.h5:/mesh/000000/cell0/connectivity");
  EXPECT_EQ(topologies[1]->attributes.at("TopologyType"), "Polyline");
  EXPECT_EQ(topologies[1]->attributes.at("NodesPerElement"), "6");
  EXPECT_EQ(topologies[2]->attributes.at("TopologyType"), "2DSMesh");
  EXPECT_EQ(topologies[2]->attributes.at("Dimensions"), "3 4");
  // 3 snapshots x (cell: 2 + 3 fields, contour: 2 + 1, wall: 1 + 2) DataItems, all in
  // the one file.
  EXPECT_EQ(checkXdmfReferences(dir.path().string(), root), 3u * (5u + 3u + 3u));
}

// ParaView's legacy XDMF reader (Xdmf2) took the first dimension of a structured grid's
// attribute as its number of tuples: the demo's wall map, "Dimensions=425" on a 17 x 25 grid,
// was read as 17 of its 425 values. Its attributes now carry the grid's shape: nodes "3 4",
// cells "2 3" on the sample's 3 x 4 grid (tests/figures checks both of ParaView's readers).
TEST(SnapshotSeries, StructuredGridAttributesHaveTheGridShape)
{
  TemporaryDirectory dir("series_structured_dims");
  io::SnapshotSeries series(dir.path().string(), "snapshots");
  series.write(sampleSnapshot(0.0, 0));
  const XmlElement root = XmlReader(io::testing::readText(series.xdmfPath())).document();
  std::vector<const XmlElement*> attributes;
  collect(root, "Attribute", attributes);
  std::map<std::string, std::string> wall;
  for (const XmlElement* a : attributes) {
    const std::string reference = trimmed(a->children.at(0).text);
    if (reference.find("/wall/") != std::string::npos) {
      wall[a->attributes.at("Name")] = a->children.at(0).attributes.at("Dimensions");
    }
  }
  EXPECT_EQ(wall, (std::map<std::string, std::string>{{"wall_shear_stress", "3 4"}, {"cell_index", "2 3"}}));
}

TEST(SnapshotSeries, RestartTruncatesTheSnapshotsAfterTheCheckpoint)
{
  TemporaryDirectory dir("series_restart");
  {
    io::SnapshotSeries series(dir.path().string(), "snapshots");
    for (int k = 0; k < 5; ++k) {
      series.write(sampleSnapshot(0.5 * k, k)); // t = 0 .. 2
    }
  }
  auto series = io::SnapshotSeries::resume(dir.path().string(), "snapshots", 1.0);
  EXPECT_EQ(series.size(), 3u); // t = 0, 0.5, 1
  EXPECT_EQ(rawMembers(series.filePath(), "/snapshots"), (std::vector<std::string>{"000000", "000001", "000002"}));
  EXPECT_EQ(xdmfTimes(series.xdmfPath()), (std::vector<std::string>{"0", "0.5", "1"}));
  EXPECT_EQ(series.write(sampleSnapshot(1.5, 3)), 3u);
  EXPECT_EQ(xdmfTimes(series.xdmfPath()), (std::vector<std::string>{"0", "0.5", "1", "1.5"}));
  checkXdmfReferences(dir.path().string(), XmlReader(io::testing::readText(series.xdmfPath())).document());
  EXPECT_EQ(io::readSnapshot(series.filePath(), 3).time, 1.5);
  EXPECT_EQ(dir.entryCount(), 2u);
}

TEST(SnapshotSeries, RestartedSeriesEqualsTheUninterruptedOne)
{
  TemporaryDirectory whole("series_whole"), restarted("series_restarted");
  std::vector<io::Snapshot> run;
  for (int k = 0; k < 5; ++k) {
    run.push_back(sampleSnapshot(0.5 * k, k));
  }
  {
    io::SnapshotSeries series(whole.path().string(), "snapshots");
    for (const auto& s : run) {
      series.write(s);
    }
  }
  {
    // The interrupted run: checkpoint at t = 1 (snapshot 2), one more snapshot, then stop.
    io::SnapshotSeries series(restarted.path().string(), "snapshots");
    for (int k = 0; k < 4; ++k) {
      series.write(run[static_cast<std::size_t>(k)]);
    }
  }
  auto series = io::SnapshotSeries::resume(restarted.path().string(), "snapshots", 1.0);
  for (std::size_t k = 3; k < run.size(); ++k) {
    series.write(run[k]);
  }
  const std::string wholeFile = whole.file("snapshots.h5");
  const std::string restartedFile = restarted.file("snapshots.h5");
  ASSERT_EQ(io::readSnapshotLayouts(restartedFile).size(), run.size());
  for (std::size_t k = 0; k < run.size(); ++k) {
    expectSameSnapshot(io::readSnapshot(wholeFile, k), io::readSnapshot(restartedFile, k));
  }
  EXPECT_EQ(io::testing::readText(restarted.file("snapshots.xdmf")),
            io::testing::readText(whole.file("snapshots.xdmf")));
}

TEST(SnapshotSeries, RunStoppedBetweenFileAndXdmfLeavesBothReadable)
{
  TemporaryDirectory dir("series_stopped");
  {
    io::SnapshotSeries series(dir.path().string(), "snapshots");
    series.write(sampleSnapshot(0.0, 0));
    series.write(sampleSnapshot(0.5, 1));
    // The third snapshot reaches the file, then the run dies before the XDMF update.
    io::appendSnapshot(series.filePath(), sampleSnapshot(1.0, 2));
  }
  const std::string file = dir.file("snapshots.h5"), xdmf = dir.file("snapshots.xdmf");
  EXPECT_EQ(io::readSnapshotLayouts(file).size(), 3u);
  EXPECT_EQ(xdmfTimes(xdmf), (std::vector<std::string>{"0", "0.5"}));
  EXPECT_EQ(checkXdmfReferences(dir.path().string(), XmlReader(io::testing::readText(xdmf)).document()), 2u * 11u);
  // Restart from a checkpoint at t = 1: the snapshot is kept and the XDMF names it again.
  auto series = io::SnapshotSeries::resume(dir.path().string(), "snapshots", 1.0);
  EXPECT_EQ(xdmfTimes(xdmf), (std::vector<std::string>{"0", "0.5", "1"}));
  series.write(sampleSnapshot(1.5, 3));
  EXPECT_EQ(checkXdmfReferences(dir.path().string(), XmlReader(io::testing::readText(xdmf)).document()), 4u * 11u);
}

TEST(SnapshotSeries, BytesOfAnAppendKilledBeforeItsFlushAreHarmless)
{
  TemporaryDirectory dir("series_killed");
  const io::Snapshot first = sampleSnapshot(0.0, 0), second = sampleSnapshot(0.5, 1);
  {
    io::SnapshotSeries series(dir.path().string(), "snapshots");
    series.write(first);
    series.write(second);
  }
  // A writer killed before its flush leaves raw data past the end of the file that
  // HDF5's metadata does not reach: simulate it with 64 kB of junk.
  const std::string file = dir.file("snapshots.h5");
  {
    std::ofstream out(file, std::ios::binary | std::ios::app);
    for (int i = 0; i < 65536; ++i) {
      out.put(static_cast<char>(i * 37));
    }
  }
  ASSERT_EQ(io::readSnapshotLayouts(file).size(), 2u);
  auto series = io::SnapshotSeries::resume(dir.path().string(), "snapshots", 0.5);
  EXPECT_EQ(series.size(), 2u);
  const io::Snapshot third = sampleSnapshot(1.0, 2);
  series.write(third);
  expectSameSnapshot(first, io::readSnapshot(file, 0));
  expectSameSnapshot(second, io::readSnapshot(file, 1));
  expectSameSnapshot(third, io::readSnapshot(file, 2));
}

/// Runs `write` in a child process that the kernel kills (SIGXFSZ) at its first write at
/// or past byte `limit` of any file (RLIMIT_FSIZE); returns whether it was killed.
template <typename Write>
bool killedAtByte(long long limit, Write write)
{
  const pid_t child = fork();
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_DFL);
    const rlimit noCore{0, 0};
    setrlimit(RLIMIT_CORE, &noCore);
    const rlimit fileSize{static_cast<rlim_t>(limit), static_cast<rlim_t>(limit)};
    setrlimit(RLIMIT_FSIZE, &fileSize);
    try {
      write();
    } catch (...) {
      _exit(2);
    }
    _exit(0);
  }
  int status = 0;
  waitpid(child, &status, 0);
  const bool killed = WIFSIGNALED(status) && WTERMSIG(status) == SIGXFSZ;
  EXPECT_TRUE(killed || (WIFEXITED(status) && WEXITSTATUS(status) == 0)) << "status " << status;
  return killed;
}

TEST(SnapshotSeries, AWriterKilledAnywhereInAnAppendLosesNothing)
{
  // A child process appends a snapshot and is killed part-way, at many points: raising
  // the byte limit step by step moves the kill through the append (its new data and
  // metadata past the end of the file). After each kill the next writer must find the
  // two earlier snapshots intact and be able to append again.
  TemporaryDirectory dir("series_killed_append");
  const std::string file = dir.file("snapshots.h5");
  const io::Snapshot first = sampleSnapshot(0.0, 0), second = sampleSnapshot(0.5, 1), third = sampleSnapshot(1.0, 2);
  const std::string pristine = dir.file("pristine.h5");
  io::createSnapshotFile(pristine);
  io::appendSnapshot(pristine, first);
  io::appendSnapshot(pristine, second);
  const auto startingFile = [&] {
    std::filesystem::copy_file(pristine, file, std::filesystem::copy_options::overwrite_existing);
    return static_cast<long long>(std::filesystem::file_size(file));
  };
  const long long before = startingFile();
  io::appendSnapshot(file, third);
  const long long growth = static_cast<long long>(std::filesystem::file_size(file)) - before;
  ASSERT_GT(growth, 0);
  int killed = 0, finished = 0;
  for (long long extra = 0; extra <= growth + 1024; extra += growth / 16) {
    const long long size = startingFile();
    const bool wasKilled = killedAtByte(size + extra, [&] { io::appendSnapshot(file, third); });
    killed += wasKilled ? 1 : 0;
    finished += wasKilled ? 0 : 1;
    auto series = io::SnapshotSeries::resume(dir.path().string(), "snapshots", 10.0);
    ASSERT_EQ(series.size(), wasKilled ? 2u : 3u) << "limit " << extra << " bytes past the file";
    expectSameSnapshot(first, io::readSnapshot(file, 0));
    expectSameSnapshot(second, io::readSnapshot(file, 1));
    series.write(sampleSnapshot(2.0, 3));
    EXPECT_EQ(io::readSnapshot(file, series.size() - 1).time, 2.0);
    EXPECT_FALSE(std::filesystem::exists(file + ".undo"));
  }
  std::printf("%d kills, %d appends finished\n", killed, finished);
  EXPECT_GT(killed, 0);
  EXPECT_GT(finished, 0); // the largest limits let the append through
}

TEST(SnapshotSeries, AWriterKilledWhileTruncatingLosesNothing)
{
  // Removing snapshots (restart truncation) copies the kept ones into a new file that
  // replaces the old one only once complete. The byte limit moves the kill through that
  // copy; after each kill the file must be exactly as before (the file itself is never
  // written, so no journal is left), the killed writer's temporary file is all that
  // remains of it, and after a finished truncation the file holds exactly the kept snapshots.
  TemporaryDirectory dir("series_killed_truncation");
  const std::string file = dir.file("snapshots.h5");
  std::vector<io::Snapshot> written;
  for (int k = 0; k < 5; ++k) {
    written.push_back(sampleSnapshot(0.5 * k, k));
  }
  const std::string pristine = dir.file("pristine.h5");
  io::createSnapshotFile(pristine);
  for (const auto& s : written) {
    io::appendSnapshot(pristine, s);
  }
  const auto size = static_cast<long long>(std::filesystem::file_size(pristine));
  int killed = 0, finished = 0;
  // Limits 0, 100, 125, 156, ..., then the whole file.
  std::vector<long long> limits{0};
  for (double limit = 100; limit < size; limit *= 1.25) {
    limits.push_back(static_cast<long long>(limit));
  }
  limits.push_back(size);
  for (const long long limit : limits) {
    std::filesystem::copy_file(pristine, file, std::filesystem::copy_options::overwrite_existing);
    const bool wasKilled = killedAtByte(limit, [&] { io::truncateSnapshots(file, 2); });
    killed += wasKilled ? 1 : 0;
    finished += wasKilled ? 0 : 1;
    EXPECT_FALSE(std::filesystem::exists(file + ".undo")) << "limit " << limit;
    const std::size_t leftovers = core::removeStaleTemporaryFiles(dir.path().string()).size();
    EXPECT_LE(leftovers, wasKilled ? 1u : 0u) << "limit " << limit;
    const std::size_t count = io::readSnapshotLayouts(file).size();
    ASSERT_EQ(count, wasKilled ? 5u : 2u) << "limit " << limit;
    for (std::size_t k = 0; k < count; ++k) {
      expectSameSnapshot(written[k], io::readSnapshot(file, k));
    }
  }
  std::printf("%d kills, %d truncations finished\n", killed, finished);
  EXPECT_GT(killed, 0);
  EXPECT_GT(finished, 0);
  // The truncated file has the size of what it holds, not of what it held.
  EXPECT_LT(static_cast<long long>(std::filesystem::file_size(file)), size);
}

TEST(SnapshotSeries, ADamagedFileIsNamedOnRestart)
{
  TemporaryDirectory dir("series_damaged");
  {
    io::SnapshotSeries series(dir.path().string(), "snapshots");
    series.write(sampleSnapshot(0.0, 0));
  }
  const std::string file = dir.file("snapshots.h5");
  std::filesystem::resize_file(file, 512); // the superblock survives, the rest is gone
  try {
    io::SnapshotSeries::resume(dir.path().string(), "snapshots", 1.0);
    FAIL() << "a damaged snapshot file was continued";
  } catch (const core::IoError& e) {
    EXPECT_TRUE(io::testing::contains(e.what(), file)) << e.what();
    EXPECT_TRUE(io::testing::contains(e.what(), "move")) << e.what();
  }
}

TEST(SnapshotSeries, RestartIntoAnotherDirectoryCarriesTheSeriesOver)
{
  TemporaryDirectory from("series_from"), to("series_to");
  {
    io::SnapshotSeries series(from.path().string(), "snapshots");
    for (int k = 0; k < 3; ++k) {
      series.write(sampleSnapshot(0.5 * k, k));
    }
  }
  auto series = io::SnapshotSeries::resume(to.path().string(), "snapshots", 0.5, from.path().string());
  EXPECT_EQ(series.size(), 2u);
  series.write(sampleSnapshot(1.25, 5));
  EXPECT_EQ(xdmfTimes(to.file("snapshots.xdmf")), (std::vector<std::string>{"0", "0.5", "1.25"}));
  EXPECT_EQ(io::readSnapshotLayouts(from.file("snapshots.h5")).size(), 3u); // the source is untouched
  // Without snapshots in the source (they were off), a new series starts.
  TemporaryDirectory none("series_none");
  EXPECT_EQ(io::SnapshotSeries::resume(to.path().string(), "snapshots", 0.5, none.path().string()).size(), 0u);
}

TEST(SnapshotSeries, ANewSeriesReplacesTheFileOfAnEarlierRun)
{
  TemporaryDirectory dir("series_fresh");
  {
    io::SnapshotSeries old(dir.path().string(), "snapshots");
    for (int k = 0; k < 3; ++k) {
      old.write(sampleSnapshot(k, k));
    }
  }
  std::ofstream(dir.file("snapshots_notes.txt")) << "kept";
  io::SnapshotSeries series(dir.path().string(), "snapshots");
  EXPECT_EQ(io::readSnapshotLayouts(series.filePath()).size(), 0u);
  EXPECT_TRUE(xdmfTimes(series.xdmfPath()).empty());
  series.write(sampleSnapshot(0.0, 0));
  EXPECT_EQ(io::readSnapshotLayouts(series.filePath()).size(), 1u);
  EXPECT_TRUE(std::filesystem::exists(dir.file("snapshots_notes.txt")));
  EXPECT_THROW(io::SnapshotSeries(dir.path().string(), "bad name"), core::InputError);
}

TEST(SnapshotSeries, UnwritableDirectoryIsNamed)
{
  TemporaryDirectory dir("series_unwritable");
  std::ofstream(dir.file("a-file")) << "x";
  const std::string target = dir.file("a-file") + "/out";
  try {
    io::SnapshotSeries series(target, "snapshots");
    FAIL() << "a directory below a regular file was accepted";
  } catch (const core::IoError& e) {
    EXPECT_TRUE(io::testing::contains(e.what(), target)) << e.what();
  }
}
