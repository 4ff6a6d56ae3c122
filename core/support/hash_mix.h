#pragma once
// A 64-bit mix for open-addressing hash tables of integer keys.
#include <cstdint>

namespace gps {

/// splitmix64's finaliser: every bit of `key` reaches every bit of the result, so keys that differ in a
/// few bits (neighbouring vertices, hashed stencil rows) spread over a table's slots.
inline uint64_t mixed_hash(uint64_t key) {
  key = (key ^ (key >> 30)) * 0xbf58476d1ce4e5b9ull;
  key = (key ^ (key >> 27)) * 0x94d049bb133111ebull;
  return key ^ (key >> 31);
}

}  // namespace gps
