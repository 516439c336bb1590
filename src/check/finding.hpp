// What a check reports: one problem at one place, with the value measured and the threshold.
#pragma once

#include <optional>
#include <string>

#include "geom/vec2.hpp"

namespace gf {

enum class Severity { info, warning, error };

const char* to_string(Severity s);

struct Finding {
  std::string check;  ///< the check id: "kink", "g2-jump", …
  Severity severity = Severity::warning;
  int contour = -1;                ///< -1: the whole glyph
  std::optional<int> node;         ///< on-curve node index in the contour
  std::optional<int> segment;      ///< segment index (starting at `node`)
  std::optional<double> t;         ///< parameter inside the segment
  std::optional<Vec2> point;       ///< font units
  std::optional<double> value;     ///< what was measured (nullopt: unbounded)
  std::optional<double> threshold; ///< what it was compared with
  std::string unit;                ///< of value and threshold: "deg", "units", "ratio", "1/em" …
  std::string message;             ///< one line for people
};

}  // namespace gf
