// HDF5 snapshots and the XDMF sidecar: datasets read back with the plain HDF5 C API
// (independently of the writer's helpers), shapes and values exact; the XDMF is
// well-formed XML whose every data reference names an existing dataset of the stated
// shape; restart drops the snapshots written after the checkpoint.
#include "TemporaryDirectory.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/io/SnapshotFile.hpp"
#include "capsula/io/SnapshotSeries.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cctype>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

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
  b.connectivity = {0, 1, 2, 4, 5, 6,    // lower right triangle
                    0, 2, 3, 6, 7, 8};   // upper left triangle
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
  const double pi = std::acos(-1.0);
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
  std::vector<double> values;   // integers converted by HDF5 on read
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

double rawAttribute(const std::string& fileName, const std::string& name)
{
  const hid_t file = H5Fopen(fileName.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t attribute = H5Aopen(file, name.c_str(), H5P_DEFAULT);
  double value = std::nan("");
  H5Aread(attribute, H5T_NATIVE_DOUBLE, &value);
  H5Aclose(attribute);
  H5Fclose(file);
  return value;
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
  [[noreturn]] void fail(const std::string& why) { throw std::runtime_error("XML error at " + std::to_string(pos_) + ": " + why); }
  void skipSpace()
  {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_])) != 0) {
      ++pos_;
    }
  }
  std::string name()
  {
    const std::size_t start = pos_;
    while (pos_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[pos_])) != 0 || s_[pos_] == '_' || s_[pos_] == ':' || s_[pos_] == '-')) {
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
      const std::map<std::string, char> known = {{"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
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

/// Every DataItem names "file.h5:/path" of an existing dataset with its Dimensions;
/// returns how many were checked.
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
    EXPECT_EQ(item->attributes.at("Dimensions"), shapeText(d.shape)) << reference;
  }
  return items.size();
}

} // namespace

TEST(SnapshotFile, DatasetsReadBackExactlyWithThePlainHdf5Api)
{
  TemporaryDirectory dir("snapshot_raw");
  const std::string path = dir.file("snap.h5");
  const io::Snapshot s = sampleSnapshot(0.75, 42);
  io::writeSnapshotFile(path, s);
  EXPECT_EQ(dir.entryCount(), 1u);

  EXPECT_EQ(rawAttribute(path, "time"), 0.75);
  EXPECT_EQ(rawAttribute(path, "step"), 42.0);

  const auto& cell = s.blocks[0];
  const RawDataset positions = readRaw(path, "/cell0/positions");
  EXPECT_EQ(positions.shape, (std::vector<hsize_t>{9, 3}));
  EXPECT_EQ(positions.values, cell.positions);
  const RawDataset connectivity = readRaw(path, "/cell0/connectivity");
  EXPECT_EQ(connectivity.shape, (std::vector<hsize_t>{2, 6}));
  for (std::size_t i = 0; i < cell.connectivity.size(); ++i) {
    EXPECT_EQ(connectivity.values[i], static_cast<double>(cell.connectivity[i]));
  }
  const RawDataset velocity = readRaw(path, "/cell0/node_fields/velocity");
  EXPECT_EQ(velocity.shape, (std::vector<hsize_t>{9, 3}));
  EXPECT_EQ(velocity.values, cell.nodeFields[0].values);
  const RawDataset tension = readRaw(path, "/cell0/node_fields/tension");
  EXPECT_EQ(tension.shape, (std::vector<hsize_t>{9}));
  EXPECT_EQ(tension.values, cell.nodeFields[1].values);
  const RawDataset load = readRaw(path, "/cell0/cell_fields/load");
  EXPECT_EQ(load.shape, (std::vector<hsize_t>{2, 3}));
  EXPECT_EQ(load.values, cell.cellFields[0].values);

  EXPECT_EQ(readRaw(path, "/contour/positions").shape, (std::vector<hsize_t>{5, 2}));
  EXPECT_EQ(readRaw(path, "/contour/connectivity").shape, (std::vector<hsize_t>{1, 6}));
  EXPECT_EQ(readRaw(path, "/wall/positions").shape, (std::vector<hsize_t>{12, 3}));
  EXPECT_EQ(readRaw(path, "/wall/cell_fields/cell_index").shape, (std::vector<hsize_t>{6}));
}

