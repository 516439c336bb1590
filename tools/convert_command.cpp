// glyphfair convert SRC [selection] -o OUT.ufo|.svg|.json: the selection written unchanged.
#include <filesystem>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "outline_output.hpp"

namespace fs = std::filesystem;

namespace gf {

void ConvertCommand::add_to(CLI::App& app) {
  add(app, "convert", "Write glyphs to UFO 3, SVG or JSON (with analysis) without changing a coordinate",
      "OUT.ufo, OUT.svg or OUT.json")
      .add_flag("--cubic", cubic_,
                "Write quadratic curves as their exact cubics (for tools that take no quadratics, such as "
                "fontmake's default overlap removal)");
}

int ConvertCommand::run() const {
  const OutlineFormat format = outline_format_for(output_);
  const GlyphSource source = GlyphSource::open(source_, selection_.parse());
  GlyphSet glyphs = source.load_all();
  if (cubic_)
    for (Glyph& g : glyphs.glyphs)
      for (Contour& c : g.outline.contours) c = with_cubics(c);
  const fs::path inputs[] = {source_};
  write_outlines(glyphs, output_, format, inputs);
  return exit_code::ok;
}

}  // namespace gf
