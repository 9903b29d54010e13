#include "capsula/adhesion/ContactParameters.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>

namespace capsula::adhesion {

namespace core = capsula::core;

void declareContactParameters(Teuchos::ParameterList& contact)
{
  core::declareBool(contact, "Enabled", false,
                    "A short-range repulsion between each membrane and the wall y = 0 and between the "
                    "membranes of two cells: the truncated steric repulsion of Bongrand & Bell (1984) "
                    "as used by Hammer & Apte (1992), acting on the membrane below the gap 'Range' "
                    "(ContactRepulsion.hpp).");
  core::declareReal(contact, "Range", 0.05,
                    "delta / a: the gap, in cell radii, below which the repulsion acts (zero at and "
                    "beyond it, smoothly). Must be below the smallest semi-axis of every cell (a wider "
                    "repulsion reaches across the cell and folds it) and, with adhesion, at least the "
                    "bonds' 'Equilibrium length' (so that bonds can form where the repulsion holds the "
                    "membrane).",
                    core::greaterThan(0.0));
  core::declareReal(contact, "Strength", 10.0,
                    "p_0 / (G / a): the pressure scale. The pressure grows as p_0 delta / d at small "
                    "gaps d, so a membrane pressed with a mean pressure P comes to rest at a gap of "
                    "about p_0 delta / (P + 2 p_0) > 0; take p_0 at least the largest pressure "
                    "expected (about 6 pi Ca over the contact area for a cell the flow presses on the "
                    "wall) to keep that gap above delta / 3.",
                    core::greaterThan(0.0));
  core::declareChoice(contact, "Load", "Nodal area", {"Nodal area", "Virtual work"},
                      "How the pressure becomes the membrane's nodal forces. 'Nodal area': F_k = p at "
                      "node k times a sixth of the areas of its elements; on 6-node elements its load "
                      "density oscillates (8.5 p at the vertices for a uniform p), but on coarse meshes "
                      "pressed by a tether it holds longer (docs/cell3d.md, 'Contact'). 'Virtual work': "
                      "F_k = int phi_k p dS over the surface (the 7-point rule on 64 pieces of each "
                      "element), the load whose density is p.");
}

ContactSettings readContactParameters(const Teuchos::ParameterList& contact, const std::string& path)
{
  ContactSettings s;
  s.enabled = contact.get<bool>("Enabled");
  s.range = contact.get<double>("Range");
  s.strength = contact.get<double>("Strength");
  s.load = contact.get<std::string>("Load") == "Virtual work" ? ContactLoad::VirtualWork : ContactLoad::NodalArea;
  if (s.enabled) {
    core::require<core::InputError>(s.range > 0.0, "'", path, "/Range' = ", s.range,
                                    " with contact enabled: give a range > 0.");
    core::require<core::InputError>(s.strength > 0.0, "'", path, "/Strength' = ", s.strength,
                                    " with contact enabled: give a strength > 0.");
  }
  return s;
}

} // namespace capsula::adhesion