TEST(SnapshotFile, ReadSnapshotFileRoundTrips)
{
  TemporaryDirectory dir("snapshot_roundtrip");
  const std::string path = dir.file("snap.h5");
  const io::Snapshot s = sampleSnapshot(1.25, 7);
  io::writeSnapshotFile(path, s);
  const io::Snapshot r = io::readSnapshotFile(path);
  EXPECT_EQ(r.time, s.time);
  EXPECT_EQ(r.step, s.step);
  ASSERT_EQ(r.blocks.size(), s.blocks.size());
  for (std::size_t b = 0; b < s.blocks.size(); ++b) {
    const auto& x = s.blocks[b];
    const auto& y = r.blocks[b];
    EXPECT_EQ(y.name, x.name);
    EXPECT_EQ(y.topology, x.topology);
    EXPECT_EQ(y.dimension, x.dimension);
    EXPECT_EQ(y.positions, x.positions);
    EXPECT_EQ(y.connectivity, x.connectivity);
    EXPECT_EQ(y.nodesPerPolyline, x.nodesPerPolyline);
    EXPECT_EQ(y.gridShape, x.gridShape);
    ASSERT_EQ(y.nodeFields.size(), x.nodeFields.size());
    for (std::size_t f = 0; f < x.nodeFields.size(); ++f) {
      EXPECT_EQ(y.nodeFields[f].name, x.nodeFields[f].name);   // in write order
      EXPECT_EQ(y.nodeFields[f].components, x.nodeFields[f].components);
      EXPECT_EQ(y.nodeFields[f].values, x.nodeFields[f].values);
    }
    ASSERT_EQ(y.cellFields.size(), x.cellFields.size());
    for (std::size_t f = 0; f < x.cellFields.size(); ++f) {
      EXPECT_EQ(y.cellFields[f].values, x.cellFields[f].values);
    }
  }
}

TEST(SnapshotFile, InconsistentBlocksAreRefusedBeforeWriting)
{
  TemporaryDirectory dir("snapshot_bad");
  const std::string path = dir.file("snap.h5");
  io::Snapshot s = sampleSnapshot(0.0, 0);
  s.blocks[0].connectivity[3] = 9;   // node 9 of 9
  try {
    io::writeSnapshotFile(path, s);
    FAIL() << "a connectivity index out of range was written";
  } catch (const core::Error& e) {
    EXPECT_TRUE(io::testing::contains(e.what(), "'cell0'")) << e.what();
  }
  s = sampleSnapshot(0.0, 0);
  s.blocks[0].nodeFields[0].values.pop_back();
  EXPECT_THROW(io::writeSnapshotFile(path, s), core::Error);
  s = sampleSnapshot(0.0, 0);
  s.blocks[1].name = "contour/0";
  EXPECT_THROW(io::writeSnapshotFile(path, s), core::Error);
  EXPECT_EQ(dir.entryCount(), 0u);
}

TEST(SnapshotFile, ReadingSomethingElseNamesTheFile)
{
  TemporaryDirectory dir("snapshot_other");
  const std::string text = dir.file("notes.h5");
  std::ofstream(text) << "not hdf5";
  for (const auto& path : {text, dir.file("missing.h5")}) {
    try {
      io::readSnapshotFile(path);
      FAIL() << path << " was read as a snapshot";
    } catch (const core::IoError& e) {
      EXPECT_TRUE(io::testing::contains(e.what(), path)) << e.what();
    }
  }
}

