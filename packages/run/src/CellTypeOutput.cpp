#include "capsula/run/CellTypeOutput.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/suspension/HeightDistribution.hpp>

#include <algorithm>

namespace capsula::run {

namespace {

constexpr const char* kHeightSum = "suspension.type.height sum";
constexpr const char* kVelocitySum = "suspension.type.velocity sum";
constexpr const char* kDensitySum = "suspension.type.density sum";
constexpr const char* kAveraged = "suspension.type.outputs averaged";

} // namespace

CellTypeOutput::CellTypeOutput(const std::vector<std::string>& cellTypes, const domain::Domain& domain, int bins,
                               double averageFrom)
    : domain_(domain), bins_(bins), averageFrom_(averageFrom)
{
  for (const std::string& type : cellTypes) {
    if (type.empty()) {
      typeOfCell_.push_back(-1);
      continue;
    }
    const auto found = std::find(types_.begin(), types_.end(), type);
    if (found == types_.end()) {
      types_.push_back(type);
      counts_.push_back(0);
    }
    const int index = static_cast<int>(std::find(types_.begin(), types_.end(), type) - types_.begin());
    typeOfCell_.push_back(index);
    ++counts_[static_cast<std::size_t>(index)];
  }
  heightSum_.assign(types_.size(), 0.0);
  velocitySum_.assign(types_.size(), 0.0);
  densitySum_.assign(domain.hasUpperWall() ? types_.size() * static_cast<std::size_t>(bins) : 0, 0.0);
}

std::vector<std::string> CellTypeOutput::columns() const
{
  std::vector<std::string> columns;
  for (const std::string& type : types_) {
    columns.push_back("y_mean_" + type);
    columns.push_back("u_mean_" + type);
  }
  return columns;
}

CellTypeOutput::Sample CellTypeOutput::measure(double t, const std::vector<mesh::Vec3>& centroids,
                                               const std::vector<mesh::Vec3>& velocities)
{
  core::require(centroids.size() == typeOfCell_.size() && velocities.size() == typeOfCell_.size(),
                "internal: CellTypeOutput measures ", typeOfCell_.size(), " cells, not ", centroids.size());
  const std::size_t n = types_.size();
  Sample sample;
  sample.meanHeight.assign(n, 0.0);
  sample.meanVelocity.assign(n, 0.0);
  std::vector<std::vector<double>> heights(n);
  for (std::size_t c = 0; c < typeOfCell_.size(); ++c) {
    const int type = typeOfCell_[c];
    if (type < 0) {
      continue;
    }
    const auto k = static_cast<std::size_t>(type);
    sample.meanHeight[k] += centroids[c][1] / counts_[k];
    sample.meanVelocity[k] += velocities[c][0] / counts_[k];
    heights[k].push_back(centroids[c][1]);
  }
  if (domain_.hasUpperWall()) {
    for (std::size_t k = 0; k < n; ++k) {
      sample.density.push_back(suspension::heightDistribution(heights[k], domain_, bins_).density);
    }
  }
  if (t >= averageFrom_) {
    for (std::size_t k = 0; k < n; ++k) {
      heightSum_[k] += sample.meanHeight[k];
      velocitySum_[k] += sample.meanVelocity[k];
      if (!sample.density.empty()) {
        for (std::size_t b = 0; b < static_cast<std::size_t>(bins_); ++b) {
          densitySum_[k * static_cast<std::size_t>(bins_) + b] += sample.density[k][b];
        }
      }
    }
    ++averaged_;
  }
  return sample;
}

std::vector<double> CellTypeOutput::row(const Sample& sample) const
{
  std::vector<double> row;
  for (std::size_t k = 0; k < types_.size(); ++k) {
    row.push_back(sample.meanHeight[k]);
    row.push_back(sample.meanVelocity[k]);
  }
  return row;
}

std::vector<io::SnapshotBlock> CellTypeOutput::blocks(const Sample& sample) const
{
  std::vector<io::SnapshotBlock> blocks;
  for (std::size_t k = 0; k < sample.density.size(); ++k) {
    io::SnapshotBlock block;
    block.name = "height_" + types_[k];
    block.topology = io::Topology::Polylines;
    block.nodesPerPolyline = bins_;
    for (int b = 0; b < bins_; ++b) {
      block.positions.insert(block.positions.end(), {0.0, domain_.channelHeight() * (b + 0.5) / bins_, 0.0});
      block.connectivity.push_back(b);
    }
    block.nodeFields.push_back({"density", 1, sample.density[k]});
    blocks.push_back(std::move(block));
  }
  return blocks;
}

void CellTypeOutput::addResults(io::JsonValue& summary) const
{
  io::JsonValue& all = summary["cell types"];
  const double outputs = static_cast<double>(averaged_);
  for (std::size_t k = 0; k < types_.size(); ++k) {
    io::JsonValue& type = all[types_[k]];
    type["count"] = static_cast<long long>(counts_[k]);
    type["outputs averaged"] = static_cast<long long>(averaged_);
    if (averaged_ == 0) {
      continue;
    }
    type["y_mean"] = heightSum_[k] / outputs;
    type["u_mean"] = velocitySum_[k] / outputs;
    if (!densitySum_.empty()) {
      std::vector<double> centres, density;
      for (int b = 0; b < bins_; ++b) {
        centres.push_back(domain_.channelHeight() * (b + 0.5) / bins_);
        density.push_back(densitySum_[k * static_cast<std::size_t>(bins_) + static_cast<std::size_t>(b)] / outputs);
      }
      type["height distribution"]["bin centres"] = io::JsonValue::array(centres);
      type["height distribution"]["values"] = io::JsonValue::array(density);
    }
  }
}

void CellTypeOutput::save(io::Checkpoint& checkpoint) const
{
  checkpoint.arrays[kHeightSum] = heightSum_;
  checkpoint.arrays[kVelocitySum] = velocitySum_;
  checkpoint.arrays[kDensitySum] = densitySum_;
  checkpoint.integers[kAveraged] = averaged_;
}

void CellTypeOutput::load(const io::Checkpoint& checkpoint, const std::string& source)
{
  const auto heights = checkpoint.arrays.find(kHeightSum);
  const auto velocities = checkpoint.arrays.find(kVelocitySum);
  const auto densities = checkpoint.arrays.find(kDensitySum);
  const auto count = checkpoint.integers.find(kAveraged);
  core::require<core::IoError>(heights != checkpoint.arrays.end() && velocities != checkpoint.arrays.end() &&
                                   densities != checkpoint.arrays.end() && count != checkpoint.integers.end(),
                               "The checkpoint '", source,
                               "' lacks the cell types' running averages ('suspension.type.'); it was written "
                               "by a run without cell types.");
  core::require<core::IoError>(
      heights->second.size() == heightSum_.size() && densities->second.size() == densitySum_.size(), "The checkpoint '",
      source, "' holds the averages of ", heights->second.size(), " cell types, not ", heightSum_.size(), ".");
  heightSum_ = heights->second;
  velocitySum_ = velocities->second;
  densitySum_ = densities->second;
  averaged_ = count->second;
}

} // namespace capsula::run
