#include "io/freetype_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <unordered_map>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_FONT_FORMATS_H
#include FT_MULTIPLE_MASTERS_H
#include FT_SFNT_NAMES_H
#include FT_TRUETYPE_IDS_H
#include FT_TRUETYPE_TABLES_H

#include "io/agl_names.hpp"
#include "io/harfbuzz_instance.hpp"
#include "io/input_error.hpp"
#include "io/sfnt_directory.hpp"

namespace gf {

namespace {

// FreeType's own message for an error code (fterrors.h builds the table from these macros).
const char* error_text(FT_Error e) {
#undef FTERRORS_H_
#define FT_ERROR_START_LIST switch (e) {
#define FT_ERRORDEF(code, value, text) \
  case value:                          \
    return text;
#define FT_ERROR_END_LIST }
#include FT_ERRORS_H
  return "unknown error";
}

std::string hex_error(FT_Error e) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%02X", static_cast<unsigned>(e));
  return std::string(error_text(e)) + " (FreeType error " + buf + ")";
}

std::string tag_string(FT_ULong tag) {
  std::string s(4, ' ');
  for (int i = 0; i < 4; ++i) s[i] = static_cast<char>((tag >> (24 - 8 * i)) & 0xFF);
  return s;
}

std::string trimmed_tag(std::string tag) {
  while (!tag.empty() && tag.back() == ' ') tag.pop_back();
  return tag;
}

std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::vector<std::uint8_t> read_bytes(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path.string() + ": no such file");
  if (std::filesystem::is_directory(path, ec)) throw InputError(path.string() + ": is a directory, not a font file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot be opened for reading");
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(path.string() + ": read error");
  if (bytes.empty()) throw InputError(path.string() + ": is empty, not a font");
  return bytes;
}

// Name-table string for a name id, preferring Windows Unicode (UTF-16BE) records.
std::optional<std::string> sfnt_name(FT_Face face, FT_UInt name_id) {
  const FT_UInt n = FT_Get_Sfnt_Name_Count(face);
  std::optional<std::string> mac;
  for (FT_UInt i = 0; i < n; ++i) {
    FT_SfntName name;
    if (FT_Get_Sfnt_Name(face, i, &name) != 0 || name.name_id != name_id) continue;
    if (name.platform_id == TT_PLATFORM_MICROSOFT) {
      std::string out;
      for (FT_UInt k = 0; k + 1 < name.string_len; k += 2) {
        const unsigned c = name.string[k] << 8 | name.string[k + 1];
        if (c < 0x80) out += static_cast<char>(c);
        else if (c < 0x800) { out += static_cast<char>(0xC0 | c >> 6); out += static_cast<char>(0x80 | (c & 0x3F)); }
        else { out += static_cast<char>(0xE0 | c >> 12); out += static_cast<char>(0x80 | (c >> 6 & 0x3F)); out += static_cast<char>(0x80 | (c & 0x3F)); }
      }
      return out;
    }
    if (name.platform_id == TT_PLATFORM_MACINTOSH && !mac)
      mac = std::string(reinterpret_cast<const char*>(name.string), name.string_len);
  }
  return mac;
}

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

}  // namespace

struct FreetypeFont::Impl {
  std::string file;
  std::vector<std::uint8_t> bytes;
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  FontInfo info;
  std::vector<std::string> names;
  std::unordered_map<std::string, std::uint32_t> by_name;
  std::vector<std::pair<char32_t, std::uint32_t>> cmap;
  std::vector<std::vector<char32_t>> unicodes;  // by glyph index
  std::vector<VariationAxis> axes;
  std::vector<AxisValue> location;
  /// Off the default instance, and for CFF and CFF2, outlines come from HarfBuzz: FreeType
  /// rounds variation results (sketch-refine-io.md §4), truncates CFF's fractional
  /// coordinates unscaled, and cannot load CFF2 unscaled at all.
  bool varied = false;
  std::optional<HarfbuzzInstance> instance;

  ~Impl() {
    if (face) FT_Done_Face(face);
    if (library) FT_Done_FreeType(library);
  }

  std::string where(std::uint32_t gid) const {
    return file + ": glyph '" + (gid < names.size() ? names[gid] : std::to_string(gid)) + "'";
  }

