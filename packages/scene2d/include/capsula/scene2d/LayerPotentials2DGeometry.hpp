#pragma once
// Part of LayerPotentials2D.hpp, included at its end: the geometry cache, the
// classification of target-segment pairs and the pieces of a near segment.
// The class and what it computes are described there.

namespace capsula::scene2d {

template <class Kernel>
LayerPotentials2D<Kernel>::LayerPotentials2D(ContourDiscretisation2D parameters)
    : parameters_(parameters),
      gauss_(quadrature::gaussLegendre(parameters.gaussLegendrePoints)),
      logRule_(quadrature::logWeightedGauss(parameters.logWeightedPoints)),
      geometryTimer_(core::timer("2D layers: geometry and pair classification")),
      loadTimer_(core::timer("2D single layer: load at the Gauss points")),
      regularTimer_(core::timer("2D single layer: regular sums")),
      specialTimer_(core::timer("2D single layer: singular and near-singular pairs")),
      doubleWeightsTimer_(core::timer("2D double layer: spline coefficients")),
      doubleApplyTimer_(core::timer("2D double layer: apply"))
{
  validate(parameters_);
  const int q = static_cast<int>(gauss_.points.size());
  for (int i = 0; i < q; ++i) {
    // Gauss-Legendre points are symmetric about 1/2: the mirror of each is another.
    int best = 0;
    for (int j = 1; j < q; ++j) {
      if (std::abs(gauss_.points[j] - (1.0 - gauss_.points[i])) <
          std::abs(gauss_.points[best] - (1.0 - gauss_.points[i]))) {
        best = j;
      }
    }
    core::require(std::abs(gauss_.points[best] - (1.0 - gauss_.points[i])) < 1e-14,
                  "LayerPotentials2D: the Gauss-Legendre rule is not symmetric on [0, 1].");
    mirror_.push_back(best);
    logGauss_.push_back(std::log(gauss_.points[i]));
  }
}

template <class Kernel>
void LayerPotentials2D<Kernel>::update(const contour::Contour& contour, int firstTarget, int numTargets)
{
  Teuchos::TimeMonitor guard(*geometryTimer_);
  const int n = contour.numberOfNodes();
  core::require<core::InputError>(firstTarget >= 0 && numTargets >= 0 && firstTarget + numTargets <= n,
                                  "The target nodes [", firstTarget, ", ", firstTarget + numTargets,
                                  ") are not nodes of the ", n, "-node contour.");
  for (int i = 0; i < n; ++i) {
    const double x[2] = {contour.nodes()(0, i), contour.nodes()(1, i)};
    core::require<core::InputError>(KernelImages2D<Kernel>::inFluid(x), "Node ", i, " of the contour at (", x[0], ", ",
                                    x[1], ") lies outside the fluid of the ", Kernel::name,
                                    " kernel: the cell has touched the wall.");
  }
  contour_.emplace(contour);
  quadrature_.emplace(contour, gauss_);
  nodes_.resize(2 * static_cast<std::size_t>(n));
  midpoints_.resize(2 * static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    nodes_[2 * i] = contour.nodes()(0, i);
    nodes_[2 * i + 1] = contour.nodes()(1, i);
    const Eigen::Vector2d mid = contour.positionAt(i, 0.5);
    midpoints_[2 * i] = mid.x();
    midpoints_[2 * i + 1] = mid.y();
  }
  firstTarget_ = firstTarget;
  numTargets_ = numTargets;
  hasDoubleWeights_ = false;

  // The whole segments: ends, middle and reach (the piece test of isNear()).
  pieceCache_.resize(static_cast<std::size_t>(n));
  pieceIndex_.clear();
  pieceTree_.assign(static_cast<std::size_t>(n) * treeSize, -1);
  pieceGauss_.clear();
  for (int k = 0; k < n; ++k) {
    CachedPiece& piece = pieceCache_[static_cast<std::size_t>(k)];
    const int next = (k + 1) % n;
    piece.a[0] = nodes_[2 * k];
    piece.a[1] = nodes_[2 * k + 1];
    piece.b[0] = nodes_[2 * next];
    piece.b[1] = nodes_[2 * next + 1];
    piece.m[0] = midpoints_[2 * k];
    piece.m[1] = midpoints_[2 * k + 1];
    const double length = pieceLength(piece);
    const double reach = parameters_.nearSingularDistance * length;
    piece.reach2 = reach * reach;
    piece.ta = 0.0;
    piece.tb = 1.0;
    piece.gauss = -1;
    piece.densityCall = 0;
  }

  const int numPoints = quadrature_->numberOfPoints();
  pointX_.resize(static_cast<std::size_t>(numPoints));
  pointY_.resize(static_cast<std::size_t>(numPoints));
  for (int p = 0; p < numPoints; ++p) {
    pointX_[p] = quadrature_->positions()[2 * p];
    pointY_[p] = quadrature_->positions()[2 * p + 1];
  }
  classifyPairs();
}

template <class Kernel>
void LayerPotentials2D<Kernel>::classifyPairs()
{
  const int n = contour_->numberOfNodes();
  paddedTargets_ =
      (numTargets_ + operators::targetLaneMultiple - 1) / operators::targetLaneMultiple * operators::targetLaneMultiple;
  const auto padded = static_cast<std::size_t>(paddedTargets_);
  targetX_.resize(padded);
  targetY_.resize(padded);
  for (int t = 0; t < paddedTargets_; ++t) {
    const int m = firstTarget_ + std::min(t, numTargets_ - 1);
    targetX_[t] = nodes_[2 * m];
    targetY_[t] = nodes_[2 * m + 1];
  }
  const bool bisecting = parameters_.nearSingularDistance > 0.0 && parameters_.nearSingularLevels > 0;
  if (bisecting) {
    regularMask_.resize(static_cast<std::size_t>(n) * padded); // markNearSegments2D writes every entry
  } else {
    regularMask_.assign(static_cast<std::size_t>(n) * padded, 1.0);
  }
  // Whole segments that pieces() would bisect: the test of isNear() with squared
  // distances (the same decision), for every target at once. With no bisection allowed
  // they stay regular pairs (pieces() returns the whole segment).
  if (bisecting) {
    segmentEnds_.resize(6 * static_cast<std::size_t>(n));
    segmentReach2_.resize(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
      const CachedPiece& piece = pieceCache_[static_cast<std::size_t>(k)];
      const double ends[6] = {piece.a[0], piece.a[1], piece.m[0], piece.m[1], piece.b[0], piece.b[1]};
      std::copy(ends, ends + 6, &segmentEnds_[6 * static_cast<std::size_t>(k)]);
      segmentReach2_[static_cast<std::size_t>(k)] = piece.reach2;
    }
    // The images are the mirror images below the wall (KernelImages2D<Wall2D>).
    markNearSegments2D(segmentEnds_.data(), segmentReach2_.data(), n, targetX_.data(), targetY_.data(), paddedTargets_,
                       KernelImages2D<Kernel>::count == 1, regularMask_.data());
  }
  // The two segments ending at the target take the log-singular rule.
  for (int t = 0; t < numTargets_; ++t) {
    const int m = firstTarget_ + t;
    regularMask_[static_cast<std::size_t>(m) * padded + t] = 0.0;
    regularMask_[static_cast<std::size_t>((m + n - 1) % n) * padded + t] = 0.0;
  }
  // Each target's special segments in increasing k (counted, then filled, row by row).
  // (Locals throughout: the loops over the mask then neither reload the members nor
  // branch when counting.)
  const int targets = numTargets_;
  specialStart_.assign(static_cast<std::size_t>(targets) + 1, 0);
  int* count = specialStart_.data() + 1;
  for (int k = 0; k < n; ++k) {
    const double* use = &regularMask_[static_cast<std::size_t>(k) * padded];
    for (int t = 0; t < targets; ++t) {
      count[t] += static_cast<int>(1.0 - use[t]);
    }
  }
  for (int t = 0; t < targets; ++t) {
    specialStart_[t + 1] += specialStart_[t];
  }
  specialSegments_.resize(static_cast<std::size_t>(specialStart_[targets]));
  specialFill_.assign(specialStart_.begin(), specialStart_.end() - 1);
  int* fill = specialFill_.data();
  int* special = specialSegments_.data();
  for (int k = 0; k < n; ++k) {
    const double* use = &regularMask_[static_cast<std::size_t>(k) * padded];
    for (int t = 0; t < targets; ++t) {
      if (use[t] == 0.0) {
        special[fill[t]++] = k;
      }
    }
  }
}

template <class Kernel>
int LayerPotentials2D<Kernel>::cachedPiece(int k, int level, int index) const
{
  if (level == 0) {
    return k;
  }
  // Levels up to treeLevels in a flat per-segment table (heap numbering), deeper ones in a
  // hash map: most bisections stop within a few levels.
  int* slot;
  if (level <= treeLevels) {
    slot = &pieceTree_[static_cast<std::size_t>(k) * treeSize + (1u << level) + static_cast<unsigned>(index)];
  } else {
    const std::uint64_t key = (static_cast<std::uint64_t>(k) << 32) | (static_cast<std::uint64_t>(level) << 24) |
                              static_cast<std::uint64_t>(index);
    slot = &pieceIndex_.try_emplace(key, -1).first->second;
  }
  if (*slot < 0) {
    *slot = static_cast<int>(pieceCache_.size());
    // The same points bisect() used to evaluate for every target: exact dyadic parameters.
    CachedPiece piece;
    piece.ta = std::ldexp(static_cast<double>(index), -level);
    piece.tb = std::ldexp(static_cast<double>(index + 1), -level);
    const Eigen::Vector2d pa = contour_->positionAt(k, piece.ta);
    const Eigen::Vector2d pb = contour_->positionAt(k, piece.tb);
    const Eigen::Vector2d pm = contour_->positionAt(k, 0.5 * (piece.ta + piece.tb));
    piece.a[0] = pa.x(), piece.a[1] = pa.y(), piece.b[0] = pb.x(), piece.b[1] = pb.y();
    piece.m[0] = pm.x(), piece.m[1] = pm.y();
    const double length = pieceLength(piece);
    const double reach = parameters_.nearSingularDistance * length;
    piece.reach2 = reach * reach;
    pieceCache_.push_back(piece);
  }
  return *slot;
}

template <class Kernel>
bool LayerPotentials2D<Kernel>::isNear(const double* x0, const double (*image)[2], int numImages,
                                       const SegmentPiece2D& piece) const
{
  // Nearer than the reach to the piece's ends or middle (squared: no square roots).
  const CachedPiece& c = pieceCache_[static_cast<std::size_t>(piece.slot)];
  const auto within = [&c](const double* p) {
    const auto d2 = [p](const double* q) { return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]); };
    return std::min({d2(c.a), d2(c.m), d2(c.b)}) < c.reach2;
  };
  if (!piece.poleAtStart && !piece.poleAtEnd && within(x0)) {
    return true;
  }
  for (int q = 0; q < numImages; ++q) {
    if (within(image[q])) {
      return true;
    }
  }
  return false;
}