TEST(SnapshotSeries, XdmfIsWellFormedAndReferencesExistingDatasets)
{
  TemporaryDirectory dir("series_xdmf");
  io::SnapshotSeries series(dir.path().string(), "cells");
  for (int k = 0; k < 3; ++k) {
    series.write(sampleSnapshot(0.5 * k, 10 * k));
  }
  EXPECT_EQ(dir.entryCount(), 4u);   // three snapshots and the XDMF, no temporaries
  const XmlElement root = XmlReader(io::testing::readText(series.xdmfPath())).document();
  EXPECT_EQ(root.name, "Xdmf");
  std::vector<const XmlElement*> times, topologies, grids;
  collect(root, "Time", times);
  collect(root, "Topology", topologies);
  collect(root, "Grid", grids);
  ASSERT_EQ(times.size(), 3u);
  EXPECT_EQ(times[0]->attributes.at("Value"), "0");
  EXPECT_EQ(times[1]->attributes.at("Value"), "0.5");
  EXPECT_EQ(times[2]->attributes.at("Value"), "1");
  EXPECT_EQ(grids.size(), 1u + 3u * (1u + 3u));   // temporal, 3 spatial, 3 blocks each
  ASSERT_EQ(topologies.size(), 9u);
  EXPECT_EQ(topologies[0]->attributes.at("TopologyType"), "Triangle_6");
  EXPECT_EQ(topologies[0]->attributes.at("NumberOfElements"), "2");
  EXPECT_EQ(topologies[1]->attributes.at("TopologyType"), "Polyline");
  EXPECT_EQ(topologies[1]->attributes.at("NodesPerElement"), "6");
  EXPECT_EQ(topologies[2]->attributes.at("TopologyType"), "2DSMesh");
  EXPECT_EQ(topologies[2]->attributes.at("Dimensions"), "3 4");
  // 3 snapshots x (cell: 2 + 3 fields, contour: 2 + 1, wall: 1 + 2) DataItems.
  EXPECT_EQ(checkXdmfReferences(dir.path().string(), root), 3u * (5u + 3u + 3u));
}

TEST(SnapshotSeries, RestartDropsSnapshotsAfterTheCheckpoint)
{
  TemporaryDirectory dir("series_restart");
  {
    io::SnapshotSeries series(dir.path().string(), "cells");
    for (int k = 0; k < 5; ++k) {
      series.write(sampleSnapshot(0.5 * k, k));   // t = 0 .. 2
    }
  }
  auto series = io::SnapshotSeries::resume(dir.path().string(), "cells", 1.0);
  EXPECT_EQ(series.size(), 3u);   // t = 0, 0.5, 1
  EXPECT_FALSE(std::filesystem::exists(series.snapshotPath(3)));
  EXPECT_FALSE(std::filesystem::exists(series.snapshotPath(4)));
  const std::string next = series.write(sampleSnapshot(1.5, 3));
  EXPECT_EQ(next, series.snapshotPath(3));
  const XmlElement root = XmlReader(io::testing::readText(series.xdmfPath())).document();
  std::vector<const XmlElement*> times;
  collect(root, "Time", times);
  ASSERT_EQ(times.size(), 4u);
  EXPECT_EQ(times[3]->attributes.at("Value"), "1.5");
  checkXdmfReferences(dir.path().string(), root);
  EXPECT_EQ(io::readSnapshotFile(next).time, 1.5);
}

TEST(SnapshotSeries, ANewSeriesRemovesTheSnapshotsOfAnEarlierRun)
{
  TemporaryDirectory dir("series_fresh");
  {
    io::SnapshotSeries old(dir.path().string(), "cells");
    for (int k = 0; k < 3; ++k) {
      old.write(sampleSnapshot(k, k));
    }
  }
  std::ofstream(dir.file("cells_notes.txt")) << "kept";
  io::SnapshotSeries series(dir.path().string(), "cells");
  series.write(sampleSnapshot(0.0, 0));
  EXPECT_TRUE(std::filesystem::exists(series.snapshotPath(0)));
  EXPECT_FALSE(std::filesystem::exists(series.snapshotPath(1)));
  EXPECT_TRUE(std::filesystem::exists(dir.file("cells_notes.txt")));
  EXPECT_THROW(io::SnapshotSeries(dir.path().string(), "bad name"), core::InputError);
}

TEST(SnapshotSeries, UnwritableDirectoryIsNamed)
{
  TemporaryDirectory dir("series_unwritable");
  std::ofstream(dir.file("a-file")) << "x";
  const std::string target = dir.file("a-file") + "/out";
  try {
    io::SnapshotSeries series(target, "cells");
    FAIL() << "a directory below a regular file was accepted";
  } catch (const core::IoError& e) {
    EXPECT_TRUE(io::testing::contains(e.what(), target)) << e.what();
  }
}
