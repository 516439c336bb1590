// Glyph names for fonts that store none (a TrueType 'post' table of format 3): the names of
// the Adobe Glyph List For New Fonts for the code points of Basic Latin and Latin-1, the ones
// a designer handles daily ("A", "zero", "comma", "Agrave"), as fontTools and FontForge give
// them; other code points are named uniXXXX by the reader.
#pragma once

#include <optional>
#include <string_view>

namespace gf {

/// The AGLFN name of `code_point` where it lies in U+0020–U+007E or U+00A0–U+00FF and the
/// list names it (it leaves out U+00A0, U+00AD, U+00B2, U+00B3 and U+00B9); else none.
std::optional<std::string_view> agl_name(char32_t code_point);

}  // namespace gf
