#pragma once
// The deck keys of the domain, declared and read here (the component that reads a key
// declares it):
//
//   Wall/Enabled                the lower wall y = 0 (true by default, as in the thesis)
//   Wall/Channel height         H > 0: a second no-slip wall y = H; 0: none
//   Domain/Periodic length x    L_x > 0: periodic along the flow; 0: unbounded
//   Domain/Periodic length z    L_z > 0: periodic across the flow; 0: unbounded
//   Flow/Profile                Shear (simple shear, or plane Couette in a channel) or
//                               Poiseuille (needs the channel)
//
// The sublists 'Wall' and 'Flow' also hold keys of other components (the scene declares
// 'Wall/Minimum gap', 'Flow/Capillary number', ...); this declares only its own.
#include "capsula/domain/Domain.hpp"
#include "capsula/domain/FlowProfile.hpp"

#include <Teuchos_ParameterList.hpp>

namespace capsula::domain {

/// Declares 'Wall/Enabled', 'Wall/Channel height', 'Domain/...' and 'Flow/Profile' in
/// the valid list `valid` (the sublists are created if absent).
void declareDomainParameters(Teuchos::ParameterList& valid);

/// The domain of a validated deck. Throws core::InputError naming the keys for a channel
/// without its lower wall.
Domain readDomain(const Teuchos::ParameterList& deck);

/// The undisturbed flow of a validated deck in `domain`. Throws core::InputError naming
/// 'Flow/Profile' and 'Wall/Channel height' for Poiseuille flow without a channel.
FlowProfile readFlowProfile(const Teuchos::ParameterList& deck, const Domain& domain);

} // namespace capsula::domain
