// UFO 3 output: glyph names, unicodes, advance widths, smooth flags, contour order, direction
// and start points as in the model; quadratic runs with implied on-curve points as `qcurve`.
#pragma once

#include <filesystem>
#include <span>

#include <set>
#include <string>

#include "geom/contour.hpp"
#include "io/atomic_output.hpp"
#include "io/plist.hpp"

namespace gf {

/// A UFO written a glyph at a time (so a whole CJK font need not be in memory), into a staging
/// directory that commit() renames into place; never over one of `inputs`. Throws OutputError.
class UfoWriter {
 public:
  UfoWriter(const std::filesystem::path& target, const FontInfo& font, std::span<const std::filesystem::path> inputs = {});
  ~UfoWriter();
  void add(const Glyph& glyph);
  void commit();

 private:
  std::filesystem::path target_;
  AtomicOutput out_;
  std::set<std::string> taken_;
  PlistDict contents_;
  PlistArray order_;
};

/// Writes atomically (a staging directory renamed into place); never over one of `inputs`.
/// Throws OutputError.
void write_ufo(const GlyphSet& glyphs, const std::filesystem::path& target,
               std::span<const std::filesystem::path> inputs = {});

}  // namespace gf
