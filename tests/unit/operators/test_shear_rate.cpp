// ShearRate: the imposed shear rate k(t) over its mean (ShearRate.hpp), its deck keys, the
// waveform file and the output-interval rule.
#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/operators/ShearRate.hpp>

#include <Teuchos_ParameterList.hpp>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace core = capsula::core;
using capsula::operators::ShearRate;

// The mean of f over [0, T] by the trapezoidal rule on n intervals.
double periodMean(const ShearRate& rate, int n)
{
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    sum += rate.factor(rate.period() * i / n);
  }
  return sum / n;
}

// A waveform file in the temporary directory with `text`; removed by the caller.
std::string writeWaveform(const std::string& name, const std::string& text)
{
  const auto path =
      std::filesystem::temp_directory_path() / ("capsula-waveform-" + std::to_string(::getpid()) + "-" + name);
  std::ofstream(path) << text;
  return path.string();
}

// The message of the core::InputError that `f` throws ("" if none).
template <typename F>
std::string inputError(F&& f)
{
  try {
    f();
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "";
}

Teuchos::ParameterList shearRateList(const std::string& form)
{
  Teuchos::ParameterList valid, list;
  capsula::operators::declareShearRateParameters(valid);
  list.set("Form", form);
  list.validateParametersAndSetDefaults(valid);
  return list;
}

TEST(ShearRate, SteadyIsExactlyOne)
{
  const ShearRate steady;
  EXPECT_FALSE(steady.periodic());
  for (const double t : {0.0, 0.3, 7.25, 1e6}) {
    EXPECT_EQ(steady.factor(t), 1.0);
  }
}

TEST(ShearRate, PulsatileHasMeanOneAndItsQuarterPeriodValues)
{
  const ShearRate rate = ShearRate::pulsatile(0.4, 3.0);
  ASSERT_TRUE(rate.periodic());
  EXPECT_EQ(rate.period(), 3.0);
  // 1 + A sin(2 pi t / T): rounding of sin(pi / 2) etc. only.
  EXPECT_NEAR(rate.factor(0.0), 1.0, 1e-15);
  EXPECT_NEAR(rate.factor(0.75), 1.4, 1e-15);
  EXPECT_NEAR(rate.factor(1.5), 1.0, 1e-15);
  EXPECT_NEAR(rate.factor(2.25), 0.6, 1e-15);
  EXPECT_NEAR(rate.factor(3.0 + 0.75), 1.4, 1e-14); // periodic
  // The trapezoidal rule on 16 points integrates sin exactly: the mean is 1 to round-off.
  EXPECT_NEAR(periodMean(rate, 16), 1.0, 1e-14);
  EXPECT_EQ(rate.minimum(), 1.0 - 0.4);
  EXPECT_EQ(rate.maximum(), 1.0 + 0.4);
  // Amplitude 0 is the steady shear, bit for bit.
  const ShearRate flat = ShearRate::pulsatile(0.0, 3.0);
  for (const double t : {0.0, 0.1, 0.75, 2.9, 123.4}) {
    EXPECT_EQ(flat.factor(t), 1.0);
  }
}

TEST(ShearRate, TabulatedIsExactAtTheSamplesPeriodicAndOfMeanOne)
{
  // Raw mean (1 + 3) / 2 * 0.25 + (3 + 1) / 2 * 0.25 + 1 * 0.5 = 1.5: f = raw / 1.5.
  const ShearRate rate = ShearRate::tabulated({0.0, 0.25, 0.5, 1.0}, {1.0, 3.0, 1.0, 1.0});
  EXPECT_EQ(rate.period(), 1.0);
  EXPECT_EQ(rate.tabulatedMean(), 1.5);
  EXPECT_EQ(rate.factor(0.25), 2.0);  // at a sample: exact
  EXPECT_EQ(rate.factor(1.25), 2.0);  // a period later (1.25 - 1 is exact)
  EXPECT_EQ(rate.factor(-0.75), 2.0); // and before
  EXPECT_EQ(rate.factor(0.0), 1.0 / 1.5);
  EXPECT_EQ(rate.factor(1.0), 1.0 / 1.5);
  EXPECT_NEAR(rate.factor(0.125), 0.5 * (1.0 / 1.5 + 2.0), 1e-15); // linear in between
  EXPECT_NEAR(rate.factor(0.375), 0.5 * (1.0 / 1.5 + 2.0), 1e-15);
  EXPECT_NEAR(rate.factor(0.75), 1.0 / 1.5, 1e-15);
  // The breakpoints lie on the 4000-point grid: the trapezoidal rule is exact.
  EXPECT_NEAR(periodMean(rate, 4000), 1.0, 1e-13);
}

TEST(ShearRate, ReadsAWaveformFile)
{
  const std::string file = writeWaveform("good", "# time, shear rate\n0 2\n\n0.5, 6  # peak\n2 2\n");
  const ShearRate rate = capsula::operators::readWaveformFile(file, "Flow/Shear rate/Waveform file", false);
  std::filesystem::remove(file);
  EXPECT_EQ(rate.form(), ShearRate::Form::Tabulated);
  EXPECT_EQ(rate.period(), 2.0);
  // Integral (2 + 6) / 2 * 0.5 + (6 + 2) / 2 * 1.5 = 8 over T = 2: mean 4.
  EXPECT_EQ(rate.tabulatedMean(), 4.0);
  EXPECT_EQ(rate.factor(0.5), 1.5);
  EXPECT_EQ(rate.factor(2.5), 1.5);
}

TEST(ShearRate, RefusesABadWaveformFileNamingKeyAndLine)
{
  const std::string key = "Flow/Shear rate/Waveform file";
  const auto refusal = [&key](const std::string& name, const std::string& text, bool allowReversal = false) {
    const std::string file = writeWaveform(name, text);
    const std::string message = inputError([&] { capsula::operators::readWaveformFile(file, key, allowReversal); });
    std::filesystem::remove(file);
    return message;
  };
  const std::string missing =
      inputError([&] { capsula::operators::readWaveformFile("/nonexistent/w.dat", key, false); });
  EXPECT_NE(missing.find("'Flow/Shear rate/Waveform file' = '/nonexistent/w.dat'"), std::string::npos) << missing;
  EXPECT_NE(missing.find("cannot be opened"), std::string::npos) << missing;

  const std::string unsorted = refusal("unsorted", "0 1\n0.5 2\n0.4 1\n1 1\n");
  EXPECT_NE(unsorted.find(key), std::string::npos) << unsorted;
  EXPECT_NE(unsorted.find("line 3: time 0.4 does not come after the 0.5 of line 2"), std::string::npos) << unsorted;

  const std::string text = refusal("text", "0 1\n0.5 fast\n1 1\n");
  EXPECT_NE(text.find("line 2: 'fast' (the shear rate) is not a finite number"), std::string::npos) << text;
  EXPECT_NE(refusal("columns", "0 1\n0.5 2 3\n1 1\n").find("line 2: 3 columns"), std::string::npos);
  EXPECT_NE(refusal("start", "# c\n0.1 1\n1 1\n").find("line 2: the first time is 0.1"), std::string::npos);
  EXPECT_NE(refusal("open", "0 1\n0.5 2\n1 1.5\n").find("line 3: the last shear rate 1.5 differs"), std::string::npos);
  EXPECT_NE(refusal("short", "0 1\n").find("1 sample(s)"), std::string::npos);

  const std::string reversing = refusal("reversing", "0 1\n0.5 -0.5\n1 1\n");
  EXPECT_NE(reversing.find("line 2: shear rate -0.5 < 0 reverses the flow"), std::string::npos) << reversing;
  EXPECT_NE(reversing.find("'Flow/Shear rate/Allow reversal'"), std::string::npos) << reversing;
  EXPECT_EQ(refusal("allowed", "0 1\n0.5 -0.5\n1 1\n", true), ""); // allowed: mean 0.625 > 0
  EXPECT_NE(refusal("negative mean", "0 -1\n1 -1\n", true).find("mean -1 must be > 0"), std::string::npos);
}

TEST(ShearRate, ReadsTheDeckAndRefusesAReversingAmplitude)
{
  EXPECT_FALSE(capsula::operators::readShearRate(shearRateList("Steady"), "Flow/Shear rate").periodic());
  Teuchos::ParameterList list = shearRateList("Pulsatile");
  list.set("Amplitude", 0.25);
  list.set("Period", 4.0);
  const ShearRate rate = capsula::operators::readShearRate(list, "Flow/Shear rate");
  EXPECT_EQ(rate.amplitude(), 0.25);
  EXPECT_EQ(rate.period(), 4.0);
  list.set("Amplitude", 1.5);
  const std::string message = inputError([&] { capsula::operators::readShearRate(list, "Flow/Shear rate"); });
  EXPECT_NE(message.find("'Flow/Shear rate/Amplitude' = 1.5 > 1 reverses the flow"), std::string::npos) << message;
  EXPECT_NE(message.find("'Flow/Shear rate/Allow reversal' = true"), std::string::npos) << message;
  list.set("Allow reversal", true);
  EXPECT_EQ(capsula::operators::readShearRate(list, "Flow/Shear rate").minimum(), -0.5);
  // Amplitude 1 touches zero and is allowed.
  list.set("Allow reversal", false);
  list.set("Amplitude", 1.0);
  EXPECT_EQ(capsula::operators::readShearRate(list, "Flow/Shear rate").minimum(), 0.0);
}

// A pulsatile key under another form, or a waveform file under a form that reads none, would
// be ignored: refused, naming the key, its value and the form that reads it.
TEST(ShearRate, KeysOfAnotherFormAreRefused)
{
  Teuchos::ParameterList steady = shearRateList("Steady");
  steady.set("Amplitude", 0.3);
  const std::string amplitude = inputError([&] { capsula::operators::readShearRate(steady, "Flow/Shear rate"); });
  EXPECT_NE(amplitude.find("'Flow/Shear rate/Amplitude' = 0.3 has no effect with 'Flow/Shear rate/Form' = Steady"),
            std::string::npos)
      << amplitude;
  EXPECT_NE(amplitude.find("Set 'Flow/Shear rate/Form' = Pulsatile"), std::string::npos) << amplitude;
  Teuchos::ParameterList pulsatile = shearRateList("Pulsatile");
  pulsatile.set("Waveform file", std::string("w.dat"));
  const std::string waveform = inputError([&] { capsula::operators::readShearRate(pulsatile, "Flow/Shear rate"); });
  EXPECT_NE(waveform.find("'Flow/Shear rate/Waveform file' = 'w.dat' has no effect with 'Flow/Shear rate/Form' = "
                          "Pulsatile"),
            std::string::npos)
      << waveform;
  // At their defaults the other form's keys are what every validated deck holds.
  EXPECT_EQ(inputError([&] { capsula::operators::readShearRate(shearRateList("Steady"), "Flow/Shear rate"); }), "");
}

TEST(ShearRate, OutputsMustSampleEveryPeriodAtTheSamePhases)
{
  using capsula::operators::requireOutputsCommensurate;
  const ShearRate rate = ShearRate::pulsatile(0.5, 1.0);
  const std::string path = "Flow/Shear rate", key = "Output/Interval";
  EXPECT_EQ(inputError([&] { requireOutputsCommensurate(rate, path, 0.1, key); }), ""); // 10 per period
  EXPECT_EQ(inputError([&] { requireOutputsCommensurate(rate, path, 1.0, key); }), "");
  EXPECT_EQ(inputError([&] { requireOutputsCommensurate(rate, path, 3.0, key); }), ""); // every third period
  EXPECT_EQ(inputError([&] { requireOutputsCommensurate(rate, path, 0.0, key); }), ""); // the start and the end only
  const std::string message = inputError([&] { requireOutputsCommensurate(rate, path, 0.3, key); });
  EXPECT_NE(message.find("'Output/Interval' = 0.3 does not divide"), std::string::npos) << message;
  EXPECT_NE(message.find("'Flow/Shear rate/Period'"), std::string::npos) << message;
  EXPECT_NE(message.find("Set 'Output/Interval' to 0.333333"), std::string::npos) << message;
  EXPECT_NE(inputError([&] { requireOutputsCommensurate(rate, path, 1.5, key); }), "");
  // tether2d: the interval is in tau = k t / lambda; lambda 2 makes 0.25 of tau 0.5 of t.
  EXPECT_EQ(inputError([&] { requireOutputsCommensurate(rate, path, 0.25, key, 2.0); }), "");
  EXPECT_NE(inputError([&] { requireOutputsCommensurate(rate, path, 0.2, key, 2.0); }).find("lambda"),
            std::string::npos);
  EXPECT_EQ(inputError([&] { requireOutputsCommensurate(ShearRate(), path, 0.3, key); }), ""); // steady
  const std::string steady = inputError([&] { capsula::operators::requireNoSteadyStop(rate, path, 1e-7); });
  EXPECT_NE(steady.find("'Time integration/Steady tolerance' = 1e-07 stops a run"), std::string::npos) << steady;
  EXPECT_EQ(inputError([&] { capsula::operators::requireNoSteadyStop(rate, path, 0.0); }), "");
  EXPECT_EQ(inputError([&] { capsula::operators::requireNoSteadyStop(ShearRate(), path, 1e-7); }), "");
  EXPECT_EQ(capsula::operators::limitStepToPeriod(1.0, rate), 1.0 / 20.0);
  EXPECT_EQ(capsula::operators::limitStepToPeriod(0.01, rate), 0.01);
  EXPECT_EQ(capsula::operators::limitStepToPeriod(1.0, ShearRate()), 1.0);
}

} // namespace
