// Paths of the bundled test fonts (fonts/, with their licences).
#pragma once

#include <string>

namespace gf::test {

inline const std::string fonts = GLYPHFAIR_FONTS;
inline const std::string dejavu = fonts + "/DejaVuSans/DejaVuSans-subset.ttf";
inline const std::string dejavu_serif = fonts + "/DejaVuSerif/DejaVuSerif-subset.ttf";  // R, s
inline const std::string because_we_learn = fonts + "/BecauseWeLearn/BecauseWeLearn-Regular-subset.otf";
inline const std::string inter_variable = fonts + "/Inter/Inter-subset.var.ttf";
inline const std::string inconsolata = fonts + "/Inconsolata/Inconsolata-subset.otf";
inline const std::string cantarell = fonts + "/Cantarell/Cantarell-Regular-subset.otf";  // S
inline const std::string lato = fonts + "/Lato/Lato-Regular-subset.ttf";  // c, g, j, s, t, z, K, M, S, W, Y
inline const std::string kristi = fonts + "/Kristi/Kristi-subset.ttf";  // N
inline const std::string eb_garamond = fonts + "/EBGaramond/EBGaramond12-Regular-subset.otf";  // d, G, I, W
inline const std::string noto_sans = fonts + "/NotoSans/NotoSans-Regular-subset.ttf";  // h, W
inline const std::string noto_serif = fonts + "/NotoSerif/NotoSerif-Regular-subset.ttf";  // A, E, Y, Z, k, v, y
inline const std::string free_serif = fonts + "/FreeSerif/FreeSerif-subset.ttf";  // w
inline const std::string carlito = fonts + "/Carlito/Carlito-Regular-subset.ttf";  // w, M, x, V
inline const std::string gentium_plus = fonts + "/GentiumPlus/GentiumPlus-Regular-subset.ttf";  // d X w M
inline const std::string comic_neue = fonts + "/ComicNeue/ComicNeue-Regular-subset.otf";  // d, i, n, u
inline const std::string linux_libertine = fonts + "/LinuxLibertine/LinLibertine_R-subset.otf";  // d, g, D, M, T, Z
inline const std::string quicksand = fonts + "/Quicksand/Quicksand-Regular-subset.ttf";  // A W x
inline const std::string linux_biolinum = fonts + "/LinuxBiolinum/LinBiolinum_R-subset.otf";  // f
// dkg handwriting's T, renamed (its licence reserves the name)
inline const std::string handwriting_probe = fonts + "/HandwritingProbe/GlyphfairProbeHandwriting-T.ttf";
// Liberation Sans 2.1's M, renamed (its licence reserves the name)
inline const std::string sans_probe = fonts + "/SansProbe/GlyphfairProbeSans-M.ttf";
// Liberation Serif 2.1's D, renamed (its licence reserves the name)
inline const std::string serif_probe = fonts + "/SerifProbe/GlyphfairProbeSerif-D.ttf";
inline const std::string cff2_variable = fonts + "/Inter/GlyphfairProbe-CFF2.var.otf";

}  // namespace gf::test
