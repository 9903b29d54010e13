#include "capsula/io/Xdmf.hpp"

#include "capsula/core/XmlText.hpp"
#include "capsula/io/NumberFormat.hpp"

#include <sstream>

namespace capsula::io {

namespace {

std::string dimensions(std::size_t rows, std::size_t columns)
{
  return columns == 1 ? std::to_string(rows) : std::to_string(rows) + " " + std::to_string(columns);
}

void dataItem(std::ostream& out, const std::string& indent, const std::string& dims, bool integer,
              const std::string& fileName, const std::string& dataset)
{
  out << indent << "<DataItem Dimensions=\"" << dims << "\" NumberType=\"" << (integer ? "Int" : "Float")
      << "\" Precision=\"8\" Format=\"HDF\">" << core::xmlEscaped(fileName) << ":" << core::xmlEscaped(dataset)
      << "</DataItem>\n";
}

std::string attributeType(int components)
{
  switch (components) {
  case 1:
    return "Scalar";
  case 2:
  case 3:
    return "Vector";
  case 6:
    return "Tensor6";
  case 9:
    return "Tensor";
  default:
    return "Matrix";
  }
}

// The shape of a field's data item. On a structured grid it is the grid's own shape ("17 25"
// for its nodes, "16 24" for its cells, then the components): the legacy XDMF reader
// (ParaView's XDMFReader, Xdmf2) takes the first dimension of a structured grid's attribute
// as its number of tuples, so "425" was read as 17 values of the 425 nodes.
std::string fieldDimensions(const SnapshotLayout::BlockLayout& block, int components, bool onNodes)
{
  if (block.topology != Topology::StructuredGrid) {
    return dimensions(onNodes ? block.nodes : block.cells, static_cast<std::size_t>(components));
  }
  const std::int64_t shift = onNodes ? 0 : 1;
  std::string dims = std::to_string(block.gridShape[0] - shift) + " " + std::to_string(block.gridShape[1] - shift);
  return components == 1 ? dims : dims + " " + std::to_string(components);
}

void attributes(std::ostream& out, const std::string& fileName, const SnapshotLayout& snapshot,
                const SnapshotLayout::BlockLayout& block, const std::vector<SnapshotLayout::FieldLayout>& fields,
                bool onNodes)
{
  for (const auto& f : fields) {
    out << "          <Attribute Name=\"" << core::xmlEscaped(f.name) << "\" AttributeType=\""
        << attributeType(f.components) << "\" Center=\"" << (onNodes ? "Node" : "Cell") << "\">\n";
    dataItem(out, "            ", fieldDimensions(block, f.components, onNodes), false, fileName,
             snapshot.group + "/" + block.name + (onNodes ? "/node_fields/" : "/cell_fields/") + f.name);
    out << "          </Attribute>\n";
  }
}

void topology(std::ostream& out, const std::string& fileName, const SnapshotLayout& snapshot,
              const SnapshotLayout::BlockLayout& block)
{
  const std::string type = xdmfTopologyName(block.topology);
  if (block.topology == Topology::StructuredGrid) {
    out << "          <Topology TopologyType=\"" << type << "\" Dimensions=\"" << block.gridShape[0] << " "
        << block.gridShape[1] << "\"/>\n";
    return;
  }
  out << "          <Topology TopologyType=\"" << type << "\" NumberOfElements=\"" << block.cells << "\"";
  if (block.topology == Topology::Polylines) {
    out << " NodesPerElement=\"" << block.nodesPerCell << "\"";
  }
  out << ">\n";
  dataItem(out, "            ", dimensions(block.cells, block.nodesPerCell), true, fileName,
           snapshot.meshGroup + "/" + block.name + "/connectivity");
  out << "          </Topology>\n";
}

} // namespace

SnapshotLayout layoutOf(const Snapshot& snapshot, const std::string& group, const std::string& meshGroup)
{
  SnapshotLayout layout;
  layout.group = group;
  layout.meshGroup = meshGroup;
  layout.time = snapshot.time;
  layout.step = snapshot.step;
  for (const auto& b : snapshot.blocks) {
    SnapshotLayout::BlockLayout block;
    block.name = b.name;
    block.topology = b.topology;
    block.dimension = b.dimension;
    block.nodes = b.nodeCount();
    block.cells = b.cellCount();
    block.nodesPerCell = b.nodesPerCell();
    block.gridShape = b.gridShape;
    for (const auto& f : b.nodeFields) {
      block.nodeFields.push_back({f.name, f.components});
    }
    for (const auto& f : b.cellFields) {
      block.cellFields.push_back({f.name, f.components});
    }
    layout.blocks.push_back(std::move(block));
  }
  return layout;
}

std::string xdmfTimeSeries(const std::string& fileName, const std::vector<SnapshotLayout>& snapshots)
{
  std::ostringstream out;
  out << "<?xml version=\"1.0\" ?>\n"
      << "<Xdmf Version=\"3.0\">\n"
      << "  <Domain>\n"
      << "    <Grid Name=\"TimeSeries\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto& snapshot : snapshots) {
    out << "      <Grid Name=\"step " << snapshot.step << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
        << "        <Time Value=\"" << shortestDecimal(snapshot.time) << "\"/>\n";
    for (const auto& block : snapshot.blocks) {
      out << "        <Grid Name=\"" << core::xmlEscaped(block.name) << "\" GridType=\"Uniform\">\n";
      topology(out, fileName, snapshot, block);
      out << "          <Geometry GeometryType=\"" << (block.dimension == 2 ? "XY" : "XYZ") << "\">\n";
      dataItem(out, "            ", dimensions(block.nodes, static_cast<std::size_t>(block.dimension)), false, fileName,
               snapshot.group + "/" + block.name + "/positions");
      out << "          </Geometry>\n";
      attributes(out, fileName, snapshot, block, block.nodeFields, true);
      attributes(out, fileName, snapshot, block, block.cellFields, false);
      out << "        </Grid>\n";
    }
    out << "      </Grid>\n";
  }
  out << "    </Grid>\n"
      << "  </Domain>\n"
      << "</Xdmf>\n";
  return out.str();
}

} // namespace capsula::io
