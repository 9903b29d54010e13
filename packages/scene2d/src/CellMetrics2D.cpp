#include "capsula/scene2d/CellMetrics2D.hpp"

#include "capsula/scene2d/ContourQuadrature2D.hpp"

#include <capsula/contour/ContourMetrics.hpp>

#include <cmath>

namespace capsula::scene2d {

ContourExtremum2D contourMaximum(const contour::Contour& contour, int axis)
{
  const contour::CubicSpline& spline = axis == 0 ? contour.xSpline() : contour.ySpline();
  const std::vector<double>& s = spline.knots();
  ContourExtremum2D best{0, 0.0, spline.piece(0).d};
  const auto consider = [&](int k, double ds, double span) {
    const double v = spline.piece(k).value(ds);
    if (v > best.value) {
      best = {k, ds / span, v};
    }
  };
  for (int k = 0; k < spline.numberOfPieces(); ++k) {
    const contour::CubicPiece& p = spline.piece(k);
    const double span = s[static_cast<std::size_t>(k) + 1] - s[static_cast<std::size_t>(k)];
    consider(k, 0.0, span);
    // Stationary points: 3a ds^2 + 2b ds + c = 0 inside the piece.
    const double qa = 3.0 * p.a, qb = 2.0 * p.b, qc = p.c;
    if (std::abs(qa) < 1e-300) {
      if (std::abs(qb) > 0.0) {
        const double r = -qc / qb;
        if (r > 0.0 && r < span)
          consider(k, r, span);
      }
      continue;
    }
    const double disc = qb * qb - 4.0 * qa * qc;
    if (disc < 0.0) {
      continue;
    }
    const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
    for (const double r : {q / qa, q != 0.0 ? qc / q : -1.0}) {
      if (r > 0.0 && r < span) {
        consider(k, r, span);
      }
    }
  }
  return best;
}

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
  const ContourExtremum2D front = contourMaximum(contour, 0);
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
