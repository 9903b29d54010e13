#include "capsula/operators/SurfaceQuadrature.hpp"

#include <algorithm>
#include <cmath>

namespace capsula::operators {

SurfaceQuadrature::SurfaceQuadrature(int numQuadraturePoints) : rule_(&quadrature::triangleRule(numQuadraturePoints)) {}

void SurfaceQuadrature::update(const CellSurfaces& surfaces)
{
  positions_ = surfaces.positions();
  const int numElements = surfaces.numElements();
  const int nq = pointsPerElement();
  const std::size_t numPoints = static_cast<std::size_t>(numElements) * nq;

  QuadraturePoints& p = points_;
  for (auto* v : {&p.x, &p.y, &p.z, &p.weight, &p.nx, &p.ny, &p.nz}) {
    v->resize(numPoints);
  }
  p.phi.resize(6 * numPoints);
  ElementData& e = elements_;
  for (auto* v : {&e.cx, &e.cy, &e.cz, &e.radius, &e.size, &e.area}) {
    v->resize(numElements);
  }
  e.shape.resize(numElements);
  e.nodes.resize(numElements);

  for (int m = 0; m < numElements; ++m) {
    e.nodes[m] = surfaces.elementNodes(m);
    const mesh::ElementNodes x = elementNodes(m);
    const mesh::ShapeParameters shape = mesh::shapeParameters(x);
    e.shape[m] = shape;

    mesh::Vec3 centre = mesh::Vec3::Zero();
    for (const auto& node : x) {
      centre += node;
    }
    centre /= 6.0;
    double radius = 0.0;
    for (const auto& node : x) {
      radius = std::max(radius, (node - centre).norm());
    }
    e.size[m] = std::max({(x[1] - x[0]).norm(), (x[2] - x[1]).norm(), (x[0] - x[2]).norm()});

    double area = 0.0;
    for (int k = 0; k < nq; ++k) {
      const std::size_t q = static_cast<std::size_t>(m) * nq + k;
      const double xi = rule_->xi[k];
      const double eta = rule_->eta[k];
      const mesh::SurfacePoint s = mesh::evaluateSurfacePoint(x, shape, xi, eta);
      const double w = rule_->weight[k] * s.metric;
      p.x[q] = s.position[0];
      p.y[q] = s.position[1];
      p.z[q] = s.position[2];
      p.weight[q] = w;
      p.nx[q] = w * s.normal[0];
      p.ny[q] = w * s.normal[1];
      p.nz[q] = w * s.normal[2];
      mesh::shapeFunctions(shape, xi, eta, &p.phi[6 * q]);
      area += w;
      // The curved element can bulge past its nodes: the points bound it too.
      radius = std::max(radius, (s.position - centre).norm());
    }
    e.cx[m] = centre[0];
    e.cy[m] = centre[1];
    e.cz[m] = centre[2];
    e.radius[m] = radius;
    e.area[m] = area;
  }
}

} // namespace capsula::operators
