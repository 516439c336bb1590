// UTF-8 text to code points, for --text.
#pragma once

#include <string_view>
#include <vector>

#include "io/input_error.hpp"

namespace gf {

/// Throws InputError("--text: not valid UTF-8") on a malformed sequence.
inline std::vector<char32_t> decode_utf8(std::string_view s) {
  std::vector<char32_t> out;
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    const int extra = c < 0x80 ? 0 : (c >> 5) == 0x6 ? 1 : (c >> 4) == 0xE ? 2 : (c >> 3) == 0x1E ? 3 : -1;
    if (extra < 0 || i + static_cast<std::size_t>(extra) >= s.size()) throw InputError("--text: not valid UTF-8");
    char32_t v = extra == 0 ? c : extra == 1 ? (c & 0x1F) : extra == 2 ? (c & 0x0F) : (c & 0x07);
    for (int k = 1; k <= extra; ++k) {
      const unsigned char cc = static_cast<unsigned char>(s[i + static_cast<std::size_t>(k)]);
      if ((cc & 0xC0) != 0x80) throw InputError("--text: not valid UTF-8");
      v = (v << 6) | (cc & 0x3F);
    }
    out.push_back(v);
    i += static_cast<std::size_t>(extra) + 1;
  }
  return out;
}

}  // namespace gf
