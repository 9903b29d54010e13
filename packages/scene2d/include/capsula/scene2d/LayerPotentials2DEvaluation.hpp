#pragma once
// Part of LayerPotentials2D.hpp, included at its end: the single and double
// layers at the nodes and at points.
// The class and what it computes are described there.

namespace capsula::scene2d {

template <class Kernel>
template <class Density>
void LayerPotentials2D<Kernel>::singleLayerAtNodes(const Density& density, double* result) const
{
  const contour::Contour& c = *contour_;
  const ContourQuadrature2D& quad = *quadrature_;
  const int n = c.numberOfNodes();
  const int perSegment = quad.pointsPerSegment();
  const int numPoints = quad.numberOfPoints();
  const std::vector<double>& s = c.parameters();
  ++densityCall_;

  // f dl at the regular points, once for all targets.
  {
    Teuchos::TimeMonitor guard(*loadTimer_);
    loadX_.resize(static_cast<std::size_t>(numPoints));
    loadY_.resize(static_cast<std::size_t>(numPoints));
    for (int p = 0; p < numPoints; ++p) {
      const Eigen::Vector2d f = density(quad.point(p), quad.segmentOf(p), quad.parameterOf(p));
      loadX_[p] = f.x() * quad.weights()[p];
      loadY_[p] = f.y() * quad.weights()[p];
    }
  }

  // Every regular pair at once (RegularSums2D.hpp).
  {
    Teuchos::TimeMonitor guard(*regularTimer_);
    sumX_.assign(static_cast<std::size_t>(paddedTargets_), 0.0);
    sumY_.assign(static_cast<std::size_t>(paddedTargets_), 0.0);
    RegularSums2DOf<Kernel>::addSums(pointX_.data(), pointY_.data(), loadX_.data(), loadY_.data(), perSegment, n,
                                     targetX_.data(), targetY_.data(), paddedTargets_, regularMask_.data(),
                                     sumX_.data(), sumY_.data());
  }

  // The pairs treated apart: the singular and near-singular rules on cached pieces.
  // Their Gauss points are gathered and evaluated in one vectorised pass; the ln tau
  // terms of the pole pieces go straight into specialU_.
  Teuchos::TimeMonitor guard(*specialTimer_);
  long long subdivided = 0;
  int count = 0; // pairs gathered; the buffers only grow (no allocation once warm)
  pairStart_.assign(static_cast<std::size_t>(numTargets_) + 1, 0);
  specialU_.assign(2 * static_cast<std::size_t>(numTargets_), 0.0);
  for (int t = 0; t < numTargets_; ++t) {
    const int m = firstTarget_ + t;
    const double x0[2] = {nodes_[2 * m], nodes_[2 * m + 1]};
    double u[2] = {0.0, 0.0};
    const auto gather = [&](double x, double y, double f0, double f1) {
      if (static_cast<std::size_t>(count) == pairX_.size()) {
        const std::size_t grown = std::max<std::size_t>(1024, 2 * pairX_.size());
        for (auto* buffer : {&pairX_, &pairY_, &pairFx_, &pairFy_, &pairX0_, &pairY0_, &pairUx_, &pairUy_}) {
          buffer->resize(grown);
        }
      }
      const auto i = static_cast<std::size_t>(count++);
      pairX_[i] = x;
      pairY_[i] = y;
      pairFx_[i] = f0;
      pairFy_[i] = f1;
      pairX0_[i] = x0[0];
      pairY0_[i] = x0[1];
    };
    for (int i = specialStart_[t]; i < specialStart_[t + 1]; ++i) {
      const int k = specialSegments_[static_cast<std::size_t>(i)];
      const bool poleAtStart = k == m;
      const bool poleAtEnd = (k + 1) % n == m;
      pieces(k, x0, poleAtStart, poleAtEnd, split_);
      subdivided += split_.size() > 1 ? 1 : 0;
      const double segmentSpan = s[static_cast<std::size_t>(k) + 1] - s[static_cast<std::size_t>(k)];
      for (const SegmentPiece2D& piece : split_) {
        // Gauss points of the piece: the regular points for a whole segment.
        const double* x;
        const double* y;
        const double* fx;
        const double* fy;
        int stride;
        if (piece.level == 0) {
          const int first = k * perSegment;
          x = &pointX_[first], y = &pointY_[first], fx = &loadX_[first], fy = &loadY_[first];
          stride = 1;
        } else {
          const double* g = pieceGauss(k, piece, density);
          x = g, y = g + 1, fx = g + 3, fy = g + 4;
          stride = gaussStride;
        }
        for (int q = 0; q < perSegment; ++q) {
          gather(x[q * stride], y[q * stride], fx[q * stride], fy[q * stride]);
        }
        if (!piece.poleAtStart && !piece.poleAtEnd) {
          continue;
        }
        // Gauss-Legendre in tau from the pole takes G + ln tau (tau = the point's own
        // parameter, or its mirror when the pole ends the piece), then the -ln tau rule.
        for (int q = 0; q < perSegment; ++q) {
          const double logTau = logGauss_[static_cast<std::size_t>(piece.poleAtStart ? q : mirror_[q])];
          u[0] += logTau * fx[q * stride];
          u[1] += logTau * fy[q * stride];
        }
        const double width = piece.tb - piece.ta;
        const double jacobian = segmentSpan * width; // ds / dtau
        for (std::size_t q = 0; q < logRule_.points.size(); ++q) {
          const double tau = logRule_.points[q];
          const double tp = piece.poleAtStart ? piece.ta + tau * width : piece.tb - tau * width;
          const contour::ContourPoint point = c.pointAt(k, tp);
          const Eigen::Vector2d f = density(point, k, tp) * (logRule_.weights[q] * jacobian * point.metric);
          u[0] += f.x();
          u[1] += f.y();
        }
      }
    }
    specialU_[2 * t] = u[0];
    specialU_[2 * t + 1] = u[1];
    pairStart_[t + 1] = count;
  }
  RegularSums2DOf<Kernel>::pairs(pairX_.data(), pairY_.data(), pairFx_.data(), pairFy_.data(), pairX0_.data(),
                                 pairY0_.data(), count, pairUx_.data(), pairUy_.data());
  for (int t = 0; t < numTargets_; ++t) {
    double u[2] = {specialU_[2 * t], specialU_[2 * t + 1]};
    for (int i = pairStart_[t]; i < pairStart_[t + 1]; ++i) {
      u[0] += pairUx_[static_cast<std::size_t>(i)];
      u[1] += pairUy_[static_cast<std::size_t>(i)];
    }
    result[2 * t] = sumX_[t] + u[0];
    result[2 * t + 1] = sumY_[t] + u[1];
  }
  subdivided_ = subdivided;
}

template <class Kernel>
void LayerPotentials2D<Kernel>::buildDoubleLayerWeights()
{
  const contour::Contour& c = *contour_;
  const ContourQuadrature2D& quad = *quadrature_;
  const int n = c.numberOfNodes();
  const int numPoints = quad.numberOfPoints();
  const int perSegment = quad.pointsPerSegment();
  const std::vector<double>& s = c.parameters();
  const auto span = [&s](int k) { return s[static_cast<std::size_t>(k) + 1] - s[static_cast<std::size_t>(k)]; };
  doubleLayer_.reset(n, c.closure() == contour::Closure::Periodic, paddedTargets_);

  // The regular pairs (mask 1) at the regular points, vectorised over the targets.
  std::vector<double> ax(static_cast<std::size_t>(numPoints)), ay(ax.size()), basis(4 * ax.size());
  for (int p = 0; p < numPoints; ++p) {
    ax[p] = quad.normals()[2 * p] * quad.weights()[p];
    ay[p] = quad.normals()[2 * p + 1] * quad.weights()[p];
    splineBasis(quad.parameterOf(p), span(quad.segmentOf(p)), &basis[4 * static_cast<std::size_t>(p)]);
  }
  RegularSums2DOf<Kernel>::addDoubleLayerCoefficients(pointX_.data(), pointY_.data(), ax.data(), ay.data(),
                                                      basis.data(), perSegment, n, targetX_.data(), targetY_.data(),
                                                      regularMask_.data(), doubleLayer_);

  // The pairs treated apart (mask 0): the segments ending at the target (the kernel is
  // bounded there, so they take the plain rule unless an image is near) and the bisected
  // ones, with the pieces of pieces().
  long long subdivided = 0;
  for (int t = 0; t < numTargets_; ++t) {
    const int m = firstTarget_ + t;
    const double x0[2] = {nodes_[2 * m], nodes_[2 * m + 1]};
    for (int i = specialStart_[t]; i < specialStart_[t + 1]; ++i) {
      const int k = specialSegments_[static_cast<std::size_t>(i)];
      pieces(k, x0, k == m, (k + 1) % n == m, split_);
      subdivided += split_.size() > 1 ? 1 : 0;
      for (const SegmentPiece2D& piece : split_) {
        detail2d::visitGaussPiece(
            c, gauss_, k, piece.ta, piece.tb, [&](const contour::ContourPoint& point, double tp, double dl) {
              double W[4];
              RegularSums2DOf<Kernel>::doubleLayerWeight(point.position.x(), point.position.y(), point.normal.x() * dl,
                                                         point.normal.y() * dl, x0[0], x0[1], W);
              doubleLayer_.addPoint(t, k, tp, span(k), W);
            });
      }
    }
  }
  subdivided_ = subdivided;
  hasDoubleWeights_ = true;
}

template <class Kernel>
void LayerPotentials2D<Kernel>::doubleLayerAtNodes(const double* nodalDensity, operators::DoubleLayerForm form,
                                                   double* result)
{
  if (!hasDoubleWeights_) {
    Teuchos::TimeMonitor guard(*doubleWeightsTimer_);
    buildDoubleLayerWeights();
  }
  Teuchos::TimeMonitor guard(*doubleApplyTimer_);
  doubleLayer_.apply(*contour_, nodalDensity, form == operators::DoubleLayerForm::Subtracted, firstTarget_, numTargets_,
                     result);
}

template <class Kernel>
template <class Density>
void LayerPotentials2D<Kernel>::singleLayerAtPoints(const double* points, int numberOfPoints, const Density& density,
                                                    double* result) const
{
  const contour::Contour& c = *contour_;
  std::vector<SegmentPiece2D> split;
  for (int i = 0; i < numberOfPoints; ++i) {
    const double* x0 = points + 2 * i;
    double u[2] = {0.0, 0.0};
    for (int k = 0; k < c.numberOfSegments(); ++k) {
      pieces(k, x0, false, false, split);
      for (const SegmentPiece2D& piece : split) {
        detail2d::visitGaussPiece(c, gauss_, k, piece.ta, piece.tb,
                                  [&](const contour::ContourPoint& point, double tp, double dl) {
                                    const Eigen::Vector2d f = density(point, k, tp) * dl;
                                    const double fx[2] = {f.x(), f.y()};
                                    const double x[2] = {point.position.x(), point.position.y()};
                                    addSingleLayerTerm2D<Kernel>(x, x0, fx, u);
                                  });
      }
    }
    result[2 * i] = u[0];
    result[2 * i + 1] = u[1];
  }
}

template <class Kernel>
void LayerPotentials2D<Kernel>::doubleLayerAtPoints(const double* points, int numberOfPoints,
                                                    const double* nodalDensity, double* result) const
{
  const contour::Contour& c = *contour_;
  const ContourField2D field(c, nodalDensity);
  std::vector<SegmentPiece2D> split;
  for (int i = 0; i < numberOfPoints; ++i) {
    const double* x0 = points + 2 * i;
    double sum[2] = {0.0, 0.0};
    for (int k = 0; k < c.numberOfSegments(); ++k) {
      pieces(k, x0, false, false, split);
      for (const SegmentPiece2D& piece : split) {
        detail2d::visitGaussPiece(c, gauss_, k, piece.ta, piece.tb,
                                  [&](const contour::ContourPoint& point, double tp, double dl) {
                                    const Eigen::Vector2d v = field.at(k, tp);
                                    const double x[2] = {point.position.x(), point.position.y()};
                                    const double a[2] = {point.normal.x() * dl, point.normal.y() * dl};
                                    double W[4];
                                    doubleLayerWeight2D<Kernel>(x, x0, a, W);
                                    sum[0] += v.x() * W[0] + v.y() * W[2];
                                    sum[1] += v.x() * W[1] + v.y() * W[3];
                                  });
      }
    }
    result[2 * i] = sum[0];
    result[2 * i + 1] = sum[1];
  }
}

} // namespace capsula::scene2d
