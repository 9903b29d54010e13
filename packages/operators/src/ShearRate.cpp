#include "capsula/operators/ShearRate.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace capsula::operators {

namespace core = capsula::core;

ShearRate ShearRate::pulsatile(double amplitude, double period)
{
  core::require<core::InputError>(std::isfinite(period) && period > 0.0, "ShearRate: the period ", period,
                                  " must be > 0");
  core::require<core::InputError>(std::isfinite(amplitude) && amplitude >= 0.0, "ShearRate: the amplitude ", amplitude,
                                  " must be >= 0");
  ShearRate rate;
  rate.form_ = Form::Pulsatile;
  rate.amplitude_ = amplitude;
  rate.period_ = period;
  return rate;
}

ShearRate ShearRate::tabulated(std::vector<double> times, std::vector<double> values)
{
  core::require<core::InputError>(times.size() >= 2 && times.size() == values.size(),
                                  "ShearRate: a waveform needs at least two samples, got ", times.size());
  core::require<core::InputError>(times.front() == 0.0, "ShearRate: a waveform starts at time 0, not ", times.front());
  for (std::size_t i = 1; i < times.size(); ++i) {
    core::require<core::InputError>(times[i] > times[i - 1], "ShearRate: waveform times must increase");
  }
  core::require<core::InputError>(values.front() == values.back(),
                                  "ShearRate: a waveform's last value must equal its first");
  double integral = 0.0; // of the linear interpolant: the trapezoidal rule is exact
  for (std::size_t i = 1; i < times.size(); ++i) {
    integral += 0.5 * (values[i] + values[i - 1]) * (times[i] - times[i - 1]);
  }
  const double mean = integral / times.back();
  core::require<core::InputError>(mean > 0.0, "ShearRate: a waveform's mean ", mean,
                                  " must be > 0 (the flow's direction and the Ca's shear rate)");
  ShearRate rate;
  rate.form_ = Form::Tabulated;
  rate.period_ = times.back();
  rate.tabulatedMean_ = mean;
  for (double& v : values) {
    v /= mean;
  }
  rate.times_ = std::move(times);
  rate.values_ = std::move(values);
  return rate;
}

double ShearRate::factor(double t) const
{
  switch (form_) {
  case Form::Steady:
    return 1.0;
  case Form::Pulsatile:
    return 1.0 + amplitude_ * std::sin(2.0 * M_PI * t / period_);
  case Form::Tabulated: {
    double s = std::fmod(t, period_);
    if (s < 0.0) {
      s += period_;
    }
    // times_[i] <= s < times_[i + 1]
    const auto upper = std::upper_bound(times_.begin(), times_.end(), s);
    const std::size_t i =
        std::min<std::size_t>(static_cast<std::size_t>(upper - times_.begin()), times_.size() - 1) - 1;
    const double w = (s - times_[i]) / (times_[i + 1] - times_[i]);
    return values_[i] + w * (values_[i + 1] - values_[i]);
  }
  }
  return 1.0;
}

std::vector<double> ShearRate::waveformSamples() const
{
  std::vector<double> samples = times_;
  samples.insert(samples.end(), values_.begin(), values_.end());
  return samples;
}

double ShearRate::minimum() const
{
  switch (form_) {
  case Form::Steady:
    return 1.0;
  case Form::Pulsatile:
    return 1.0 - amplitude_;
  case Form::Tabulated:
    return *std::min_element(values_.begin(), values_.end());
  }
  return 1.0;
}

double ShearRate::maximum() const
{
  switch (form_) {
  case Form::Steady:
    return 1.0;
  case Form::Pulsatile:
    return 1.0 + amplitude_;
  case Form::Tabulated:
    return *std::max_element(values_.begin(), values_.end());
  }
  return 1.0;
}

std::string ShearRate::describe() const
{
  std::ostringstream line;
  switch (form_) {
  case Form::Steady:
    line << "steady, k = 1";
    break;
  case Form::Pulsatile:
    line << "pulsatile, k = 1 + " << amplitude_ << " sin(2 pi t / " << period_ << ")";
    break;
  case Form::Tabulated:
    line << "tabulated waveform of " << times_.size() << " samples, period " << period_ << ", divided by its mean "
         << tabulatedMean_ << ", k from " << minimum() << " to " << maximum();
    break;
  }
  return line.str();
}

