// A font's contours faired once each. Composite glyphs repeat their components' contours
// point for point (an accented letter its base letter's: whole DejaVu Sans has 16,080
// contours, 7,767 of them distinct), and a contour's fairing depends on nothing but the
// contour and the settings, so a repeat takes the first one's result.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <mutex>
#include <unordered_map>
#include <utility>

#include "fair/contour_fairing.hpp"

namespace gf {

/// fair_contour with its results kept by their inputs. Shared by the threads that fair a
/// font's glyphs; keeps the `capacity` contours faired last, so memory stays bounded on any
/// font (a CJK font's 50,000 glyphs).
class FairedContours {
 public:
  explicit FairedContours(std::size_t capacity = 8192) : capacity_(capacity) {}
  ContourFairing fair(const Contour& source, const FairSettings& settings);
  /// How many contours it holds.
  std::size_t size() const;

 private:
  struct Entry {
    std::uint64_t serial;  ///< the order it came in
    Contour source;
    FairSettings settings;
    ContourFairing result;
  };
  std::size_t capacity_;
  mutable std::mutex mutex_;
  std::unordered_multimap<std::size_t, Entry> entries_;      ///< by hash of the source and settings
  std::deque<std::pair<std::size_t, std::uint64_t>> order_;  ///< hash and serial, oldest first
  std::uint64_t serial_ = 0;
};

}  // namespace gf
