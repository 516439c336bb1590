#include "io/text_shaping.hpp"

#include <algorithm>
#include <memory>

#include <hb.h>

#include "io/utf8.hpp"

namespace gf {

namespace {

template <typename T, void (*Destroy)(T*)>
using HbPtr = std::unique_ptr<T, decltype([](T* p) { Destroy(p); })>;

}  // namespace

std::vector<std::uint32_t> glyphs_for_text(std::span<const std::uint8_t> font_bytes,
                                           std::span<const AxisValue> location, std::string_view text) {
  decode_utf8(text);  // refuses malformed text before HarfBuzz would replace it
  HbPtr<hb_blob_t, hb_blob_destroy> blob(hb_blob_create(reinterpret_cast<const char*>(font_bytes.data()),
                                                        static_cast<unsigned>(font_bytes.size()),
                                                        HB_MEMORY_MODE_READONLY, nullptr, nullptr));
  HbPtr<hb_face_t, hb_face_destroy> face(hb_face_create(blob.get(), 0));
  HbPtr<hb_font_t, hb_font_destroy> font(hb_font_create(face.get()));
  std::vector<hb_variation_t> variations;
  for (const AxisValue& a : location)
    variations.push_back({HB_TAG(a.tag[0], a.tag[1], a.tag[2], a.tag[3]), static_cast<float>(a.value)});
  if (!variations.empty()) hb_font_set_variations(font.get(), variations.data(), static_cast<unsigned>(variations.size()));
  HbPtr<hb_buffer_t, hb_buffer_destroy> buffer(hb_buffer_create());
  hb_buffer_add_utf8(buffer.get(), text.data(), static_cast<int>(text.size()), 0, static_cast<int>(text.size()));
  hb_buffer_guess_segment_properties(buffer.get());
  hb_shape(font.get(), buffer.get(), nullptr, 0);
  unsigned count = 0;
  const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(buffer.get(), &count);
  std::vector<std::uint32_t> glyphs;
  for (unsigned i = 0; i < count; ++i)
    if (std::find(glyphs.begin(), glyphs.end(), info[i].codepoint) == glyphs.end()) glyphs.push_back(info[i].codepoint);
  return glyphs;
}

}  // namespace gf
