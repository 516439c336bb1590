#include "source_options.hpp"

#include "io/variation_location.hpp"

namespace gf {

void SourceArguments::add_to(CLI::App& command) {
  command.add_option("--glyphs", glyphs, "Glyphs by name, comma-separated: a,b,c");
  command.add_option("--unicodes", unicodes, "Glyphs by code point, hb-subset syntax: U+0041-005A,U+0061");
  command.add_option("--text", text, "The glyphs this text uses, shaped with HarfBuzz (ligatures included)");
  command.add_option("--location", location, "Variable fonts: design coordinates, e.g. wght=700,wdth=80");
  command.add_option("--instance", instance, "Variable fonts: a named instance, by name or 1-based number");
}

SourceOptions SourceArguments::parse() const {
  SourceOptions o;
  o.selection.names = split_glyph_names(glyphs);
  if (!unicodes.empty()) o.selection.unicodes = parse_unicode_ranges(unicodes);
  o.selection.text = text;
  if (!location.empty()) o.font.location = parse_variation_location(location);
  if (!instance.empty()) o.font.named_instance = instance;
  return o;
}

}  // namespace gf
