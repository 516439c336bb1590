// Comma-separated option values ("a, b,c"; "wght=700,wdth=80") split into trimmed entries.
#pragma once

#include <string_view>
#include <vector>

namespace gf {

/// Every entry between separators, spaces trimmed; empty entries are kept (callers decide).
inline std::vector<std::string_view> split_trimmed(std::string_view list, char separator = ',') {
  std::vector<std::string_view> entries;
  std::size_t i = 0;
  while (true) {
    std::size_t j = list.find(separator, i);
    if (j == std::string_view::npos) j = list.size();
    std::string_view entry = list.substr(i, j - i);
    while (!entry.empty() && entry.front() == ' ') entry.remove_prefix(1);
    while (!entry.empty() && entry.back() == ' ') entry.remove_suffix(1);
    entries.push_back(entry);
    if (j == list.size()) return entries;
    i = j + 1;
  }
}

}  // namespace gf