template <class Kernel>
void LayerPotentials2D<Kernel>::bisect(int k, const double* x0, const double (*image)[2], int numImages,
                                       SegmentPiece2D piece, int level, std::vector<SegmentPiece2D>& out) const
{
  piece.slot = cachedPiece(k, piece.level, piece.index);
  if (level >= parameters_.nearSingularLevels || !isNear(x0, image, numImages, piece)) {
    out.push_back(piece);
    return;
  }
  const double middle = 0.5 * (piece.ta + piece.tb);
  bisect(k, x0, image, numImages, {piece.ta, middle, piece.poleAtStart, false, piece.level + 1, 2 * piece.index},
         level + 1, out);
  bisect(k, x0, image, numImages, {middle, piece.tb, false, piece.poleAtEnd, piece.level + 1, 2 * piece.index + 1},
         level + 1, out);
}

template <class Kernel>
void LayerPotentials2D<Kernel>::pieces(int k, const double* x0, bool poleAtStart, bool poleAtEnd,
                                       std::vector<SegmentPiece2D>& out) const
{
  out.clear();
  const SegmentPiece2D whole{0.0, 1.0, poleAtStart, poleAtEnd, 0, 0, k};
  if (!(parameters_.nearSingularDistance > 0.0)) {
    out.push_back(whole);
    return;
  }
  double image[KernelImages2D<Kernel>::count + 1][2];
  KernelImages2D<Kernel>::images(x0, image);
  bisect(k, x0, image, KernelImages2D<Kernel>::count, whole, 0, out);
}

