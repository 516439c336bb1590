// The exit codes of the glyphfair command (README "Exit codes").
#pragma once

namespace gf::exit_code {
inline constexpr int ok = 0;
inline constexpr int internal_error = 1;  ///< a bug: please report it
inline constexpr int bad_input = 2;       ///< bad usage, or an input file, glyph or option that does not fit
inline constexpr int cannot_write = 3;    ///< an output could not be written (nothing partial is left)
inline constexpr int findings = 4;        ///< glyphfair check found problems at or above --fail-on
}  // namespace gf::exit_code
