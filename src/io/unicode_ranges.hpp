// `--unicodes` in hb-subset's syntax: code points or ranges in hexadecimal, separated by
// commas or spaces, each optionally prefixed with U+ (U+0041-005A,U+0061-007A), or * for all.
#pragma once

#include <string_view>
#include <vector>

namespace gf {

struct CodepointRange {
  char32_t first = 0;
  char32_t last = 0;  // inclusive
  bool single() const { return first == last; }
};

/// Throws InputError with a one-line message naming the bad token.
std::vector<CodepointRange> parse_unicode_ranges(std::string_view spec);

}  // namespace gf
