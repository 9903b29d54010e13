#pragma once
// What the Chapter 4 study measures on the cell at an output time (all dimensionless:
// lengths in L, velocities in k L, forces in E, membrane tension in E):
//   contour length ratio  A/A0, the contour length over the reference's (Fig. 4.7);
//   cell length           L_cell = x_max - x_min over the spline (eq 4.2);
//   tether force          F = int_C Delta f dl (eq A.56). Loads are in E/L (the thesis's
//                         stress scale), so this is F/E as plotted in Figs. 4.15-4.18;
//                         F/(mu k L) = (F/E) / Ca. Zero (to quadrature) on a free cell;
//   leading-edge velocity lambda U_cell / (k a): U_cell the x-velocity of the point of
//                         largest x (the velocity spline there: by the envelope theorem
//                         that is d x_max / dt), a = sqrt(a/b) the semi-axis along x;
//   area, area drift      enclosed area and (A - A_ref)/A_ref;
//   D12                   Taylor deformation of the equivalent ellipse (eq A.53).
#include "capsula/scene2d/CapsuleModel2D.hpp"
#include "capsula/scene2d/MembraneState2D.hpp"

#include <capsula/contour/Contour.hpp>

#include <string>
#include <vector>

namespace capsula::scene2d {

struct CellMetrics2D {
  double contourLengthRatio = 0.0;
  double cellLength = 0.0;
  double tetherForceX = 0.0;
  double tetherForceY = 0.0;
  double tetherForce = 0.0;
  double leadingEdgeVelocity = 0.0;
  double area = 0.0;
  double areaDrift = 0.0;
  double D12 = 0.0;
  double centroidX = 0.0;
  double centroidY = 0.0;
  double lowestPoint = 0.0; ///< smallest y of the spline (the gap to the wall)
};

/// The metrics of one state. `velocities`: 2 per node, of the same state.
CellMetrics2D cellMetrics2D(const CapsuleModel2D& model, const contour::Contour& contour,
                            const MembraneState2D& membrane, const std::vector<double>& velocities);

/// metrics.csv columns after time, step and dt, in the order of metricValues().
std::vector<std::string> metricColumns();
std::vector<double> metricValues(const CellMetrics2D& metrics);

} // namespace capsula::scene2d
