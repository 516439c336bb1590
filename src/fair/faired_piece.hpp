// The faired curve itself, before the cubic writeback: what each piece of a contour is, with
// its end frames (κ and κ′ included), so that the continuity the fairing claims can be checked
// outside it (`glyphfair fair --segments`).
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "aesthetic/log_aesthetic_segment.hpp"

namespace gf {

/// `as_drawn`: a cubic of a run no chain fairs, kept as the source draws it.
enum class FairedPieceKind { line, log_aesthetic, polynomial_spiral, guide, as_drawn };

struct FairedPiece {
  FairedPieceKind kind;
  double length;
  LacPoint start, end;            ///< κ′ nullopt where unbounded (a log-aesthetic inflection end) or not known (a guide's)
  std::optional<double> alpha{};  ///< log-aesthetic segments: the LCG slope
  bool smooth_start = false;      ///< the join with the piece before is smooth, not a corner
  /// Polynomial spirals: the symmetric and odd bumps c₁, c₂ (aesthetic/polynomial_spiral.hpp).
  std::optional<std::pair<double, double>> bumps{};
};

/// A contour's pieces in order; empty when the contour was kept unfaired.
using FairedPieces = std::vector<FairedPiece>;

inline const char* to_string(FairedPieceKind kind) {
  switch (kind) {
    case FairedPieceKind::line: return "line";
    case FairedPieceKind::log_aesthetic: return "log-aesthetic";
    case FairedPieceKind::polynomial_spiral: return "polynomial-spiral";
    case FairedPieceKind::guide: return "guide";
    case FairedPieceKind::as_drawn: return "as-drawn";
  }
  return "";
}

}  // namespace gf
