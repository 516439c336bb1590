#include "io/unicode_ranges.hpp"

#include <cctype>
#include <string>

#include "io/input_error.hpp"

namespace gf {

namespace {

[[noreturn]] void bad(std::string_view token, const char* why) {
  throw InputError("--unicodes: '" + std::string(token) + "' " + why);
}

char32_t parse_codepoint(std::string_view text, std::string_view token) {
  if (text.size() >= 2 && (text[0] == 'U' || text[0] == 'u') && text[1] == '+') text.remove_prefix(2);
  else if (text.size() >= 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) text.remove_prefix(2);
  if (text.empty()) bad(token, "is not a hexadecimal code point");
  if (text.size() > 6) bad(token, "is beyond U+10FFFF");
  unsigned long value = 0;
  for (const char ch : text) {
    if (!std::isxdigit(static_cast<unsigned char>(ch))) bad(token, "is not a hexadecimal code point");
    value = value * 16 + static_cast<unsigned long>(std::isdigit(static_cast<unsigned char>(ch))
                                                        ? ch - '0'
                                                        : std::tolower(static_cast<unsigned char>(ch)) - 'a' + 10);
  }
  if (value > 0x10FFFF) bad(token, "is beyond U+10FFFF");
  return static_cast<char32_t>(value);
}

}  // namespace

std::vector<CodepointRange> parse_unicode_ranges(std::string_view spec) {
  std::vector<CodepointRange> ranges;
  std::size_t i = 0;
  while (i < spec.size()) {
    while (i < spec.size() && (spec[i] == ',' || std::isspace(static_cast<unsigned char>(spec[i])))) ++i;
    std::size_t j = i;
    while (j < spec.size() && spec[j] != ',' && !std::isspace(static_cast<unsigned char>(spec[j]))) ++j;
    const std::string_view token = spec.substr(i, j - i);
    i = j;
    if (token.empty()) continue;
    if (token == "*") {
      ranges.push_back({0, 0x10FFFF});
      continue;
    }
    const std::size_t dash = token.find('-');
    if (dash == std::string_view::npos) {
      const char32_t c = parse_codepoint(token, token);
      ranges.push_back({c, c});
      continue;
    }
    const char32_t first = parse_codepoint(token.substr(0, dash), token);
    const char32_t last = parse_codepoint(token.substr(dash + 1), token);
    if (last < first) bad(token, "is a range that ends before it starts");
    ranges.push_back({first, last});
  }
  if (ranges.empty()) throw InputError("--unicodes: no code points given");
  return ranges;
}

}  // namespace gf
