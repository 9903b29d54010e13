#pragma once
// Step-size controllers: given the size h of an attempted step and its error estimate,
// accept or reject it and propose the next step size. Controllers keep no state; the
// one number of memory the PI controller needs (the previous accepted error) lives in
// IntegrationState so that a restarted run continues exactly.
//
// Both follow Hairer, Norsett & Wanner (Solving ODEs I, II.4) in one respect the thesis
// does not mention: the step accepted right after a rejection is not followed by a
// larger one, which avoids reject/accept oscillations.

namespace capsula::timeint {

struct StepDecision {
  bool accepted = false;
  double nextStep = 0.0; ///< proposed size of the next attempt (retry or next step)
};

/// The thesis controller (eq 3.50): with the error estimate err = |x5 - x4| and the
/// tolerance eps,
///   s = ( (eps/2) / err )^(1/4);   s > 1.5: double the step;   s < 0.75: halve it.
/// The thesis does not say whether a step with s < 0.75 is kept. Here it is rejected and
/// retried with half the step size; steps with s >= 0.75 are accepted. So every
/// accepted step has err <= eps / (2 * 0.75^4) = 1.58 eps, and the controller aims at
/// err ~ eps/2. (Accepting iff err <= eps instead would leave 0.75 <= s < 0.84 with
/// neither acceptance nor a smaller step.)
class ThesisStepController {
public:
  explicit ThesisStepController(double tolerance);

  double tolerance() const { return tolerance_; }
  /// s of eq 3.50 (+infinity for err = 0).
  double stepRatio(double errorEstimate) const;
  StepDecision decide(double step, double errorEstimate, bool afterRejection) const;

private:
  double tolerance_;
};

/// Parameters of the PI controller. alpha and beta are the exponents of the current
/// and previous error (the defaults are those of Hairer's DOPRI5 code: alpha =
/// 1/5 - 0.75 beta, beta = 0.04; in Soderlind's notation k_I = alpha - beta, k_P = beta).
struct PiControllerParameters {
  double safety = 0.9;
  double alpha = 0.17;
  double beta = 0.04;
  double minimumFactor = 0.2;  ///< the step never shrinks by more than this in one go
  double maximumFactor = 10.0; ///< nor grows by more than this
  double errorFloor = 1.0e-4;  ///< previous error is floored here (and starts here)
};

/// A PI step-size controller (Gustafsson 1991; Hairer, Norsett & Wanner IV.2) for a
/// scaled error norm err (accept iff err <= 1):
///   accepted: h_new = h * safety * err^(-alpha) * errPrevious^(beta), clamped to
///             [minimumFactor, maximumFactor] h (and to <= h right after a rejection);
///   rejected: h_new = h * max(minimumFactor, safety * err^(-1/k)), k = error order.
/// The proportional term damps the step-size oscillations of the elementary controller.
class PiStepController {
public:
  PiStepController(int errorOrder, PiControllerParameters parameters = {});

  const PiControllerParameters& parameters() const { return parameters_; }
  StepDecision decide(double step, double errorNorm, double previousErrorNorm, bool afterRejection) const;
  /// The value an accepted step leaves as "previous error" for the next one.
  double rememberedError(double errorNorm) const;

private:
  int errorOrder_;
  PiControllerParameters parameters_;
};

} // namespace capsula::timeint
