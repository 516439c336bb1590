// Glyph name -> .glif file name, the UFO 3 algorithm (fontTools.ufoLib.filenames
// userNameToFileName): illegal characters become '_', capitals get a trailing '_', a leading
// '.' becomes '_', reserved Windows names get a '_' prefix, clashes (ignoring case) get a
// numeric suffix.
#pragma once

#include <set>
#include <string>

namespace gf {

/// `taken` holds the lower-cased file names already used; the result is added to it.
std::string glif_file_name(const std::string& glyph_name, std::set<std::string>& taken);

}  // namespace gf
