#pragma once
// Counter-based random numbers: a uniform number is a pure function of (seed, stream,
// counter, purpose), never the next draw of a shared generator. Which receptors a rank
// holds, and in which order it visits them, then cannot change a single event: the draw of
// receptor r at step s is the same on every rank and in every partition.
//
// The mixing function is the finaliser of SplitMix64 (Steele, Lea & Flood, OOPSLA 2014), a
// bijection of 64-bit words with full avalanche; chaining it over the key words (each
// xor-ed into the state, then mixed) gives a hash whose low-order structure does not carry
// over from one key to the next.
#include <cstdint>

namespace capsula::adhesion {

/// The SplitMix64 finaliser of x + golden-ratio increment.
inline std::uint64_t splitMix64(std::uint64_t x)
{
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

/// A 64-bit hash of four key words.
inline std::uint64_t counterHash(std::uint64_t seed, std::uint64_t stream, std::uint64_t counter, std::uint64_t purpose)
{
  std::uint64_t h = splitMix64(seed);
  h = splitMix64(h ^ stream);
  h = splitMix64(h ^ counter);
  return splitMix64(h ^ purpose);
}

/// A uniform number in [0, 1) from the top 53 bits of the hash (every double of the form
/// k 2^-53 equally likely).
inline double counterUniform(std::uint64_t seed, std::uint64_t stream, std::uint64_t counter, std::uint64_t purpose)
{
  return static_cast<double>(counterHash(seed, stream, counter, purpose) >> 11) * 0x1.0p-53;
}

/// What a draw is for: distinct purposes of one receptor and step never share a number.
enum class DrawPurpose : std::uint64_t { Formation = 1, Breakage = 2, PlacementCount = 3, PlacementPoint = 4 };

} // namespace capsula::adhesion
