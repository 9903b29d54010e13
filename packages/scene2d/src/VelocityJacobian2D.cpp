#include "capsula/scene2d/VelocityJacobian2D.hpp"

#include "capsula/scene2d/ContourDiscretisation2D.hpp"
#include "capsula/scene2d/PointSingleLayer2D.hpp"

#include <capsula/core/Error.hpp>

#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace capsula::scene2d {

namespace {

// J~ v by fourth-order central differences of the load: e |v|_max = kDirectionalStep l_min
// (see the header).
constexpr double kDirectionalStep = 1e-3;

// The preconditioner's load Jacobian by forward differences, e = kColumnStep l_min: its
// error, 1e-6 relative, is far below what a preconditioner needs.
constexpr double kColumnStep = 1e-6;

// Nodes perturbed together for the preconditioner's load Jacobian are kColumnSpacing apart
// along the contour, and each node's response is charged to the nearest perturbed node
// (2 kColumnSpacing membrane evaluations in all, instead of 2N). The load reaches other
// nodes through interpolating splines: the response falls from 110 at the node to 1.4,
// 1e-3 and 1e-7 six, twelve and twenty nodes away (64 points, Ca = 0.01). Twelve nodes,
// the nearest another perturbed node can be, keep K to 1e-5 of its entries; that matters
// on the smooth modes, where K v is a near-cancellation of those entries (every rigid
// motion has K v = 0): half the spacing gave O(1) errors there.
constexpr int kColumnSpacing = 24;

} // namespace

VelocityJacobian2D::VelocityJacobian2D(CapsuleModel2D& model, const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                                       const Teuchos::ParameterList& deck)
    : VelocityJacobian2D(model, comm, deck, readStiffSolverSettings2D(deck.sublist("Solver").sublist("Stiff")))
{}

VelocityJacobian2D::VelocityJacobian2D(CapsuleModel2D& model, const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                                       const Teuchos::ParameterList& deck, const StiffSolverSettings2D& settings)
    : StageJacobian(settings.stage, "Stiff Jacobian 2D", toString(StiffPreconditioner2D::PointSingleLayer)),
      model_(model),
      settings_(settings)
{
  ContourDiscretisation2D discretisation = model.discretisation();
  if (settings_.gaussLegendrePoints > 0) {
    discretisation.gaussLegendrePoints = settings_.gaussLegendrePoints;
  }
  const int n = model.numberOfNodes();
  velocity_ =
      model.makeInterfaceVelocity(comm, n, discretisation, operators::readSolverParameters(deck.sublist("Solver")));
  const auto map =
      Teuchos::rcp(new Tpetra::Map<>(2 * static_cast<Tpetra::global_size_t>(n), 0, comm, Tpetra::LocallyReplicated));
  if (settings_.preconditioner != StiffPreconditioner2D::None) {
    preconditioner_ = Teuchos::rcp(new operators::DenseStagePreconditioner(map));
  }
  tetherEnabled_ = deck.sublist("Tether").get<bool>("Enabled");
  const double lambda = model.flow().conditions.viscosityRatio;
  coefficient_ = 1.0 / (2.0 * M_PI * (1.0 + lambda) * model.flow().conditions.capillaryNumber);
  flowFactor_ = 2.0 / (1.0 + lambda);
  startSolver(map, preconditioner_);
}

void VelocityJacobian2D::freeze(double t, const std::vector<double>& y)
{
  flowGradient_ = model_.flowAt(t).background.gradient;
  frozenState_ = y;
  frozen_.emplace(model_.contour(y));
  fixed_ = model_.tethered() ? std::vector<int>{0} : std::vector<int>{};
  shortestSegment_ = frozen_->segmentLength(0);
  for (int k = 1; k < frozen_->numberOfSegments(); ++k) {
    shortestSegment_ = std::min(shortestSegment_, frozen_->segmentLength(k));
  }
  if (!preconditioner_.is_null()) {
    preconditioner_->setJacobian(approximateJacobian(*frozen_));
  }
}