  // A name for a glyph the font names not: the Adobe Glyph List's where it has one for the
  // glyph's first code point, as other tools name them; else uniXXXX, or by glyph id.
  std::string made_name(std::uint32_t gid) const {
    if (gid == 0) return ".notdef";
    char made[32];
    if (unicodes[gid].empty()) {
      std::snprintf(made, sizeof made, "glyph%05u", gid);
      return made;
    }
    const char32_t c = unicodes[gid][0];
    if (const std::optional<std::string_view> listed = agl_name(c)) return std::string(*listed);
    std::snprintf(made, sizeof made, c > 0xFFFF ? "u%05X" : "uni%04X", static_cast<unsigned>(c));
    return made;
  }

  void read_names() {
    const std::uint32_t n = static_cast<std::uint32_t>(face->num_glyphs);
    names.resize(n);
    unicodes.assign(n, {});
    for (const auto& [c, gid] : cmap)
      if (gid < n) unicodes[gid].push_back(c);
    for (std::uint32_t gid = 0; gid < n; ++gid) {
      std::string name;
      char buf[256];
      if (FT_HAS_GLYPH_NAMES(face) && FT_Get_Glyph_Name(face, gid, buf, sizeof buf) == 0) name = buf;
      if (name.empty()) name = made_name(gid);
      // Names must identify glyphs; a font that repeats one gets the later ones suffixed.
      if (by_name.count(name)) name += ".gid" + std::to_string(gid);
      by_name.emplace(name, gid);
      names[gid] = std::move(name);
    }
  }

  void read_cmap() {
    if (FT_Select_Charmap(face, FT_ENCODING_UNICODE) != 0) return;
    FT_UInt gid = 0;
    FT_ULong c = FT_Get_First_Char(face, &gid);
    while (gid != 0) {
      cmap.emplace_back(static_cast<char32_t>(c), gid);
      c = FT_Get_Next_Char(face, c, &gid);
    }
  }

  void read_info(const std::filesystem::path& path) {
    info.source_path = path.string();
    info.family_name = face->family_name ? face->family_name : "";
    info.style_name = face->style_name ? face->style_name : "";
    info.units_per_em = face->units_per_EM;
    info.ascender = face->ascender;
    info.descender = face->descender;
    const char* format = FT_Get_Font_Format(face);
    info.outer_contours_clockwise = format && std::string(format) == "TrueType";
    if (const auto* post = static_cast<const TT_Postscript*>(FT_Get_Sfnt_Table(face, FT_SFNT_POST)))
      info.italic_angle = post->italicAngle / 65536.0;
    if (const auto* os2 = static_cast<const TT_OS2*>(FT_Get_Sfnt_Table(face, FT_SFNT_OS2));
        os2 && os2->version >= 2 && os2->version != 0xFFFF) {
      if (os2->sxHeight > 0) info.x_height = os2->sxHeight;
      if (os2->sCapHeight > 0) info.cap_height = os2->sCapHeight;
    }
  }

  void apply_variations(const FontLoadOptions& options) {
    FT_MM_Var* mm = nullptr;
    const bool variable = FT_HAS_MULTIPLE_MASTERS(face) && FT_Get_MM_Var(face, &mm) == 0;
    if (!variable) {
      if (!options.location.empty()) throw InputError(file + ": --location needs a variable font, and this one is not");
      if (options.named_instance) throw InputError(file + ": --instance needs a variable font, and this one is not");
      return;
    }
    std::vector<FT_Fixed> coords(mm->num_axis);
    for (FT_UInt i = 0; i < mm->num_axis; ++i) {
      axes.push_back({tag_string(mm->axis[i].tag), mm->axis[i].minimum / 65536.0,
                      mm->axis[i].def / 65536.0, mm->axis[i].maximum / 65536.0});
      coords[i] = mm->axis[i].def;
    }
    if (options.named_instance) {
      const std::string& wanted = *options.named_instance;
      std::optional<FT_UInt> index;
      std::string available;
      for (FT_UInt i = 0; i < mm->num_namedstyles; ++i) {
        const std::string name = sfnt_name(face, mm->namedstyle[i].strid).value_or("");
        available += (available.empty() ? "" : ", ") + name;
        if (equal_ignoring_case(name, wanted) || wanted == std::to_string(i + 1)) index = i;
      }
      if (!index) {
        FT_Done_MM_Var(library, mm);
        throw InputError(file + ": no named instance '" + wanted + "' (it has: " + available + ")");
      }
      std::copy_n(mm->namedstyle[*index].coords, mm->num_axis, coords.begin());
      varied = true;
    }
    for (const AxisValue& v : options.location) {
      const auto it = std::find_if(axes.begin(), axes.end(), [&](const VariationAxis& a) { return a.tag == v.tag; });
      if (it == axes.end()) {
        std::string have;
        for (const auto& a : axes) have += (have.empty() ? "" : ", ") + trimmed_tag(a.tag);
        FT_Done_MM_Var(library, mm);
        throw InputError(file + ": --location: no axis '" + trimmed_tag(v.tag) + "' (it has: " + have + ")");
      }
      if (v.value < it->minimum || v.value > it->maximum) {
        FT_Done_MM_Var(library, mm);
        throw InputError(file + ": --location: " + trimmed_tag(v.tag) + "=" + format_number(v.value) +
                         " is outside the axis range " + format_number(it->minimum) + " to " +
                         format_number(it->maximum));
      }
      coords[static_cast<std::size_t>(it - axes.begin())] = static_cast<FT_Fixed>(std::lround(v.value * 65536.0));
      varied = true;
    }
    FT_Done_MM_Var(library, mm);
    // The location itself is applied by HarfBuzz, which draws the instance (see `instance`).
    for (std::size_t i = 0; i < axes.size(); ++i) location.push_back({axes[i].tag, coords[i] / 65536.0});
  }

};

