// Numbers as text for the writers: the shortest decimal that reads back as the same double,
// so coordinates survive a write and read exactly ("120", "120.5", "0.1").
#pragma once

#include <charconv>
#include <string>

namespace gf {

inline std::string shortest_decimal(double v) {
  if (v == 0.0) return "0";  // never "-0"
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

}  // namespace gf
