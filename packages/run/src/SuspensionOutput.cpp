#include "capsula/run/SuspensionOutput.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>

#include <cmath>
#include <sstream>

namespace capsula::run {

namespace core = capsula::core;

void declareSuspensionOutputParameters(Teuchos::ParameterList& suspension)
{
  core::declareBool(suspension, "Enabled", false,
                    "Measure the suspension at every output: the cell-free layer along each wall "
                    "(metrics.csv cell_free_layer_lower, cell_free_layer_upper in a channel) and the "
                    "hematocrit profile across y (suspension.h5), averaged in summary.json "
                    "(docs/suspensions.md, section 'Outputs of a run').");
  core::declareInt(suspension, "Bins", 20, "Slabs of equal thickness the hematocrit profile cuts the box into.", 1);
  core::declareReal(suspension, "Average from", 0.0,
                    "summary.json's hematocrit is the mean of the profiles at the outputs at this "
                    "time and later.",
                    core::atLeast(0.0));
  core::declareReal(suspension, "Height", 0.0,
                    "Top of the box across y without a channel (the box is 0 < y < Height); in a "
                    "channel the box is 0 < y < H and this must be 0.",
                    core::atLeast(0.0));
  core::declareReal(suspension, "Box length x", 0.0,
                    "The box's length along x, over which a slab's volume fraction is taken, where "
                    "the domain is not periodic along x (periodic: the period, and this must be 0).",
                    core::atLeast(0.0));
  core::declareReal(suspension, "Box length z", 0.0, "As 'Box length x', along z.", core::atLeast(0.0));
  core::declareString(suspension, "Hematocrit type", "",
                      "The cell 'Type' whose cells the hematocrit profile and the cell-free layer count "
                      "(the red cells, for the red-cell-free layer of the margination literature); empty: "
                      "every cell. suspension3d reads empty as the type that fills 'Suspension/Hematocrit' (every "
                      "cell when each type has a 'Count').");
  core::declareInt(suspension, "Columns", 32,
                   "Columns per period along x and along z over which the cell-free layer is "
                   "averaged in a channel periodic along x and z (CellFreeLayer.hpp).",
                   1);
}

namespace {

// A box length that the domain fixes (`fixed` > 0, named by `fixedBy`) or the deck must give
// (`what`: "height", "length along x", ...).
void requireBoxLength(double fixed, const char* fixedBy, double given, const char* key, const char* what)
{
  if (fixed > 0.0) {
    core::require<core::InputError>(given == 0.0, "'Output/Suspension/", key, "' = ", given, " is given, but ", fixedBy,
                                    " = ", fixed, " is the box's length there; leave it at 0.");
    return;
  }
  core::require<core::InputError>(given > 0.0, "'Output/Suspension/", key, "' = 0, but ", fixedBy,
                                  " does not bound the domain: give the box's ", what,
                                  " over which the hematocrit is taken (> 0).");
}

} // namespace

SuspensionOutputSettings readSuspensionOutputSettings(const Teuchos::ParameterList& suspension,
                                                      const domain::Domain& domain)
{
  SuspensionOutputSettings out;
  out.enabled = suspension.get<bool>("Enabled");
  out.bins = suspension.get<int>("Bins");
  out.averageFrom = suspension.get<double>("Average from");
  out.height = suspension.get<double>("Height");
  out.boxLengthX = suspension.get<double>("Box length x");
  out.boxLengthZ = suspension.get<double>("Box length z");
  out.columns = suspension.get<int>("Columns");
  out.hematocritType = suspension.get<std::string>("Hematocrit type");
  if (!out.enabled) {
    return out;
  }
  core::require<core::InputError>(domain.hasLowerWall(),
                                  "'Output/Suspension/Enabled' is true but 'Wall/Enabled' is false: the profile "
                                  "and the cell-free layer are measured from the lower wall.");
  requireBoxLength(domain.channelHeight(), "'Wall/Channel height'", out.height, "Height", "height");
  requireBoxLength(domain.period(domain::flowAxis), "'Domain/Periodic length x'", out.boxLengthX, "Box length x",
                   "length along x");
  requireBoxLength(domain.period(domain::vorticityAxis), "'Domain/Periodic length z'", out.boxLengthZ, "Box length z",
                   "length along z");
  return out;
}

SuspensionOutput::SuspensionOutput(const SuspensionOutputSettings& settings, const domain::Domain& domain)
    : settings_(settings),
      domain_(domain),
      top_(domain.hasUpperWall() ? domain.channelHeight() : settings.height),
      lengthX_(domain.isPeriodic(domain::flowAxis) ? domain.period(domain::flowAxis) : settings.boxLengthX),
      lengthZ_(domain.isPeriodic(domain::vorticityAxis) ? domain.period(domain::vorticityAxis) : settings.boxLengthZ),
      periodicChannel_(domain.hasUpperWall() && domain.isPeriodic(domain::flowAxis) &&
                       domain.isPeriodic(domain::vorticityAxis))
{}

std::string SuspensionOutput::term() const
{
  std::ostringstream line;
  line << "output: suspension: hematocrit in " << settings_.bins << " slabs of 0 < y < " << top_ << " over " << lengthX_
       << " x " << lengthZ_ << ", averaged from t = " << settings_.averageFrom << "; cell-free layer "
       << (periodicChannel_ ? "averaged over " + std::to_string(settings_.columns) + " x " +
                                  std::to_string(settings_.columns) + " columns"
                            : std::string("as the smallest wall distance of the cells"));
  return line.str();
}

std::vector<std::string> SuspensionOutput::columns() const
{
  std::vector<std::string> columns{"cell_free_layer_lower"};
  if (domain_.hasUpperWall()) {
    columns.push_back("cell_free_layer_upper");
  }
  if (periodicChannel_) {
    columns.push_back("relative_viscosity");
  }
  return columns;
}

SuspensionSample SuspensionOutput::measure(double t, const std::vector<const mesh::SurfaceMesh*>& cells,
                                           double relativeViscosity)
{
  SuspensionSample sample;
  sample.time = t;
  sample.relativeViscosity = relativeViscosity;
  sample.profile = suspension::hematocritProfileInSlab(cells, top_, lengthX_ * lengthZ_, settings_.bins);
  sample.layer = periodicChannel_ ? suspension::cellFreeLayer(cells, domain_, settings_.columns, settings_.columns)
                                  : suspension::thinnestCellFreeLayer(cells, domain_);
  if (t >= settings_.averageFrom) {
    sum_.resize(sample.profile.fraction.size(), 0.0);
    for (std::size_t k = 0; k < sum_.size(); ++k) {
      sum_[k] += sample.profile.fraction[k];
    }
    if (std::isfinite(relativeViscosity)) {
      viscositySum_ += relativeViscosity;
      ++viscosityAveraged_;
    }
    ++averaged_;
  }
  return sample;
}

std::vector<double> SuspensionOutput::row(const SuspensionSample& sample) const
{
  std::vector<double> row{sample.layer.lower};
  if (domain_.hasUpperWall()) {
    row.push_back(sample.layer.upper);
  }
  if (periodicChannel_) {
    row.push_back(sample.relativeViscosity);
  }
  return row;
}

std::vector<double> SuspensionOutput::binCentres() const
{
  std::vector<double> centres;
  for (int k = 0; k < settings_.bins; ++k) {
    centres.push_back(top_ * (k + 0.5) / settings_.bins);
  }
  return centres;
}

io::SnapshotBlock SuspensionOutput::profileBlock(const SuspensionSample& sample) const
{
  io::SnapshotBlock block;
  block.name = "hematocrit";
  block.topology = io::Topology::Polylines;
  block.nodesPerPolyline = settings_.bins;
  for (double y : binCentres()) {
    block.positions.insert(block.positions.end(), {0.0, y, 0.0});
  }
  for (int k = 0; k < settings_.bins; ++k) {
    block.connectivity.push_back(k);
  }
  block.nodeFields.push_back({"hematocrit", 1, sample.profile.fraction});
  return block;
}

std::vector<double> SuspensionOutput::averageProfile() const
{
  std::vector<double> average = sum_;
  for (double& value : average) {
    value /= static_cast<double>(averaged_);
  }
  return average;
}

void SuspensionOutput::addResults(io::JsonValue& summary) const
{
  io::JsonValue& hematocrit = summary["hematocrit"];
  hematocrit["average from"] = settings_.averageFrom;
  hematocrit["outputs averaged"] = static_cast<long long>(averaged_);
  hematocrit["box"]["height"] = top_;
  hematocrit["box"]["length x"] = lengthX_;
  hematocrit["box"]["length z"] = lengthZ_;
  hematocrit["bin centres"] = io::JsonValue::array(binCentres());
  hematocrit["values"] = io::JsonValue::array(averageProfile());
  if (periodicChannel_) {
    io::JsonValue& viscosity = summary["relative viscosity"];
    viscosity["average from"] = settings_.averageFrom;
    viscosity["outputs averaged"] = static_cast<long long>(viscosityAveraged_);
    if (viscosityAveraged_ > 0) {
      viscosity["value"] = viscositySum_ / static_cast<double>(viscosityAveraged_);
    }
  }
}

void SuspensionOutput::save(io::Checkpoint& checkpoint) const
{
  if (!sum_.empty()) { // empty before the window opens
    checkpoint.arrays["suspension.hematocrit sum"] = sum_;
  }
  checkpoint.integers["suspension.outputs averaged"] = averaged_;
  if (periodicChannel_) {
    checkpoint.reals["suspension.relative viscosity sum"] = viscositySum_;
    checkpoint.integers["suspension.relative viscosity outputs"] = viscosityAveraged_;
  }
}

void SuspensionOutput::load(const io::Checkpoint& checkpoint, const std::string& source)
{
  const auto sum = checkpoint.arrays.find("suspension.hematocrit sum");
  const auto count = checkpoint.integers.find("suspension.outputs averaged");
  core::require<core::IoError>(count != checkpoint.integers.end(), "The checkpoint '", source,
                               "' lacks the suspension's running average ('suspension.'); it was written "
                               "without 'Output/Suspension/Enabled'.");
  sum_ = sum == checkpoint.arrays.end() ? std::vector<double>{} : sum->second;
  core::require<core::IoError>((sum_.empty() && count->second == 0) ||
                                   sum_.size() == static_cast<std::size_t>(settings_.bins),
                               "The checkpoint '", source, "' holds a hematocrit profile of ", sum_.size(),
                               " bins, not 'Output/Suspension/Bins' = ", settings_.bins, ".");
  averaged_ = count->second;
  if (periodicChannel_) {
    const auto viscosity = checkpoint.reals.find("suspension.relative viscosity sum");
    core::require<core::IoError>(viscosity != checkpoint.reals.end(), "The checkpoint '", source,
                                 "' lacks the relative viscosity's running sum ('suspension.relative viscosity "
                                 "sum'); it was written by a version without it.");
    viscositySum_ = viscosity->second;
    // A checkpoint written before the count was kept summed every output of the window.
    const auto outputs = checkpoint.integers.find("suspension.relative viscosity outputs");
    viscosityAveraged_ = outputs == checkpoint.integers.end() ? averaged_ : outputs->second;
  }
}

} // namespace capsula::run
