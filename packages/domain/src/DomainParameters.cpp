#include "capsula/domain/DomainParameters.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>

#include <algorithm>

namespace capsula::domain {

void declareDomainParameters(Teuchos::ParameterList& valid)
{
  auto& wall = core::declareSublist(valid, "Wall", "The no-slip plane walls: y = 0 below the flow, y = H above it.");
  core::declareBool(wall, "Enabled", true,
                    "true: the flow is bounded by the wall y = 0 (Blake's kernel, App. B); false: "
                    "unbounded shear (free-space kernel).");
  core::declareReal(wall, "Channel height", 0.0,
                    "H, in cell radii: > 0 puts a second no-slip wall at y = H (a channel 0 < y < H; needs "
                    "'Wall/Enabled'); 0: no upper wall. With 'Flow/Profile' = Shear the upper wall slides at "
                    "k H (plane Couette flow). A channel needs a kernel that serves it ('Operator/Kernel', "
                    "docs/domains.md).",
                    core::atLeast(0.0));

  auto& box = core::declareSublist(valid, "Domain",
                                   "Periodic directions along the walls (docs/domains.md). Positions are never "
                                   "wrapped: distances use the nearest periodic image.");
  core::declareReal(box, "Periodic length x", 0.0,
                    "L_x, in cell radii: > 0 makes the flow periodic along x (the flow direction) with period "
                    "L_x; 0: unbounded along x. Needs a kernel that serves periodic boxes ('Operator/Kernel', "
                    "docs/domains.md).",
                    core::atLeast(0.0));
  core::declareReal(box, "Periodic length z", 0.0,
                    "L_z, in cell radii: > 0 makes the flow periodic along z (across the flow) with period "
                    "L_z; 0: unbounded along z. Needs a kernel that serves periodic boxes ('Operator/Kernel', "
                    "docs/domains.md).",
                    core::atLeast(0.0));

  auto& flow = core::declareSublist(valid, "Flow", "The undisturbed flow.");
  core::declareChoice(flow, "Profile", "Shear", flowProfileNames(),
                      "The undisturbed flow u = k(t) f(y) e_x, k being the shear rate at the lower wall. Shear: "
                      "f = y (simple shear; in a channel plane Couette flow, the upper wall sliding at k H). "
                      "Poiseuille: f = y (1 - y / H), pressure-driven flow in a channel (needs "
                      "'Wall/Channel height'); centre-line velocity k H / 4.");
}

Domain readDomain(const Teuchos::ParameterList& deck)
{
  DomainShape shape;
  const auto& wall = deck.sublist("Wall");
  shape.lowerWall = wall.get<bool>("Enabled");
  shape.channelHeight = wall.get<double>("Channel height");
  core::require<core::InputError>(shape.channelHeight == 0.0 || shape.lowerWall,
                                  "'Wall/Channel height' = ", shape.channelHeight,
                                  " asks for a channel, but 'Wall/Enabled' = false removes its lower wall y = 0: "
                                  "enable the wall, or set 'Wall/Channel height' to 0.");
  const auto& box = deck.sublist("Domain");
  shape.periodX = box.get<double>("Periodic length x");
  shape.periodZ = box.get<double>("Periodic length z");
  return Domain(shape);
}

FlowProfile readFlowProfile(const Teuchos::ParameterList& deck, const Domain& domain)
{
  const auto& names = flowProfileNames();
  const std::string name = deck.sublist("Flow").get<std::string>("Profile");
  const auto found = std::find(names.begin(), names.end(), name);
  core::require<core::InputError>(found != names.end(), "'Flow/Profile' = '", name, "' is not a flow profile.");
  return FlowProfile(static_cast<FlowProfileKind>(found - names.begin()), domain);
}

} // namespace capsula::domain
