// Numbers as text: for the writers, the shortest decimal that reads back as the same double,
// so coordinates survive a write and read exactly ("120", "120.5", "0.1"); for the readers,
// one finite number that is the whole of a piece of text.
#pragma once

#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

namespace gf {

inline std::string shortest_decimal(double v) {
  if (v == 0.0) return "0";  // never "-0"
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

/// `text`, all of it, as a finite number ("120", "-0.5", "+3", "1e-3"); nullopt for anything
/// else (empty, trailing characters, inf, nan).
inline std::optional<double> parse_number(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);  // from_chars does not take a plus sign
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace gf