void declareShearRateParameters(Teuchos::ParameterList& shearRate)
{
  core::declareChoice(shearRate, "Form", "Steady", {"Steady", "Pulsatile", "Tabulated"},
                      "The shear rate k(t) over its mean (the mean is the k of the capillary number; time "
                      "is in units of 1/k_mean). Steady: k = 1. Pulsatile: k = 1 + Amplitude sin(2 pi t / "
                      "Period). Tabulated: the two columns (time, shear rate) of 'Waveform file', "
                      "interpolated linearly and repeated with the period of its last time, divided by "
                      "their mean. The undisturbed flow of the instant is (k(t) y, 0, 0).");
  core::declareReal(shearRate, "Amplitude", kDefaultAmplitude,
                    "Pulsatile: the amplitude A of k = 1 + A sin(2 pi t / T), relative to the mean. A > 1 "
                    "reverses the flow for part of the period and needs 'Allow reversal'. Another 'Form' "
                    "with a value other than the default is refused (it would have no effect).",
                    core::atLeast(0.0));
  core::declareReal(shearRate, "Period", kDefaultPeriod,
                    "Pulsatile: the period T, in units of 1/k_mean. 'Output/Interval' (tether2d: times "
                    "lambda) must divide it into a whole number of outputs, be a whole number of "
                    "periods or 0, and the time step is at most T/20. Another 'Form' with a value other "
                    "than the default is refused (it would have no effect).",
                    core::greaterThan(0.0));
  core::declareString(shearRate, "Waveform file", "",
                      "Tabulated: a text file of two columns, time (from 0; the last time is the "
                      "period) and shear rate (any unit: divided by the mean over the period); the "
                      "last shear rate equals the first. '#' starts a comment. A relative name is "
                      "taken from the directory the run starts in. Outputs and steps follow its "
                      "period as they follow 'Period'.");
  core::declareBool(shearRate, "Allow reversal", false,
                    "Allow a shear rate that changes sign during the period (Amplitude > 1, a "
                    "negative waveform value); refused otherwise.");
}

namespace {

// The whole token as a finite real, or false.
bool parseReal(const std::string& token, double& value)
{
  errno = 0;
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return end != token.c_str() && *end == '\0' && errno != ERANGE && std::isfinite(value);
}

} // namespace

ShearRate readWaveformFile(const std::string& fileName, const std::string& key, bool allowReversal)
{
  const std::string where = "'" + key + "' = '" + fileName + "'";
  core::require<core::InputError>(!fileName.empty(), "'", key,
                                  "' is empty: 'Tabulated' needs a two-column waveform file (time, shear rate).");
  std::ifstream in(fileName);
  core::require<core::InputError>(static_cast<bool>(in), where, ": the file cannot be opened (missing or unreadable).");
  std::vector<double> times, values;
  std::vector<int> lines;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    text = text.substr(0, text.find('#'));
    std::replace(text.begin(), text.end(), ',', ' ');
    std::istringstream fields(text);
    std::vector<std::string> tokens;
    for (std::string token; fields >> token;) {
      tokens.push_back(token);
    }
    if (tokens.empty()) {
      continue;
    }
    core::require<core::InputError>(tokens.size() == 2, where, ", line ", line, ": ", tokens.size(),
                                    " columns; each line holds two, time and shear rate.");
    double t = 0.0, k = 0.0;
    for (int c = 0; c < 2; ++c) {
      core::require<core::InputError>(parseReal(tokens[static_cast<std::size_t>(c)], c == 0 ? t : k), where, ", line ",
                                      line, ": '", tokens[static_cast<std::size_t>(c)], "' (the ",
                                      c == 0 ? "time" : "shear rate", ") is not a finite number.");
    }
    if (times.empty()) {
      core::require<core::InputError>(t == 0.0, where, ", line ", line, ": the first time is ", t,
                                      "; the waveform starts at time 0.");
    } else {
      core::require<core::InputError>(t > times.back(), where, ", line ", line, ": time ", t,
                                      " does not come after the ", times.back(), " of line ", lines.back(),
                                      ": the times must increase.");
    }
    core::require<core::InputError>(allowReversal || k >= 0.0, where, ", line ", line, ": shear rate ", k,
                                    " < 0 reverses the flow; set '",
                                    key.substr(0, key.rfind('/') + 1) + "Allow reversal", "' = true to allow it.");
    times.push_back(t);
    values.push_back(k);
    lines.push_back(line);
  }
  core::require<core::InputError>(times.size() >= 2, where, ": ", times.size(),
                                  " sample(s); a waveform needs at least two lines (time 0 and the period).");
  core::require<core::InputError>(values.back() == values.front(), where, ", line ", lines.back(),
                                  ": the last shear rate ", values.back(), " differs from the first, ", values.front(),
                                  " (line ", lines.front(), "): the repeated waveform would jump at the period.");
  try {
    return ShearRate::tabulated(std::move(times), std::move(values));
  } catch (const core::InputError& e) {
    throw core::InputError(core::message(where, ": ", e.what()));
  }
}

