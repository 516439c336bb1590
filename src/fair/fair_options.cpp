#include "fair/fair_options.hpp"

#include <algorithm>
#include <numbers>

namespace gf {

FairSettings resolve_settings(const FairOptions& options, double units_per_em) {
  FairSettings s;
  s.profile = options.profile;
  s.continuity = options.continuity;
  s.rounding = options.rounding;
  const bool hand = options.profile == FairProfile::handwriting;
  s.tolerance_units = options.tolerance_units.value_or((hand ? 0.014 : 0.00125) * units_per_em);
  s.corner_angle_deg = options.corner_angle_deg.value_or(hand ? 30.0 : 3.0);
  s.units_per_em = units_per_em;
  s.chain_share = hand ? 0.7 : 0.4;
  s.feature_window_units = hand ? 0.03 * units_per_em : 0.004 * units_per_em;
  if (hand) s.guide_lobes = {std::numbers::pi / 6.0, 0.3 / units_per_em};
  s.tangents_between_chords = hand;
  s.free_node_curvatures = !hand;
  s.remove_spare_nodes = !hand && options.continuity != Continuity::g3;
  if (hand) {
    s.stub_line_units = 2.0 * s.tolerance_units;
    s.stub_turn_deg = 0.5 * s.corner_angle_deg;
  }
  return s;
}

Rounding resolve_rounding(Rounding rounding, std::span<const Contour> contours) {
  if (rounding != Rounding::as_source) return rounding;
  const bool whole = std::all_of(contours.begin(), contours.end(), on_integer_grid);
  return whole ? Rounding::integers : Rounding::none;
}

std::optional<FairProfile> parse_fair_profile(const std::string& name) {
  if (name == "text") return FairProfile::text;
  if (name == "handwriting") return FairProfile::handwriting;
  return std::nullopt;
}

std::optional<Continuity> parse_continuity(const std::string& name) {
  if (name == "g1") return Continuity::g1;
  if (name == "g2") return Continuity::g2;
  if (name == "g3") return Continuity::g3;
  return std::nullopt;
}

const char* to_string(FairProfile profile) { return profile == FairProfile::text ? "text" : "handwriting"; }

const char* to_string(Continuity continuity) {
  static constexpr const char* names[] = {"g1", "g2", "g3"};
  return names[static_cast<int>(continuity)];
}

}  // namespace gf
