#include "outline_output.hpp"

#include "io/file_extension.hpp"
#include "io/input_error.hpp"
#include "io/json_writer.hpp"
#include "io/svg_writer.hpp"
#include "io/ufo_writer.hpp"

namespace gf {

OutlineFormat outline_format_for(const std::filesystem::path& output) {
  const std::string ext = lower_extension(output);
  if (ext == ".ufo") return OutlineFormat::ufo;
  if (ext == ".svg") return OutlineFormat::svg;
  if (ext == ".json") return OutlineFormat::json;
  throw InputError(output.string() + ": unknown output format (use .ufo, .svg or .json)");
}

void write_outlines(const GlyphSet& glyphs, const std::filesystem::path& target, OutlineFormat format,
                    std::span<const std::filesystem::path> inputs) {
  switch (format) {
    case OutlineFormat::ufo: write_ufo(glyphs, target, inputs); break;
    case OutlineFormat::svg: write_svg(glyphs, target, inputs); break;
    case OutlineFormat::json: write_json(glyphs, target, inputs); break;
  }
}

}  // namespace gf
