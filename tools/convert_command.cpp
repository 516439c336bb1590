// glyphfair convert SRC [selection] -o OUT.ufo|.svg|.json: the selection written unchanged.
#include <algorithm>
#include <filesystem>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "io/input_error.hpp"
#include "io/json_writer.hpp"
#include "io/svg_writer.hpp"
#include "io/ufo_writer.hpp"

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
  std::string ext = fs::path(output_).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".ufo" && ext != ".svg" && ext != ".json")
    throw InputError(output_ + ": unknown output format (use .ufo, .svg or .json)");
  const GlyphSource source = GlyphSource::open(source_, selection_.parse());
  GlyphSet glyphs = source.load_all();
  if (cubic_)
    for (Glyph& g : glyphs.glyphs)
      for (Contour& c : g.outline.contours) c = with_cubics(c);
  const fs::path inputs[] = {source_};
  if (ext == ".ufo") write_ufo(glyphs, output_, inputs);
  else if (ext == ".svg") write_svg(glyphs, output_, inputs);
  else write_json(glyphs, output_, inputs);
  return exit_code::ok;
}

}  // namespace gf
