#include "io/glyph_selection.hpp"

#include <algorithm>
#include <cstdio>
#include <unordered_set>

#include "io/input_error.hpp"
#include "io/text_list.hpp"

namespace gf {

std::vector<std::uint32_t> resolve_selection(const GlyphSelection& selection, const GlyphCatalog& catalog,
                                             const std::string& file) {
  std::vector<std::uint32_t> out;
  std::unordered_set<std::uint32_t> seen;
  const auto add = [&](std::uint32_t gid) {
    if (seen.insert(gid).second) out.push_back(gid);
  };
  for (const std::string& name : selection.names) {
    const auto gid = catalog.by_name(name);
    if (!gid) throw InputError(file + ": glyph '" + name + "': no glyph of that name");
    add(*gid);
  }
  const auto& cmap = catalog.character_map;
  for (const CodepointRange& r : selection.unicodes) {
    auto it = std::lower_bound(cmap.begin(), cmap.end(), std::pair<char32_t, std::uint32_t>{r.first, 0});
    if (r.single() && (it == cmap.end() || it->first != r.first)) {
      char buf[16];
      std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(r.first));
      throw InputError(file + ": " + buf + ": no glyph for that code point");
    }
    for (; it != cmap.end() && it->first <= r.last; ++it) add(it->second);
  }
  if (selection.text)
    for (const std::uint32_t gid : catalog.glyphs_for_text(*selection.text)) add(gid);
  if (out.empty()) throw InputError(file + ": the selection matches no glyph");
  return out;
}

std::vector<std::string> split_glyph_names(std::string_view list) {
  std::vector<std::string> names;
  for (const std::string_view name : split_trimmed(list))
    if (!name.empty()) names.emplace_back(name);
  return names;
}

}  // namespace gf
