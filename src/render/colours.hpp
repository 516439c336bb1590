// The proof's palette, chosen to stay apart when printed in colour and to keep the outline
// readable under the combs.
#pragma once

namespace gf::colour {

struct Rgba {
  double r, g, b, a = 1.0;
};

inline constexpr Rgba ink{0.08, 0.08, 0.10};
inline constexpr Rgba fill{0.10, 0.10, 0.12, 0.10};
inline constexpr Rgba metrics{0.55, 0.58, 0.62};
inline constexpr Rgba handle{0.45, 0.45, 0.50};
inline constexpr Rgba comb_positive{0.16, 0.42, 0.82, 0.55};  // left turn
inline constexpr Rgba comb_negative{0.90, 0.45, 0.08, 0.60};  // right turn
inline constexpr Rgba inflection{0.78, 0.10, 0.62};
inline constexpr Rgba curvature_extremum{0.85, 0.12, 0.12};
inline constexpr Rgba axis_extremum{0.10, 0.58, 0.25};
inline constexpr Rgba start_point{0.10, 0.58, 0.25};
inline constexpr Rgba compare{0.86, 0.08, 0.20};
inline constexpr Rgba join_corner{0.25, 0.25, 0.28};
inline constexpr Rgba join_kink{0.90, 0.45, 0.08};

}  // namespace gf::colour