template <class Kernel>
template <class Density>
const double* LayerPotentials2D<Kernel>::pieceGauss(int k, const SegmentPiece2D& piece, const Density& density) const
{
  const int perSegment = static_cast<int>(gauss_.points.size());
  CachedPiece& c = pieceCache_[static_cast<std::size_t>(piece.slot)];
  const std::vector<double>& s = contour_->parameters();
  const double span = (s[static_cast<std::size_t>(k) + 1] - s[static_cast<std::size_t>(k)]) * (c.tb - c.ta);
  const bool fresh = c.gauss < 0;
  if (fresh) {
    c.gauss = static_cast<int>(pieceGauss_.size() / gaussStride);
    pieceGauss_.resize(pieceGauss_.size() + static_cast<std::size_t>(gaussStride * perSegment));
  }
  double* g = &pieceGauss_[static_cast<std::size_t>(c.gauss) * gaussStride];
  if (fresh || c.densityCall != densityCall_) {
    for (int q = 0; q < perSegment; ++q) {
      const double t = c.ta + gauss_.points[q] * (c.tb - c.ta);
      const contour::ContourPoint point = contour_->pointAt(k, t);
      const double dl = gauss_.weights[q] * span * point.metric;
      const Eigen::Vector2d f = density(point, k, t) * dl;
      double* row = g + gaussStride * q;
      row[0] = point.position.x();
      row[1] = point.position.y();
      row[2] = dl;
      row[3] = f.x();
      row[4] = f.y();
    }
    c.densityCall = densityCall_;
  }
  return g;
}

namespace detail2d {

/// Calls visit(point, t, dl) at the Gauss points of piece [ta, tb] of segment k.
template <class Visit>
inline void visitGaussPiece(const contour::Contour& contour, const quadrature::Rule1D& rule, int k, double ta,
                            double tb, Visit&& visit)
{
  const std::vector<double>& s = contour.parameters();
  const double span = (s[static_cast<std::size_t>(k) + 1] - s[static_cast<std::size_t>(k)]) * (tb - ta);
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    const double t = ta + rule.points[q] * (tb - ta);
    const contour::ContourPoint point = contour.pointAt(k, t);
    visit(point, t, rule.weights[q] * span * point.metric);
  }
}

} // namespace detail2d

} // namespace capsula::scene2d