namespace {

// A key of another form than the deck's, set to a value other than its default, would have
// no effect: refused, as every key a scene does not use (docs/user-guide.md, "Keys without
// effect").
void requireUnusedAtDefault(bool unused, bool atDefault, const std::string& path, const std::string& key,
                            const std::string& value, const std::string& form, const std::string& usedBy)
{
  core::require<core::InputError>(!unused || atDefault, "'", path, "/", key, "' = ", value, " has no effect with '",
                                  path, "/Form' = ", form, ": it is read by Form ", usedBy, ". Set '", path,
                                  "/Form' = ", usedBy, " or remove the key.");
}

} // namespace

ShearRate readShearRate(const Teuchos::ParameterList& shearRate, const std::string& path)
{
  const std::string form = shearRate.get<std::string>("Form");
  const double amplitude = shearRate.get<double>("Amplitude"), period = shearRate.get<double>("Period");
  const std::string waveform = shearRate.get<std::string>("Waveform file");
  requireUnusedAtDefault(form != "Pulsatile", amplitude == kDefaultAmplitude, path, "Amplitude",
                         core::message(amplitude), form, "Pulsatile");
  requireUnusedAtDefault(form != "Pulsatile", period == kDefaultPeriod, path, "Period", core::message(period), form,
                         "Pulsatile");
  requireUnusedAtDefault(form != "Tabulated", waveform.empty(), path, "Waveform file", "'" + waveform + "'", form,
                         "Tabulated");
  const bool allowReversal = shearRate.get<bool>("Allow reversal");
  if (form == "Pulsatile") {
    core::require<core::InputError>(allowReversal || amplitude <= 1.0, "'", path, "/Amplitude' = ", amplitude,
                                    " > 1 reverses the flow for part of the period (k = 1 + A sin(2 pi t / T) < 0); "
                                    "lower it to at most 1 or set '",
                                    path, "/Allow reversal' = true.");
    return ShearRate::pulsatile(amplitude, period);
  }
  if (form == "Tabulated") {
    return readWaveformFile(waveform, path + "/Waveform file", allowReversal);
  }
  return ShearRate();
}

void requireNoSteadyStop(const ShearRate& rate, const std::string& ratePath, double steadyTolerance)
{
  core::require<core::InputError>(!rate.periodic() || steadyTolerance == 0.0,
                                  "'Time integration/Steady tolerance' = ", steadyTolerance,
                                  " stops a run when its state stops changing, which it never does under a periodic "
                                  "shear rate ('",
                                  ratePath, "/Form' is not Steady): set it to 0 and choose the end time.");
}

double limitStepToPeriod(double maximumStep, const ShearRate& rate)
{
  return rate.periodic() ? std::min(maximumStep, rate.period() / kStepsPerPeriod) : maximumStep;
}

void requireOutputsCommensurate(const ShearRate& rate, const std::string& ratePath, double interval,
                                const std::string& intervalKey, double timeScale)
{
  // Interval 0 writes only the start and the end: no output falls at a phase of the period.
  if (!rate.periodic() || interval == 0.0) {
    return;
  }
  const double period = rate.period();
  const double perPeriod = period / (interval * timeScale);
  // A relative 1e-9 lets decimal intervals such as 0.1 of a period 1 through.
  const auto whole = [](double x) { return std::round(x) >= 1.0 && std::abs(x - std::round(x)) <= 1e-9 * x; };
  if (whole(perPeriod) || whole(1.0 / perPeriod)) { // n outputs per period, or one every n periods
    return;
  }
  const double wholeCount = std::round(perPeriod);
  const std::string periodKey = rate.form() == ShearRate::Form::Pulsatile
                                    ? "'" + ratePath + "/Period'"
                                    : "the last time of '" + ratePath + "/Waveform file'";
  const double suggested = period / std::max(1.0, wholeCount) / timeScale;
  throw core::InputError(core::message(
      "'", intervalKey, "' = ", interval, timeScale != 1.0 ? core::message(" (times lambda = ", timeScale, ")") : "",
      " does not divide the shear rate's period ", period, " (", periodKey, ") into a whole number of outputs (",
      perPeriod, " per period): the outputs would fall at another phase each period. Set '", intervalKey, "' to ",
      suggested, ", or another period / n or n periods", timeScale != 1.0 ? " (divided by lambda)" : "", "."));
}

} // namespace capsula::operators
