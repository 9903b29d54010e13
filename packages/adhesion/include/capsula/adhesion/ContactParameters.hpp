#pragma once
// The deck's "Contact" sublist: the short-range repulsion that keeps membranes off the wall
// and off each other (ContactRepulsion.hpp). Units of the capillary number: lengths in a,
// pressures in G / a (so a pressure times an area is a force in G a).
#include <Teuchos_ParameterList.hpp>

#include <string>

namespace capsula::adhesion {

/// How the pressure becomes nodal forces (ContactRepulsion.hpp).
enum class ContactLoad {
  NodalArea,  ///< F_k = p(x_k) a_k, a_k = sum of A_e / 6: lumped, oscillating on 6-node elements
  VirtualWork ///< F_k = int phi_k p dS: a load density equal to p where the mesh resolves it
};

struct ContactSettings {
  bool enabled = false;
  double range = 0.05;    ///< delta / a: no force at gaps >= delta
  double strength = 10.0; ///< p_0 / (G / a): the pressure scale
  ContactLoad load = ContactLoad::NodalArea;
};

/// Declares Enabled, Range, Strength and Load.
void declareContactParameters(Teuchos::ParameterList& contact);

/// Reads a validated sublist; throws core::InputError naming the key (under `path`) for a
/// range or strength that is not > 0 with contact enabled.
ContactSettings readContactParameters(const Teuchos::ParameterList& contact, const std::string& path = "Contact");

} // namespace capsula::adhesion
