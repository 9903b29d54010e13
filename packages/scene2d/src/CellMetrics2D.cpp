#include "capsula/scene2d/CellMetrics2D.hpp"

#include "capsula/scene2d/ContourQuadrature2D.hpp"

#include <capsula/contour/ContourLocation.hpp>
#include <capsula/contour/ContourMetrics.hpp>

#include <cmath>

namespace capsula::scene2d {

CellMetrics2D cellMetrics2D(const CapsuleModel2D& model, const contour::Contour& contour,
                            const MembraneState2D& membrane, const std::vector<double>& velocities)
{
  CellMetrics2D m;
  m.contourLengthRatio = contour.length() / model.referenceLength();
  m.cellLength = contour::cellLength(contour);
  const Eigen::Vector2d force = membrane.netForce(model.discretisation().gaussLegendrePoints);
  m.tetherForceX = force.x();
  m.tetherForceY = force.y();
  m.tetherForce = force.norm();
  const contour::ContourLocation front = contour::extremePoint(contour, 0, contour::Extreme::Largest).location;
  const ContourField2D velocity(contour, velocities.data());
  m.leadingEdgeVelocity =
      model.flow().conditions.viscosityRatio * velocity.at(front.segment, front.t).x() / flowSemiAxis(model.cell());
  m.area = contour::enclosedArea(contour);
  m.areaDrift = (m.area - model.referenceArea()) / model.referenceArea();
  m.D12 = contour::taylorDeformation(contour);
  const Eigen::Vector2d c = contour::centroid(contour);
  m.centroidX = c.x();
  m.centroidY = c.y();
  m.lowestPoint = contour::extent(contour, 1).min;
  return m;
}

std::vector<std::string> metricColumns()
{
  return {"contour_length_ratio",
          "cell_length",
          "tether_force_x",
          "tether_force_y",
          "tether_force",
          "leading_edge_velocity",
          "area",
          "area_drift",
          "D12",
          "centroid_x",
          "centroid_y",
          "lowest_point"};
}

std::vector<double> metricValues(const CellMetrics2D& m)
{
  return {m.contourLengthRatio,  m.cellLength, m.tetherForceX, m.tetherForceY, m.tetherForce,
          m.leadingEdgeVelocity, m.area,       m.areaDrift,    m.D12,          m.centroidX,
          m.centroidY,           m.lowestPoint};
}

} // namespace capsula::scene2d
