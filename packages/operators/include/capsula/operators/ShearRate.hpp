#pragma once
// The imposed shear rate as a function of time, k(t) = k_mean f(t), with f dimensionless
// and time in units of 1/k_mean (the thesis's nondimensionalisation, eq 3.15, with the
// mean shear rate: Ca = mu k_mean a / G). The flow is quasi-static (Stokes), so f(t) scales
// the undisturbed flow u_inf = (f(t) y, 0, 0) of the instant (LinearFlow.hpp).
//
//   Steady     f = 1
//   Pulsatile  f = 1 + A sin(2 pi t / T)           (mean 1 over a period T)
//   Tabulated  f = linear interpolation of a two-column file (time, shear rate), repeated
//              with period T = the last time; the values are divided by their mean over
//              a period (the integral of the interpolant over T), so that f has mean 1.
//
// f depends on t alone: a restart at any t continues the same function.
#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace capsula::operators {

class ShearRate {
public:
  enum class Form { Steady, Pulsatile, Tabulated };

  /// f = 1.
  ShearRate() = default;
  /// f = 1 + amplitude sin(2 pi t / period).
  static ShearRate pulsatile(double amplitude, double period);
  /// f from samples (times[0] = 0 < times[1] < ... , period = times.back(); values
  /// first == last), divided by their mean over the period.
  static ShearRate tabulated(std::vector<double> times, std::vector<double> values);

  /// f(t): exactly 1 for the steady form and for a pulsatile amplitude 0.
  double factor(double t) const;
  Form form() const { return form_; }
  bool periodic() const { return form_ != Form::Steady; }
  /// T (0 when steady).
  double period() const { return period_; }
  double amplitude() const { return amplitude_; }
  /// The tabulated samples after the normalisation to mean 1, and the mean removed.
  const std::vector<double>& times() const { return times_; }
  const std::vector<double>& values() const { return values_; }
  double tabulatedMean() const { return tabulatedMean_; }
  /// times() then values() (empty unless tabulated): what a checkpoint keeps of a waveform,
  /// so that a restart can refuse a waveform file changed since.
  std::vector<double> waveformSamples() const;
  /// min and max of f over a period.
  double minimum() const;
  double maximum() const;
  /// One line for the run log: "steady", "pulsatile, amplitude 0.5, period 10", ...
  std::string describe() const;

private:
  Form form_ = Form::Steady;
  double amplitude_ = 0.0;
  double period_ = 0.0;
  double tabulatedMean_ = 1.0;
  std::vector<double> times_;
  std::vector<double> values_;
};

/// The defaults of the pulsatile form's keys (a key of another form must keep its default).
constexpr double kDefaultAmplitude = 0.5;
constexpr double kDefaultPeriod = 10.0;

/// Declares Form, Amplitude, Period, Waveform file and Allow reversal in `shearRate` (the
/// "Flow/Shear rate" sublist).
void declareShearRateParameters(Teuchos::ParameterList& shearRate);

/// Reads a validated "Shear rate" sublist; `path` is its key path for messages ("Flow/Shear
/// rate"). Throws core::InputError naming the key (and the file and line of a waveform) for
/// a reversing flow without 'Allow reversal' and for a waveform file that is missing,
/// non-numeric, unsorted, too short, not starting at 0 or not closing (last value != first).
ShearRate readShearRate(const Teuchos::ParameterList& shearRate, const std::string& path);

/// Reads the two columns (time, shear rate) of a waveform file: '#' starts a comment,
/// blank lines are skipped. Throws core::InputError naming `key`, the file and the line.
ShearRate readWaveformFile(const std::string& fileName, const std::string& key, bool allowReversal);

/// Refuses (core::InputError naming both keys) an output interval `interval` (in run time
/// units over `timeScale`: tether2d's tau = k t / lambda has timeScale lambda) that neither
/// divides the period of a periodic shear rate into a whole number of outputs nor is a whole
/// number of periods: every period is then sampled at the same phases. Nothing for a steady
/// one.
void requireOutputsCommensurate(const ShearRate& rate, const std::string& ratePath, double interval,
                                const std::string& intervalKey, double timeScale = 1.0);

/// Refuses (core::InputError naming the keys) a steady-state stop ('Time integration/Steady
/// tolerance' > 0) under a periodic shear rate: the state never stops changing, and a stop
/// at a moment of slow change would end the run at a random phase.
void requireNoSteadyStop(const ShearRate& rate, const std::string& ratePath, double steadyTolerance);

/// The largest time step for a run under `rate`: `maximumStep`, and with a periodic shear
/// rate at most period / kStepsPerPeriod.
constexpr double kStepsPerPeriod = 20.0;
double limitStepToPeriod(double maximumStep, const ShearRate& rate);

} // namespace capsula::operators
