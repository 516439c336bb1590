#include "io/ufo_file_names.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <string_view>

namespace gf {

namespace {

constexpr std::string_view illegal = "\"*+/:<>?[\\]|";
constexpr std::array<std::string_view, 23> reserved = {
    "con", "prn", "aux", "clock$", "nul", "com1", "com2", "com3", "com4", "com5", "com6", "com7",
    "com8", "com9", "lpt1", "lpt2", "lpt3", "lpt4", "lpt5", "lpt6", "lpt7", "lpt8", "lpt9"};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

}  // namespace

std::string glif_file_name(const std::string& glyph_name, std::set<std::string>& taken) {
  constexpr std::string_view suffix = ".glif";
  constexpr std::size_t max_length = 255;
  std::string name = glyph_name;
  if (!name.empty() && name[0] == '.') name[0] = '_';
  std::string out;
  for (const char ch : name) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7F || illegal.find(ch) != std::string_view::npos) out += '_';
    else if (std::isupper(c)) { out += ch; out += '_'; }
    else out += ch;
  }
  // Reserved names are checked per dot-separated part.
  std::string checked;
  std::size_t start = 0;
  while (start <= out.size()) {
    std::size_t dot = out.find('.', start);
    if (dot == std::string::npos) dot = out.size();
    const std::string part = out.substr(start, dot - start);
    const bool is_reserved = std::find(reserved.begin(), reserved.end(), lower(part)) != reserved.end();
    checked += (is_reserved ? "_" : "") + part;
    if (dot < out.size()) checked += '.';
    start = dot + 1;
  }
  const std::size_t room = max_length - suffix.size();
  if (checked.size() > room) checked.resize(room);
  std::string candidate = checked + std::string(suffix);
  for (int counter = 1; taken.count(lower(candidate)); ++counter) {
    const std::string number = std::to_string(counter);
    std::string base = checked.substr(0, std::min(checked.size(), room - number.size()));
    candidate = base + number + std::string(suffix);
  }
  taken.insert(lower(candidate));
  return candidate;
}

}  // namespace gf
