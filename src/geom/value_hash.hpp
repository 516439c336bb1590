// A hash of numbers by their bits (FNV-1a), for memos keyed by exact inputs: two values hash
// alike when they are equal bit for bit (−0 and +0 differ, which only costs a memo a miss).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

#include "geom/vec2.hpp"

namespace gf {

class ValueHash {
 public:
  ValueHash& add(double x) {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    for (int shift = 0; shift < 64; shift += 8) value_ = (value_ ^ ((bits >> shift) & 0xffu)) * 0x100000001b3u;
    return *this;
  }
  ValueHash& add(Vec2 p) { return add(p.x).add(p.y); }
  std::size_t value() const { return static_cast<std::size_t>(value_); }

 private:
  std::uint64_t value_ = 0xcbf29ce484222325u;
};

}  // namespace gf
