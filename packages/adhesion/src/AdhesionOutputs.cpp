#include "capsula/adhesion/AdhesionOutputs.hpp"

#include "capsula/adhesion/ContactRepulsion.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <limits>
#include <vector>

namespace capsula::adhesion {

AdhesionSummary summariseAdhesion(const BondPopulation& bonds, const mesh::SurfaceMesh& mesh,
                                  const ReceptorSet& receptors, const double* positions)
{
  AdhesionSummary s;
  s.bonds = bonds.bondCount();
  for (int r = 0; r < bonds.size(); ++r) {
    if (bonds.state(r).occupancy > 0.0) {
      s.bondForce += bonds.force(r, receptors.position(mesh, positions, r));
    }
  }
  const std::vector<double> areas = nodalAreaShares(mesh, positions);
  const double reach = bonds.settings().reactionDistance;
  s.minimumGap = std::numeric_limits<double>::infinity();
  for (int k = 0; k < mesh.numNodes(); ++k) {
    const double gap = bonds.settings().ligandWall.gap(positions[3 * k + 1]);
    s.minimumGap = std::min(s.minimumGap, gap);
    if (gap <= reach) {
      s.contactArea += areas[static_cast<std::size_t>(k)];
    }
  }
  return s;
}

ReceptorRange ownedReceptors(int numReceptors, int rank, int numRanks)
{
  const int base = numReceptors / numRanks, extra = numReceptors % numRanks;
  const int first = rank * base + std::min(rank, extra);
  return {first, first + base + (rank < extra ? 1 : 0)};
}

void shareBondStates(BondPopulation& bonds, const Teuchos::Comm<int>& comm)
{
  const int n = bonds.size();
  const ReceptorRange mine = ownedReceptors(n, comm.getRank(), comm.getSize());
  std::vector<double> local(4 * static_cast<std::size_t>(n), 0.0), global(local.size(), 0.0);
  for (int r = mine.first; r < mine.last; ++r) {
    const BondState& s = bonds.state(r);
    double* out = local.data() + 4 * r;
    out[0] = s.occupancy;
    out[1] = s.anchor[0];
    out[2] = s.anchor[1];
    out[3] = s.anchor[2];
  }
  // Every entry is non-zero on at most one rank, so the sum is exact.
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 4 * n, local.data(), global.data());
  for (int r = 0; r < n; ++r) {
    const double* in = global.data() + 4 * r;
    bonds.setState(r, BondState{in[0], mesh::Vec3(in[1], in[2], in[3])});
  }
}

} // namespace capsula::adhesion