Eigen::MatrixXf VelocityJacobian2D::approximateJacobian(const contour::Contour& frozen)
{
  const int n = model_.numberOfNodes();
  const Eigen::Matrix2Xd base = model_.membrane(frozen).load();

  // K = d(nodal load) / d(node positions). Group g perturbs the nodes p_m + g, p_m =
  // floor(m N / M) spread evenly (M = N / kColumnSpacing of them, so that they lie at least
  // kColumnSpacing apart): ceil(N / M) groups cover every node once. A node's response is
  // charged to the group's member within kColumnSpacing / 2 of it (none for the odd node
  // midway in a wider gap: its response is below 1e-5 of the local one).
  std::vector<Eigen::Triplet<float>> entries;
  const double step = kColumnStep * shortestSegment_;
  const int members = std::max(1, n / kColumnSpacing);
  std::vector<int> start(static_cast<std::size_t>(members) + 1);
  for (int m = 0; m <= members; ++m) {
    start[static_cast<std::size_t>(m)] = static_cast<int>((static_cast<long long>(m) * n) / members);
  }
  int groups = 0;
  for (int m = 0; m < members; ++m) {
    groups = std::max(groups, start[static_cast<std::size_t>(m) + 1] - start[static_cast<std::size_t>(m)]);
  }
  const int reach = members > 1 ? kColumnSpacing / 2 : n;
  std::vector<int> group, owner(static_cast<std::size_t>(n));
  std::vector<double> probe;
  for (int g = 0; g < groups; ++g) {
    group.clear();
    for (int m = 0; m < members; ++m) {
      if (start[static_cast<std::size_t>(m)] + g < start[static_cast<std::size_t>(m) + 1]) {
        group.push_back(start[static_cast<std::size_t>(m)] + g);
      }
    }
    std::fill(owner.begin(), owner.end(), -1);
    for (int d = 0; d <= std::min(reach, n / 2); ++d) {
      for (const int j : group) {
        for (const int i : {(j + d) % n, (j - d + n) % n}) {
          if (owner[static_cast<std::size_t>(i)] < 0) {
            owner[static_cast<std::size_t>(i)] = j;
          }
        }
      }
    }
    for (int b = 0; b < 2; ++b) {
      probe = frozenState_;
      for (const int j : group) {
        probe[2 * static_cast<std::size_t>(j) + static_cast<std::size_t>(b)] += step;
      }
      const Eigen::Matrix2Xd load = model_.membrane(model_.contour(probe)).load();
      for (int i = 0; i < n; ++i) {
        const int j = owner[static_cast<std::size_t>(i)];
        if (j < 0) {
          continue;
        }
        for (int a = 0; a < 2; ++a) {
          const double value = (load(a, i) - base(a, i)) / step;
          if (value != 0.0) {
            entries.emplace_back(2 * i + a, 2 * j + b, static_cast<float>(value));
          }
        }
      }
    }
  }
  Eigen::SparseMatrix<float> K(2 * n, 2 * n);
  K.setFromTriplets(entries.begin(), entries.end());

  // A = -c M K + 2/(1 + lambda) grad u_inf, the tethered rows zero.
  Eigen::MatrixXf A;
  if (settings_.preconditioner == StiffPreconditioner2D::PointSingleLayer) {
    // M K column by column: K's columns hold ~2 kColumnSpacing entries each.
    const Eigen::MatrixXf M = pointSingleLayer2D(frozen, model_.flow().domain.hasLowerWall()).cast<float>();
    A.setZero(2 * n, 2 * n);
    const auto c = static_cast<float>(coefficient_);
    for (Eigen::Index column = 0; column < K.outerSize(); ++column) {
      for (Eigen::SparseMatrix<float>::InnerIterator entry(K, column); entry; ++entry) {
        A.col(column).noalias() -= (c * entry.value()) * M.col(entry.row());
      }
    }
  } else {
    Eigen::VectorXf mobility(2 * n);
    for (int i = 0; i < n; ++i) {
      const double share = 0.5 * (frozen.segmentLength((i + n - 1) % n) + frozen.segmentLength(i));
      mobility(2 * i) = mobility(2 * i + 1) = static_cast<float>(coefficient_ * settings_.mobilityFactor * share);
    }
    A = -(mobility.asDiagonal() * K);
  }
  const Eigen::Matrix2f gradient = (flowFactor_ * flowGradient_).cast<float>();
  for (int i = 0; i < n; ++i) {
    A.block<2, 2>(2 * i, 2 * i) += gradient;
  }
  for (const int i : fixed_) {
    A.row(2 * i).setZero();
    A.row(2 * i + 1).setZero();
  }
  return A;
}

