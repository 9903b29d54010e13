#pragma once
// Constitutive law of a 2D membrane (a contour, thesis A.5): the tension gamma(omega) as a
// function of the stretch ratio omega = dl / dl0 (eq A.37), and the strain energy per unit
// reference length whose derivative in omega it is, so that int gamma d(omega)/dt dl0 is
// the rate of stored energy (ElasticMembrane2D.hpp). A law is chosen by name
// ('Cell/Membrane law', MembraneLawRegistry2D.hpp).
#include <string>

namespace capsula::scene2d {

class MembraneLaw2D {
public:
  virtual ~MembraneLaw2D() = default;

  /// The name the registry knows the law by ("Hookean").
  virtual std::string name() const = 0;
  /// gamma(omega).
  virtual double tension(double stretch) const = 0;
  /// w(omega), zero at omega = 1, with dw/d(omega) = gamma.
  virtual double energyDensity(double stretch) const = 0;
};

} // namespace capsula::scene2d
