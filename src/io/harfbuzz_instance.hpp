// Outlines and advances of a variable font's instance, or of a CFF font, through HarfBuzz,
// whose glyf and CFF2 variation arithmetic is unrounded (float, ~1e-4 unit), where FreeType's
// is rounded to 1/64 unit (glyf) or to whole units (CFF2); FreeType cannot load CFF2 unscaled
// at all, and truncates CFF's fractional coordinates to whole units.
#pragma once

#include <cstdint>
#include <memory>
#include <span>

#include "geom/contour.hpp"
#include "io/variation_location.hpp"

namespace gf {

class HarfbuzzInstance {
 public:
  /// `bytes` must outlive the instance.
  HarfbuzzInstance(std::span<const std::uint8_t> bytes, std::span<const AxisValue> location);
  HarfbuzzInstance(HarfbuzzInstance&&) noexcept;
  HarfbuzzInstance& operator=(HarfbuzzInstance&&) noexcept;
  ~HarfbuzzInstance();

  /// TrueType on-curve points that sit at the midpoint of their two off-curve neighbours
  /// (within 1e-3 unit) are marked implied, as the font stores them.
  Outline outline(std::uint32_t gid) const;
  /// In font units, to 1/1024 unit.
  double advance_width(std::uint32_t gid) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gf