void VelocityJacobian2D::applyFrozen(const double* x, double* y)
{
  const std::size_t n = frozenState_.size();
  double largest = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    largest = std::max(largest, std::abs(x[k]));
  }
  if (largest == 0.0) {
    std::fill(y, y + n, 0.0);
    return;
  }
  // Fourth-order central differences of the load at the frozen contour's points:
  // K v = [8 (f(e) - f(-e)) - (f(2e) - f(-2e))] / 12e, f(s) = Delta f(x_n + s v).
  const double e = kDirectionalStep * shortestSegment_ / largest;
  std::vector<MembraneState2D> states;
  states.reserve(4);
  probe_.resize(n);
  for (const double multiple : {1.0, -1.0, 2.0, -2.0}) {
    for (std::size_t k = 0; k < n; ++k) {
      probe_[k] = frozenState_[k] + multiple * e * x[k];
    }
    states.push_back(model_.membrane(model_.contour(probe_)));
  }
  const double scale = 1.0 / (12.0 * e);
  const ContourLoad2D derivative = [&](const contour::ContourPoint&, int segment, double t) {
    return Eigen::Vector2d(scale * (8.0 * (states[0].loadAt(segment, t) - states[1].loadAt(segment, t)) -
                                    (states[2].loadAt(segment, t) - states[3].loadAt(segment, t))));
  };
  const std::vector<double> single = velocity_->singleLayer(*frozen_, derivative);
  operators::combineWithFlowGradient<2>([this](std::size_t) -> const Eigen::Matrix2d& { return flowGradient_; },
                                        [this](std::size_t) { return -coefficient_; },
                                        [this](std::size_t) { return flowFactor_; }, n / 2, x, single, y);
  for (const int i : fixed_) {
    y[2 * i] = y[2 * i + 1] = 0.0;
  }
}

const Eigen::MatrixXf& VelocityJacobian2D::approximateJacobian() const
{
  core::require(!preconditioner_.is_null(), "VelocityJacobian2D: 'Solver/Stiff/Preconditioner' = None forms no "
                                            "approximate Jacobian");
  return preconditioner_->jacobian();
}

std::string VelocityJacobian2D::describe() const
{
  std::ostringstream line;
  line << "stiff Jacobian: single layer of the membrane load's directional derivative, frozen each step";
  if (model_.flow().conditions.viscosityRatio != 1.0) {
    line << " (double layer left out)";
  }
  if (tetherEnabled_) {
    line << ", the tethered node's rows zero once tethered";
  }
  line << "; " << operators::describe(stageSettings());
  switch (settings_.preconditioner) {
  case StiffPreconditioner2D::PointSingleLayer:
    line << " with the point-single-layer preconditioner (dense LU)";
    break;
  case StiffPreconditioner2D::LocalMobility:
    line << " with the local-mobility preconditioner (beta = " << settings_.mobilityFactor << ", dense LU)";
    break;
  case StiffPreconditioner2D::None:
    line << " without preconditioner";
    break;
  }
  return line.str();
}

} // namespace capsula::scene2d
