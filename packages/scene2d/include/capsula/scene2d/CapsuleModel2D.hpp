#pragma once
// The 2D capsule of Chapter 4 as an ODE for its marker points, dx_i/dt = u_i (thesis eq
// A.48): contour (App. A.3) -> membrane load of 'Cell/Membrane law' (Hookean by default)
// with E = 1 (App. A.5; loads in units of E/L), plus the bending load with 'Cell/Bending modulus' > 0 (elasticity/
// MembraneBending2D.hpp) -> node velocities from the boundary-integral equation (eq A.35). Free cells use
// periodic splines; after tethering, tethered splines with node 0 at the tether, whose
// velocity is held at zero. With lambda != 1 and 'Solver/Warm start', each GMRES solve starts
// from the last solutions (operators/WarmStartHistory.hpp); the history is part of the run's
// state (gmresWarmStart(), restored from checkpoints) and is dropped at tethering, when the
// nodes are relabelled.
//
// Its checkpoint section holds the warm start ("run gmres warm start rhs", "... solutions")
// and the prestress the membrane's reference was built with ("run cell prestress"): the
// reference is rebuilt from the deck on restart, so a deck with another prestress is
// refused. A tabulated shear rate's samples ("run shear rate waveform") are kept too: a
// restart whose waveform file changed is refused. The regridded markers and the tether are
// the tether procedure's to save.
#include "capsula/scene2d/CellContour2D.hpp"
#include "capsula/scene2d/ContourDiscretisation2D.hpp"
#include "capsula/scene2d/ElasticMembrane2D.hpp"
#include "capsula/scene2d/FlowModel2D.hpp"
#include "capsula/scene2d/InterfaceVelocity2D.hpp"
#include "capsula/scene2d/KernelRegistry2D.hpp"
#include "capsula/scene2d/MembraneState2D.hpp"

#include <capsula/contour/Contour.hpp>
#include <capsula/io/CheckpointSection.hpp>
#include <capsula/operators/OperatorParameters.hpp>

#include <Eigen/Core>
#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace capsula::scene2d {

class CapsuleModel2D final : public io::CheckpointSection {
public:
  CapsuleModel2D(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const CellSettings2D& cell,
                 const FlowSettings2D& flow, const ContourDiscretisation2D& discretisation,
                 const operators::SolverParameters& solver, KernelRegistry2D kernels = builtInKernels2D());

  int numberOfNodes() const { return static_cast<int>(referenceNodes_.cols()); }
  const CellSettings2D& cell() const { return cell_; }
  const FlowSettings2D& flow() const { return flow_; }
  /// Ca, lambda and u_inf = (k(t) y, 0) at time t ('Flow/Shear rate').
  FlowConditions2D flowAt(double t) const;
  const ContourDiscretisation2D& discretisation() const { return discretisation_; }
  std::string kernelName() const { return velocity_->kernelName(); }
  /// An evaluator of the model's Green's function (FlowSettings2D::kernel) for contours of
  /// `numNodes` nodes, e.g. the stiff solver's on a frozen contour.
  std::unique_ptr<InterfaceVelocity2D> makeInterfaceVelocity(const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                                                             int numNodes,
                                                             const ContourDiscretisation2D& discretisation,
                                                             const operators::SolverParameters& solver) const;
  /// The terms built, one line each (the run log and summary.json print them).
  std::vector<std::string> terms() const;

  /// The initial contour in the free (preparation) labelling (unstressed unless
  /// Cell/Prestress > 0).
  const Eigen::Matrix2Xd& referenceNodes() const { return referenceNodes_; }
  /// The unstressed reference positions of the free cell's markers now: referenceNodes()
  /// shrunk by 1 + prestress (elasticity/Prestress.hpp) until a regridFree().
  const Eigen::Matrix2Xd& freeReferenceNodes() const { return freeReference_; }
  bool freeCellRegridded() const { return freeRegridded_; }
  /// The free cell gets new markers (TetherRegrid2D): node i of the state from now on is the
  /// material point whose reference position is column i of `referenceNodes`.
  void regridFree(const Eigen::Matrix2Xd& referenceNodes);
  /// The initial contour's length A0 and area (the reference of A/A0 and of the area drift).
  double referenceLength() const { return referenceLength_; }
  double referenceArea() const { return referenceArea_; }

  /// The state at t = 0: referenceNodes(), x0, y0, x1, y1, ...
  std::vector<double> initialState() const;

  /// Switches to the tethered cell: node 0 is the material point that was node `offset`
  /// of the free cell's markers (the membrane's reference, freeReferenceNodes(), is
  /// relabelled the same way) and its velocity is zero from now on.
  void tether(int offset);
  /// Switches to the tethered cell with new markers (TetherRegrid2D): node i of the state
  /// from now on is the material point whose reference position is column i of
  /// `referenceNodes` (node 0 the tether).
  void tether(const Eigen::Matrix2Xd& referenceNodes);
  /// Those reference positions after a regridding tether() (empty otherwise).
  const Eigen::Matrix2Xd& regriddedReference() const { return regriddedReference_; }
  bool tethered() const { return tetherOffset_.has_value(); }
  int tetherOffset() const { return tetherOffset_.value_or(0); }

  /// The contour through the state's nodes (periodic, or tethered after tether()).
  contour::Contour contour(const std::vector<double>& state) const;
  MembraneState2D membrane(const contour::Contour& contour) const;

  /// Node velocities at time t for a contour and its membrane state (collective).
  VelocitySolution2D velocities(double t, const contour::Contour& contour, const MembraneState2D& membrane);

  /// dy/dt = u(t, y) (collective): the right-hand side of the time integration.
  void rightHandSide(double t, const std::vector<double>& state, std::vector<double>& derivative);

  /// GMRES iterations of the last velocity solve (0 when lambda = 1).
  int lastIterations() const { return lastIterations_; }

  /// The warm start of the next GMRES solve (null without one: lambda = 1 or 'Solver/Warm
  /// start' = false), and its restoration from a checkpoint (WarmStartHistory::
  /// rightHandSides() and solutions()).
  const operators::WarmStartHistory* gmresWarmStart() const { return warmStart_ ? &*warmStart_ : nullptr; }
  void restoreGmresWarmStart(const std::vector<double>& rightHandSides, const std::vector<double>& solutions);

  void save(io::Checkpoint& checkpoint) const override;
  /// Throws core::InputError if the checkpoint was written with another Cell/Prestress.
  /// Loads after the tether (tethering drops the warm start).
  void load(const io::Checkpoint& checkpoint, const std::string& source) override;

private:
  /// The membrane on `reference`: the tension of 'Cell/Membrane law' (E = 1), with bending
  /// when Cell/Bending modulus > 0.
  std::unique_ptr<ElasticMembrane2D> makeMembrane(const contour::Contour& reference) const;

  CellSettings2D cell_;
  FlowSettings2D flow_;
  ContourDiscretisation2D discretisation_;
  std::string krylovMethod_; ///< 'Solver/Method', named in terms()
  Eigen::Matrix2Xd referenceNodes_;
  double referenceLength_ = 0.0;
  double referenceArea_ = 0.0;
  std::optional<int> tetherOffset_;
  Eigen::Matrix2Xd regriddedReference_;
  Eigen::Matrix2Xd freeReference_;
  bool freeRegridded_ = false;
  std::unique_ptr<ElasticMembrane2D> membrane_;
  KernelRegistry2D kernels_;
  std::unique_ptr<InterfaceVelocity2D> velocity_;
  std::optional<operators::WarmStartHistory> warmStart_;
  int lastIterations_ = 0;
};

} // namespace capsula::scene2d
