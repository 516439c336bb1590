// A point in a variable font's design space: `--location wght=700,wdth=80`.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace gf {

struct AxisValue {
  std::string tag;  // four characters, space padded
  double value = 0.0;
};

/// Throws InputError with a one-line message naming the bad entry.
std::vector<AxisValue> parse_variation_location(std::string_view spec);

}  // namespace gf
