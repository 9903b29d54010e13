#include "capsula/run/OutputMetrics.hpp"

#include <capsula/scene/CellKinematics.hpp>
#include <capsula/contour/CubicSpline.hpp>

#include <capsula/core/Error.hpp>

#include <algorithm>
#include <cmath>

namespace capsula::run {

namespace core = capsula::core;
using mesh::Vec3;
using scene::centroidVelocity;
using scene::measureShape;
using scene::measureStability;
using scene::membraneStress;
using scene::rigidMotionFit;

namespace {

std::string indexed(const std::string& name, int cell)
{
  return "metrics." + name + "." + std::to_string(cell);
}

} // namespace

double shapeChangeRate(const double* nodeVelocities, const double* nodeNormals, int numNodes,
                       const Vec3& centroidVelocity)
{
  double sum = 0.0;
  for (int i = 0; i < numNodes; ++i) {
    const double normalSpeed = (mesh::nodeAt(nodeVelocities, i) - centroidVelocity).dot(mesh::nodeAt(nodeNormals, i));
    sum += normalSpeed * normalSpeed;
  }
  return numNodes == 0 ? 0.0 : std::sqrt(sum / static_cast<double>(numNodes));
}

OutputMetrics::OutputMetrics(int numCells) : numCells_(numCells), centroids_(static_cast<std::size_t>(numCells)) {}

std::vector<CellSample> OutputMetrics::record(double t, const scene::Scene& scene, const scene::SceneFields& fields)
{
  core::require(scene.numCells() == numCells_, "OutputMetrics: ", scene.numCells(), " cells, expected ", numCells_);
  core::require(times_.empty() || t > times_.back(), "OutputMetrics: output time ", t, " does not follow ",
                times_.empty() ? 0.0 : times_.back());
  const bool first = times_.empty();
  times_.push_back(t);
  std::vector<CellSample> samples(static_cast<std::size_t>(numCells_));
  for (int c = 0; c < numCells_; ++c) {
    CellSample& s = samples[static_cast<std::size_t>(c)];
    const mesh::SurfaceMesh& cell = scene.cell(c);
    const double* velocities = fields.velocities.data() + 3 * static_cast<std::size_t>(scene.nodeOffset(c));
    s.shape = measureShape(cell);
    s.stress = membraneStress(cell, fields.elementLoads.data() + 3 * static_cast<std::size_t>(scene.elementOffset(c)));
    s.instantVelocity = centroidVelocity(cell, velocities);
    s.unconstrainedVelocity =
        centroidVelocity(cell, fields.solverVelocities.data() + 3 * static_cast<std::size_t>(scene.nodeOffset(c)));
    s.rotation = rigidMotionFit(cell, velocities, s.shape.centroid).rotation;
    const double* normals = fields.nodeNormals.data() + 3 * static_cast<std::size_t>(scene.nodeOffset(c));
    s.shapeChangeRate = shapeChangeRate(velocities, normals, cell.numNodes(), s.instantVelocity);
    s.gmresIterations = fields.gmresIterations;
    s.shearRate = scene.description().shearRate.factor(t);
    s.profileAtCentroid = scene.description().flowProfile.velocity(s.shape.centroid[1]);
    s.stability =
        measureStability(cell, fields.membraneExtremes[static_cast<std::size_t>(c)], scene.description().domain);
    if (scene.hasBonds()) {
      s.adhesion = scene.bonds().summary(c, cell, cell.positionData());
    }
    if (scene.hasTether() && scene.tether().cell() == c) {
      const adhesion::TetherState tether = scene.tether().state(cell, cell.positionData());
      s.tether = TetherSample{tether, adhesion::pivotAngleDegrees(tether.anchor, s.shape.centroid)};
    }

    auto& history = centroids_[static_cast<std::size_t>(c)];
    for (int d = 0; d < 3; ++d) {
      history.push_back(s.shape.centroid[d]);
    }
    for (int d = 0; d < 3; ++d) {
      std::vector<double> component(times_.size());
      for (std::size_t k = 0; k < times_.size(); ++k) {
        component[k] = history[3 * k + static_cast<std::size_t>(d)];
      }
      // One sample has no slope: fall back to the instantaneous velocity at t = 0.
      s.splineVelocity[d] = times_.size() > 1 ? contour::CubicSpline::interpolating(times_, component).derivative(t)
                                              : s.instantVelocity[d];
    }
    if (first) {
      initialVolume_.push_back(s.shape.volume);
      initialArea_.push_back(s.shape.area);
      initialMeanStress_.push_back(s.stress.mean);
      initialMaximumStress_.push_back(s.stress.maximum);
    }
    s.volumeChange = s.shape.volume / initialVolume_[static_cast<std::size_t>(c)] - 1.0;
    s.areaChange = s.shape.area / initialArea_[static_cast<std::size_t>(c)] - 1.0;
    s.meanStressIncrease = s.stress.mean - initialMeanStress_[static_cast<std::size_t>(c)];
    s.maximumStressIncrease = s.stress.maximum - initialMaximumStress_[static_cast<std::size_t>(c)];
  }
  return samples;
}

void OutputMetrics::save(io::Checkpoint& checkpoint) const
{
  checkpoint.arrays["metrics.times"] = times_;
  for (int c = 0; c < numCells_; ++c) {
    const auto k = static_cast<std::size_t>(c);
    checkpoint.arrays[indexed("centroids", c)] = centroids_[k];
    if (!initialVolume_.empty()) {
      checkpoint.reals[indexed("initial volume", c)] = initialVolume_[k];
      checkpoint.reals[indexed("initial area", c)] = initialArea_[k];
      checkpoint.reals[indexed("initial mean stress", c)] = initialMeanStress_[k];
      checkpoint.reals[indexed("initial maximum stress", c)] = initialMaximumStress_[k];
    }
  }
}

void OutputMetrics::load(const io::Checkpoint& checkpoint, const std::string& source)
{
  const auto array = [&](const std::string& name) -> const std::vector<double>& {
    const auto it = checkpoint.arrays.find(name);
    core::require<core::IoError>(it != checkpoint.arrays.end(), "The checkpoint '", source, "' lacks the array '", name,
                                 "'; it was not written by this application.");
    return it->second;
  };
  const auto real = [&](const std::string& name) {
    const auto it = checkpoint.reals.find(name);
    core::require<core::IoError>(it != checkpoint.reals.end(), "The checkpoint '", source, "' lacks the value '", name,
                                 "'; it was not written by this application.");
    return it->second;
  };
  times_ = array("metrics.times");
  initialVolume_.clear();
  initialArea_.clear();
  initialMeanStress_.clear();
  initialMaximumStress_.clear();
  for (int c = 0; c < numCells_; ++c) {
    centroids_[static_cast<std::size_t>(c)] = array(indexed("centroids", c));
    core::require<core::IoError>(centroids_[static_cast<std::size_t>(c)].size() == 3 * times_.size(),
                                 "The checkpoint '", source, "' has an inconsistent centroid history.");
    if (!times_.empty()) {
      initialVolume_.push_back(real(indexed("initial volume", c)));
      initialArea_.push_back(real(indexed("initial area", c)));
      initialMeanStress_.push_back(real(indexed("initial mean stress", c)));
      initialMaximumStress_.push_back(real(indexed("initial maximum stress", c)));
    }
  }
}

} // namespace capsula::run