namespace {

enum class PointKind { on, conic, cubic };

// One FreeType contour to the model: the contour starts at its first on-curve point; a
// contour made only of conic off-curve points starts at the implied point before its first.
Contour contour_from_points(std::span<const Vec2> p, std::span<const PointKind> kind) {
  Contour c;
  const std::size_t n = p.size();
  const auto first_on = std::find(kind.begin(), kind.end(), PointKind::on);
  std::vector<Vec2> q;
  std::vector<PointKind> k;
  bool start_implied = false;
  if (first_on == kind.end()) {
    q.push_back((p[n - 1] + p[0]) * 0.5);
    k.push_back(PointKind::on);
    start_implied = true;
    q.insert(q.end(), p.begin(), p.end());
    k.insert(k.end(), kind.begin(), kind.end());
  } else {
    const std::size_t s = static_cast<std::size_t>(first_on - kind.begin());
    for (std::size_t i = 0; i < n; ++i) {
      q.push_back(p[(s + i) % n]);
      k.push_back(kind[(s + i) % n]);
    }
  }
  const std::size_t m = q.size();
  c.nodes.push_back({start_implied, std::nullopt});
  Vec2 current = q[0];
  std::vector<Vec2> pending;
  PointKind pending_kind = PointKind::on;
  for (std::size_t i = 1; i <= m; ++i) {
    const Vec2 pt = q[i % m];
    const PointKind pk = i == m ? PointKind::on : k[i];
    if (pk == PointKind::conic && pending_kind == PointKind::conic && !pending.empty()) {
      const Vec2 mid = (pending.back() + pt) * 0.5;
      c.segments.push_back(Quad{{current, pending.back(), mid}});
      c.nodes.push_back({true, std::nullopt});
      current = mid;
      pending = {pt};
      continue;
    }
    if (pk != PointKind::on) {
      pending.push_back(pt);
      pending_kind = pk;
      continue;
    }
    if (pending.empty()) c.segments.push_back(Line{{current, pt}});
    else if (pending_kind == PointKind::conic) c.segments.push_back(Quad{{current, pending[0], pt}});
    else if (pending.size() == 2) c.segments.push_back(Cubic{{current, pending[0], pending[1], pt}});
    else c.segments.push_back(Cubic{{current, pending[0], pending[0], pt}});  // a lone cubic control
    pending.clear();
    pending_kind = PointKind::on;
    current = pt;
    if (i < m) c.nodes.push_back({false, std::nullopt});
  }
  return c;
}

}  // namespace

