#pragma once
// The suspension's outputs of a 3D scene run ('Output/Suspension/Enabled'): at every output,
// the cell-free layer along each wall (metrics.csv) and the hematocrit profile across the
// wall-normal direction (suspension.h5 + .xdmf, one polyline of the bin centres per output);
// in summary.json the profile averaged over the outputs at t >= 'Output/Suspension/Average
// from' (docs/suspensions.md, section 'Outputs of a run').
//
// The box the volume fraction is taken over: across y, 0 < y < H in a channel, else 0 < y <
// 'Output/Suspension/Height'; along x and z, the period where the domain is periodic, else
// 'Output/Suspension/Box length x' or 'z'. A slab's fraction is the cells' volume in it over
// its volume L_x dy L_z (capsula::suspension::hematocritProfileInSlab), whatever the cells' x
// and z.
//
// The cell-free layer: in a channel periodic along x and z, the suspension package's column
// mean (CellFreeLayer.hpp, 'Output/Suspension/Columns' per period); in any other domain with
// the lower wall, the thinnest layer, the smallest distance from the wall to a cell surface.
//
// With 'Output/Suspension/Hematocrit type' (suspension3d reads it empty as the type that fills
// 'Suspension/Hematocrit', the red cells), the profile and the layer count only the cells of
// that 'Type', as the margination literature's red-cell-free layer does; otherwise every cell.
//
// The relative viscosity (RelativeViscosity.hpp), in a channel periodic along x and z: from the
// flux in Poiseuille flow, from the mean wall shear stress in Couette flow; the caller measures
// it with the operators and hands it to measure().
//
// The time averages are the arithmetic means of the profiles and of the relative viscosity at
// the outputs in the window; their running sums and count are checkpointed ("suspension."), so
// a restart continues them bit for bit.
#include <capsula/domain/Domain.hpp>
#include <capsula/io/Checkpoint.hpp>
#include <capsula/io/Json.hpp>
#include <capsula/io/Snapshot.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/suspension/CellFreeLayer.hpp>
#include <capsula/suspension/HematocritProfile.hpp>

#include <Teuchos_ParameterList.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace capsula::run {

struct SuspensionOutputSettings {
  bool enabled = false;
  int bins = 20;
  double averageFrom = 0.0;
  double height = 0.0;     ///< the profile's top without a channel
  double boxLengthX = 0.0; ///< the box's length along x without periodicity along x
  double boxLengthZ = 0.0;
  int columns = 32;           ///< columns per period of the cell-free layer in a periodic channel
  std::string hematocritType; ///< the cells' 'Type' the profile and the layer count; empty: all
};

/// Declares the "Output/Suspension" sublist.
void declareSuspensionOutputParameters(Teuchos::ParameterList& suspension);

/// Reads the "Output/Suspension" sublist `suspension` of a validated deck. Throws
/// core::InputError naming the key when the box is not given where the domain does not
/// bound it (no channel: 'Height'; not periodic along x or z: 'Box length x' or 'z').
SuspensionOutputSettings readSuspensionOutputSettings(const Teuchos::ParameterList& suspension,
                                                      const domain::Domain& domain);

/// What one output measures.
struct SuspensionSample {
  double time = 0.0;
  suspension::HematocritProfile profile;
  suspension::CellFreeLayer layer;
  double relativeViscosity = 0.0; ///< in a channel periodic along x and z
};

class SuspensionOutput {
public:
  /// `settings` from readSuspensionOutputSettings for `domain` (enabled).
  SuspensionOutput(const SuspensionOutputSettings& settings, const domain::Domain& domain);

  /// The line of the run's "Terms built" block.
  std::string term() const;
  /// cell_free_layer_lower, and cell_free_layer_upper in a channel; relative_viscosity in a
  /// channel periodic along x and z.
  std::vector<std::string> columns() const;
  /// Whether measure() takes a relative viscosity (a channel periodic along x and z).
  bool measuresRelativeViscosity() const { return periodicChannel_; }
  /// Measures `cells` at time t and adds the profile and `relativeViscosity` (read only where
  /// measuresRelativeViscosity()) to the averages if t is in their window.
  SuspensionSample measure(double t, const std::vector<const mesh::SurfaceMesh*>& cells,
                           double relativeViscosity = 0.0);
  /// The values of columns() for `sample`.
  std::vector<double> row(const SuspensionSample& sample) const;
  /// The profile as a polyline block "hematocrit" of the bin centres (0, y_k, 0) with the
  /// node field "hematocrit".
  io::SnapshotBlock profileBlock(const SuspensionSample& sample) const;

  /// The bin centres and the averaged profile (empty before the window opens).
  std::vector<double> binCentres() const;
  std::vector<double> averageProfile() const;
  std::int64_t averagedOutputs() const { return averaged_; }
  /// summary.json's "hematocrit", and "relative viscosity" where measured.
  void addResults(io::JsonValue& summary) const;

  void save(io::Checkpoint& checkpoint) const;
  void load(const io::Checkpoint& checkpoint, const std::string& source);

private:
  SuspensionOutputSettings settings_;
  const domain::Domain& domain_;
  double top_ = 0.0, lengthX_ = 0.0, lengthZ_ = 0.0;
  bool periodicChannel_ = false;
  std::vector<double> sum_; // of the profiles in the window
  double viscositySum_ = 0.0;
  std::int64_t averaged_ = 0;
  // Outputs in the window with a relative viscosity: an instant of a pulsatile flow at rest
  // has none (NaN) and stays out of its mean.
  std::int64_t viscosityAveraged_ = 0;
};

} // namespace capsula::run
