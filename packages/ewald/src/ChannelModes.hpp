#pragma once
// One Fourier mode k != 0 (a = |k|) of the channel Stokeslet's reference series
// (ChannelStokeslet2P.hpp): the profiles W_l, W_y and T and their y-derivatives at a height
// y != h for a point force at height h between no-slip walls at 0 and H. Shared by the
// references of the velocity and of the stress.

namespace capsula::ewald::detail {

/// A profile and its first three y-derivatives.
struct ChannelProfile {
  double d[4] = {0.0, 0.0, 0.0, 0.0};
};

/// W_l (w = i a g_l W_l) and W_y (w = a^2 g_y W_y): the free part plus the four wall modes
/// that make W = W' = 0 on both walls.
void channelPlaneProfiles(double a, double height, double h, double y, ChannelProfile& longitudinal,
                          ChannelProfile& normal);

/// T and T' (the transverse component u_t = g_t T).
void channelTransverseProfile(double a, double height, double h, double y, double& value, double& slope);

} // namespace capsula::ewald::detail
