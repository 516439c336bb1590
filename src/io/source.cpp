#include "io/source.hpp"

#include <algorithm>
#include <unordered_map>
#include <variant>

#include "io/file_extension.hpp"
#include "io/input_error.hpp"
#include "io/point_sequence_reader.hpp"
#include "io/svg_reader.hpp"
#include "io/text_shaping.hpp"
#include "io/ufo_reader.hpp"
#include "io/utf8.hpp"

namespace fs = std::filesystem;

namespace gf {

namespace {

// What selection needs, for sources read whole (UFO, SVG).
struct LoadedCatalog {
  std::unordered_map<std::string, std::uint32_t> by_name;
  std::vector<std::pair<char32_t, std::uint32_t>> cmap;

  explicit LoadedCatalog(const GlyphSet& set) {
    for (std::uint32_t i = 0; i < set.glyphs.size(); ++i) {
      by_name.emplace(set.glyphs[i].name, i);
      for (const char32_t u : set.glyphs[i].unicodes) cmap.emplace_back(u, i);
    }
    std::sort(cmap.begin(), cmap.end());
    cmap.erase(std::unique(cmap.begin(), cmap.end(), [](auto a, auto b) { return a.first == b.first; }), cmap.end());
  }
};

}  // namespace

struct GlyphSource::Impl {
  fs::path path;
  SourceKind kind;
  std::variant<FreetypeFont, GlyphSet> data;
  std::vector<std::uint32_t> selected;
  bool whole = true;

  const FontInfo& font() const {
    return std::holds_alternative<FreetypeFont>(data) ? std::get<FreetypeFont>(data).info()
                                                      : std::get<GlyphSet>(data).font;
  }
};

GlyphSource::GlyphSource(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GlyphSource::GlyphSource(GlyphSource&&) noexcept = default;
GlyphSource& GlyphSource::operator=(GlyphSource&&) noexcept = default;
GlyphSource::~GlyphSource() = default;

GlyphSource GlyphSource::open(const fs::path& path, const SourceOptions& options) {
  const std::string file = path.string();
  const std::string ext = lower_extension(path);
  std::error_code ec;
  const bool is_ufo = ext == ".ufo" || fs::is_directory(path, ec);
  const bool is_svg = ext == ".svg";
  const bool is_points = ext == ".json";
  const SourceKind kind = is_ufo ? SourceKind::ufo : is_svg ? SourceKind::svg : is_points ? SourceKind::points : SourceKind::font;
  if ((is_ufo || is_svg || is_points) && (!options.font.location.empty() || options.font.named_instance))
    throw InputError(file + ": --location and --instance apply to variable font files only");

  auto impl = std::make_unique<Impl>(Impl{path, kind, GlyphSet{}, {}, options.selection.empty()});
  GlyphCatalog catalog;
  std::optional<LoadedCatalog> loaded;
  if (is_ufo || is_svg || is_points) {
    impl->data = is_ufo ? read_ufo(path) : is_svg ? read_svg(path) : read_point_sequences(path);
    loaded.emplace(std::get<GlyphSet>(impl->data));
    catalog.by_name = [&](std::string_view n) -> std::optional<std::uint32_t> {
      const auto it = loaded->by_name.find(std::string(n));
      if (it == loaded->by_name.end()) return std::nullopt;
      return it->second;
    };
    catalog.character_map = loaded->cmap;
    catalog.glyphs_for_text = [&](std::string_view text) {
      std::vector<std::uint32_t> gids;
      for (const char32_t c : decode_utf8(text)) {
        const auto it = std::lower_bound(loaded->cmap.begin(), loaded->cmap.end(), std::pair<char32_t, std::uint32_t>{c, 0});
        if (it != loaded->cmap.end() && it->first == c) gids.push_back(it->second);
      }
      return gids;
    };
  } else {
    impl->data = FreetypeFont::open(path, options.font);
    const FreetypeFont& font = std::get<FreetypeFont>(impl->data);
    catalog.by_name = [&](std::string_view n) { return font.glyph_by_name(n); };
    catalog.character_map = font.character_map();
    catalog.glyphs_for_text = [&](std::string_view text) {
      return glyphs_for_text(font.bytes(), font.location(), text);
    };
  }
  if (options.selection.empty()) {
    const std::size_t n = std::holds_alternative<FreetypeFont>(impl->data)
                              ? std::get<FreetypeFont>(impl->data).glyph_count()
                              : std::get<GlyphSet>(impl->data).glyphs.size();
    impl->selected.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) impl->selected[i] = i;
  } else {
    impl->selected = resolve_selection(options.selection, catalog, file);
  }
  return GlyphSource(std::move(impl));
}

const FontInfo& GlyphSource::font() const { return impl_->font(); }
const fs::path& GlyphSource::path() const { return impl_->path; }
SourceKind GlyphSource::kind() const { return impl_->kind; }
std::size_t GlyphSource::size() const { return impl_->selected.size(); }

std::optional<Glyph> GlyphSource::load(std::size_t i) const {
  const std::uint32_t gid = impl_->selected.at(i);
  Glyph g = std::holds_alternative<FreetypeFont>(impl_->data) ? std::get<FreetypeFont>(impl_->data).load_glyph(gid)
                                                               : std::get<GlyphSet>(impl_->data).glyphs.at(gid);
  if (impl_->whole && g.outline.contours.empty()) return std::nullopt;
  return g;
}

GlyphSet GlyphSource::load_all() const {
  GlyphSet set;
  set.font = font();
  for (std::size_t i = 0; i < size(); ++i)
    if (auto g = load(i)) set.glyphs.push_back(std::move(*g));
  return set;
}

}  // namespace gf
