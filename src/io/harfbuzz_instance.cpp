#include "io/harfbuzz_instance.hpp"

#include <cmath>
#include <variant>
#include <vector>

#include <hb.h>

namespace gf {

namespace {

// HarfBuzz draws CFF in 16.16 fixed point, so a contour can come back to its start 1.5e-5
// units off (Linux Libertine's d, i, Y) and close with a line that short: residue, not a
// segment, and as a line it would make two corners of a smooth join.
constexpr double residue_units = 1e-3;

struct OutlineBuilder {
  Outline outline;
  Contour contour;
  Vec2 current;
  bool open = false;

  void finish(bool closed) {
    if (!open) return;
    if (!contour.segments.empty()) {
      if (closed) close_on_start();
      contour.closed = closed;
      contour.nodes.assign(contour.segments.size() + (closed ? 0 : 1), NodeFlags{});
      outline.contours.push_back(std::move(contour));
    }
    contour = Contour{};
    open = false;
  }

  // The closing residue line was never added (line_to); the last segment ends on the start.
  void close_on_start() {
    const Vec2 start = start_point(contour.segments.front());
    if (distance(end_point(contour.segments.back()), start) <= residue_units)
      std::visit([&](auto& s) { s.p.back() = start; }, contour.segments.back());
  }
};

OutlineBuilder& builder(void* data) { return *static_cast<OutlineBuilder*>(data); }

void move_to(hb_draw_funcs_t*, void* d, hb_draw_state_t*, float x, float y, void*) {
  OutlineBuilder& b = builder(d);
  b.finish(false);
  b.current = {x, y};
  b.open = true;
}
void line_to(hb_draw_funcs_t*, void* d, hb_draw_state_t*, float x, float y, void*) {
  OutlineBuilder& b = builder(d);
  if (distance(b.current, {x, y}) <= residue_units) return;
  b.contour.segments.push_back(Line{{b.current, {x, y}}});
  b.current = {x, y};
}
void quadratic_to(hb_draw_funcs_t*, void* d, hb_draw_state_t*, float cx, float cy, float x, float y, void*) {
  OutlineBuilder& b = builder(d);
  b.contour.segments.push_back(Quad{{b.current, {cx, cy}, {x, y}}});
  b.current = {x, y};
}
void cubic_to(hb_draw_funcs_t*, void* d, hb_draw_state_t*, float c1x, float c1y, float c2x, float c2y, float x,
              float y, void*) {
  OutlineBuilder& b = builder(d);
  b.contour.segments.push_back(Cubic{{b.current, {c1x, c1y}, {c2x, c2y}, {x, y}}});
  b.current = {x, y};
}
void close_path(hb_draw_funcs_t*, void* d, hb_draw_state_t*, void*) { builder(d).finish(true); }

void mark_implied(Contour& c) {
  const std::size_t n = c.segments.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (i == 0 && !c.closed) continue;
    const auto* in = std::get_if<Quad>(&c.segments[(i + n - 1) % n]);
    const auto* out = std::get_if<Quad>(&c.segments[i]);
    if (!in || !out || i == 0) continue;  // node 0 stays explicit, like the FreeType reader's
    const Vec2 mid = (in->p[1] + out->p[1]) * 0.5;
    if (distance(mid, out->p[0]) <= 1e-3) c.nodes[i].implied = true;
  }
}

}  // namespace

struct HarfbuzzInstance::Impl {
  hb_blob_t* blob = nullptr;
  hb_face_t* face = nullptr;
  hb_font_t* font = nullptr;
  hb_font_t* fine = nullptr;  // scaled 1024× for advances
  hb_draw_funcs_t* funcs = nullptr;
  ~Impl() {
    hb_draw_funcs_destroy(funcs);
    hb_font_destroy(fine);
    hb_font_destroy(font);
    hb_face_destroy(face);
    hb_blob_destroy(blob);
  }
};

HarfbuzzInstance::HarfbuzzInstance(std::span<const std::uint8_t> bytes, std::span<const AxisValue> location)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.blob = hb_blob_create(reinterpret_cast<const char*>(bytes.data()), static_cast<unsigned>(bytes.size()),
                          HB_MEMORY_MODE_READONLY, nullptr, nullptr);
  m.face = hb_face_create(m.blob, 0);
  m.font = hb_font_create(m.face);
  std::vector<hb_variation_t> variations;
  for (const AxisValue& a : location)
    variations.push_back({HB_TAG(a.tag[0], a.tag[1], a.tag[2], a.tag[3]), static_cast<float>(a.value)});
  hb_font_set_variations(m.font, variations.data(), static_cast<unsigned>(variations.size()));
  m.fine = hb_font_create_sub_font(m.font);
  const int upem = static_cast<int>(hb_face_get_upem(m.face));
  hb_font_set_scale(m.fine, upem * 1024, upem * 1024);
  m.funcs = hb_draw_funcs_create();
  hb_draw_funcs_set_move_to_func(m.funcs, move_to, nullptr, nullptr);
  hb_draw_funcs_set_line_to_func(m.funcs, line_to, nullptr, nullptr);
  hb_draw_funcs_set_quadratic_to_func(m.funcs, quadratic_to, nullptr, nullptr);
  hb_draw_funcs_set_cubic_to_func(m.funcs, cubic_to, nullptr, nullptr);
  hb_draw_funcs_set_close_path_func(m.funcs, close_path, nullptr, nullptr);
  hb_draw_funcs_make_immutable(m.funcs);
}

HarfbuzzInstance::HarfbuzzInstance(HarfbuzzInstance&&) noexcept = default;
HarfbuzzInstance& HarfbuzzInstance::operator=(HarfbuzzInstance&&) noexcept = default;
HarfbuzzInstance::~HarfbuzzInstance() = default;

Outline HarfbuzzInstance::outline(std::uint32_t gid) const {
  OutlineBuilder b;
  hb_font_get_glyph_shape(impl_->font, gid, impl_->funcs, &b);
  b.finish(false);
  for (Contour& c : b.outline.contours) mark_implied(c);
  return std::move(b.outline);
}

double HarfbuzzInstance::advance_width(std::uint32_t gid) const {
  return hb_font_get_glyph_h_advance(impl_->fine, gid) / 1024.0;
}

}  // namespace gf