FreetypeFont::FreetypeFont(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
FreetypeFont::FreetypeFont(FreetypeFont&&) noexcept = default;
FreetypeFont& FreetypeFont::operator=(FreetypeFont&&) noexcept = default;
FreetypeFont::~FreetypeFont() = default;

FreetypeFont FreetypeFont::open(const std::filesystem::path& path, const FontLoadOptions& options) {
  auto impl = std::make_unique<Impl>();
  impl->file = path.string();
  impl->bytes = read_bytes(path);
  const auto directory = read_sfnt_directory(impl->bytes, impl->file);  // refuses truncated fonts up front
  if (FT_Init_FreeType(&impl->library) != 0) throw InputError(impl->file + ": cannot start FreeType");
  if (const FT_Error e = FT_New_Memory_Face(impl->library, impl->bytes.data(),
                                            static_cast<FT_Long>(impl->bytes.size()), 0, &impl->face)) {
    if (!directory) throw InputError(impl->file + ": not a font file (no OpenType or other font header FreeType knows)");
    throw InputError(impl->file + ": a damaged font FreeType cannot read: " + hex_error(e));
  }
  if (!FT_IS_SCALABLE(impl->face) || impl->face->units_per_EM == 0)
    throw InputError(impl->file + ": has no scalable outlines (a bitmap-only font)");
  impl->read_cmap();
  impl->read_names();
  impl->read_info(path);
  impl->apply_variations(options);
  // CFF charstrings carry fractions (Inconsolata's E stands at x = 58.68), which FreeType
  // unscaled truncates to whole units; HarfBuzz draws them as they are.
  if (impl->varied || (directory && (directory->tables.count("CFF2") || directory->tables.count("CFF "))))
    impl->instance.emplace(impl->bytes, impl->location);
  return FreetypeFont(std::move(impl));
}

const FontInfo& FreetypeFont::info() const { return impl_->info; }
std::uint32_t FreetypeFont::glyph_count() const { return static_cast<std::uint32_t>(impl_->names.size()); }
const std::string& FreetypeFont::glyph_name(std::uint32_t gid) const { return impl_->names.at(gid); }
std::span<const std::pair<char32_t, std::uint32_t>> FreetypeFont::character_map() const { return impl_->cmap; }
std::vector<VariationAxis> FreetypeFont::axes() const { return impl_->axes; }
const std::vector<AxisValue>& FreetypeFont::location() const { return impl_->location; }
std::span<const std::uint8_t> FreetypeFont::bytes() const { return impl_->bytes; }

std::optional<std::uint32_t> FreetypeFont::glyph_by_name(std::string_view name) const {
  const auto it = impl_->by_name.find(std::string(name));
  if (it == impl_->by_name.end()) return std::nullopt;
  return it->second;
}

std::optional<std::uint32_t> FreetypeFont::glyph_by_codepoint(char32_t c) const {
  const auto it = std::lower_bound(impl_->cmap.begin(), impl_->cmap.end(), std::pair<char32_t, std::uint32_t>{c, 0});
  if (it == impl_->cmap.end() || it->first != c) return std::nullopt;
  return it->second;
}

Glyph FreetypeFont::load_glyph(std::uint32_t gid) const {
  const Impl& m = *impl_;
  if (gid >= m.names.size()) throw InputError(m.file + ": no glyph with index " + std::to_string(gid));
  Glyph g;
  g.name = m.names[gid];
  g.unicodes = m.unicodes[gid];
  if (m.instance) {
    g.advance_width = m.instance->advance_width(gid);
    g.outline = m.instance->outline(gid);
    return g;
  }
  if (const FT_Error e = FT_Load_Glyph(m.face, gid, FT_LOAD_NO_SCALE))
    throw InputError(m.where(gid) + ": cannot load its outline: " + hex_error(e));
  const FT_GlyphSlot slot = m.face->glyph;
  if (slot->format != FT_GLYPH_FORMAT_OUTLINE)
    throw InputError(m.where(gid) + ": has no outline (a bitmap glyph)");
  // TrueType outlines arrive moved by hmtx.lsb − glyf.xMin, as FreeType, HarfBuzz and
  // fontTools all draw them (sketch-refine-io.md §4): that is the outline the font shows.
  g.advance_width = double(slot->metrics.horiAdvance);

  const FT_Outline& o = slot->outline;
  std::vector<Vec2> points;
  std::vector<PointKind> kinds;
  int first = 0;
  for (int ci = 0; ci < o.n_contours; ++ci) {
    const int last = o.contours[ci];
    if (last < first || last >= o.n_points)
      throw InputError(m.where(gid) + ": malformed outline (contour end out of range)");
    points.clear();
    kinds.clear();
    for (int i = first; i <= last; ++i) {
      points.push_back({double(o.points[i].x), double(o.points[i].y)});
      const int tag = FT_CURVE_TAG(o.tags[i]);
      kinds.push_back(tag == FT_CURVE_TAG_ON ? PointKind::on : tag == FT_CURVE_TAG_CUBIC ? PointKind::cubic : PointKind::conic);
    }
    g.outline.contours.push_back(contour_from_points(points, kinds));
    first = last + 1;
  }
  return g;
}

}  // namespace gf
