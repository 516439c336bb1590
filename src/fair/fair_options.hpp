// What the user asks of the fairing, and the defaults each profile resolves it to.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "geom/contour.hpp"
#include "geom/smoothing_spline.hpp"

namespace gf {

enum class FairProfile { text, handwriting };
/// g3: after the G2 solve, dκ/ds continuous too (fair/g3_run.hpp).
enum class Continuity { g1, g2, g3 };
/// How the written coordinates are rounded. as_source: a glyph whose source points are all
/// whole units goes to the integer grid; one drawn off it (a CFF font in fixed point, as
/// Inconsolata's 1/1024 units) keeps fractions, which the grid would coarsen.
enum class Rounding { as_source, integers, none };

struct FairOptions {
  FairProfile profile = FairProfile::text;
  Continuity continuity = Continuity::g2;
  std::optional<double> tolerance_units;   ///< two-sided Hausdorff bound, font units
  std::optional<double> corner_angle_deg;  ///< joins turning more than this stay corners
  Rounding rounding = Rounding::as_source;
};

/// The options with every default filled in for a font of `units_per_em`.
///   text:        tolerance 0.125 % of the em (a professional font's bar is 0.15 %; at the
///                0.1 % it was, rounding had too little left to make G2 exact where a curve
///                meets a long diagonal: DejaVu's s); corners from 3° (the check's kink
///                limit: a professional font's smooth joins are G1 to 0.05°, so anything at
///                3° or more was drawn as a corner);
///   handwriting: tolerance 1.4 % of the em (the bar is 1.5 %, and the fairing keeps within
///                its tolerance as it measures it: a tenth of a per cent is left for another
///                sampling; at 1 % dkg kept half its inflections and Because We Learn more, at
///                1.2 % Domestic Manners kept 0.52× its source's); corners from 30° (fonts
///                traced from scans break their curves by 3–20° at many joins; a stroke end or
///                a sharp turn of the pen turns by far more), and wobbles up to the tolerance
///                smoothed away: each run is first replaced by the smoothest spline within 0.8
///                of the chain's budget (geom/smoothing_spline's sparse penalty: fewest
///                changes of curvature; its lobes turning less than 30° merged into their
///                neighbours); a line under twice the tolerance that a curve meets within
///                half the corner angle faired with it (`stub_line_units`, `stub_turn_deg`).
struct FairSettings {
  FairProfile profile = FairProfile::text;
  Continuity continuity = Continuity::g2;
  double tolerance_units = 1.0;
  double corner_angle_deg = 3.0;
  /// Length over which the source's tangent is averaged to find inflections and curvature
  /// extrema: wobbles shorter than this are not features.
  double feature_window_units = 5.0;
  Rounding rounding = Rounding::as_source;
  /// The em the settings were resolved for (the check's rules are per em).
  double units_per_em = 1000.0;
  /// |κ| (1/unit) of half a unit per em: flatter curves are compared by the difference of
  /// their curvatures, not the ratio (the check's g2-jump rule).
  double flat_curvature() const { return 0.5 / units_per_em; }
  /// Of the tolerance, what the fairing leaves rounding to the grid (units; none without
  /// rounding): half a unit, what rounding moves a point, and room for the handle steps.
  double rounding_reserve_units = 0.5;
  /// The shortest span the cubic writeback halves when the outline is rounded (units; else
  /// fair/cubic_writeback's own): cubics of two to four units land on a few grid points whose
  /// whole steps cannot set their curvature (Breip's W and E, Because We Create's d, t and X
  /// kept jumps there; halving from eight units leaves no cubic under four).
  double shortest_rounded_span_units = 8.0;
  // rounding_reserve_units, shortest_rounded_span_units, free_node_curvatures,
  // split_beside_jumps, remove_spare_nodes, turn_inflection_nodes and fit_spare_runs are read
  // by the budgets, the writeback and rounding, never by fair_run: a contour's fairings that
  // differ only in them share their faired runs (fair/plan_fairing's RunFairings).
  /// The writeback may give an extremum inside a chain another curvature than the faired
  /// path's where both spans beside it then fit as one cubic each (fair/node_curvatures):
  /// fewer nodes for the same budget. Text only: on handwriting the single cubics' curvature
  /// humps added curvature extrema (a–z A–Z, Because We Learn 0.439× → 0.486× of its
  /// source's, against the bar's 0.5×) for 7 % fewer nodes.
  bool free_node_curvatures = false;
  /// Text under G2 on the grid: where rounding leaves a curvature jump, the float cubics beside
  /// it are split in two and rounded again, kept where that leaves fewer faults
  /// (fair/jump_splits.hpp).
  bool split_beside_jumps = true;
  /// The writeback's spare nodes removed where one cubic draws their two (fair/spare_nodes).
  /// Text, not under G3. On handwriting the merged cubics' curvature humps added curvature
  /// extrema (a–z A–Z: Because We Learn 0.439× → 0.472× of its source's, Purisa 0.432× →
  /// 0.449×, against the bar's 0.5×) and dkg a missing extremum. Under G3 the merged cubics
  /// spend the tolerance the G3 solve moves the cubics within (fair/g3_cubics): the κ′ jump
  /// median of DejaVu Sans, TeX Gyre Heros and Lato came out 0.21, 0.91 and 0.59 (0.033–0.040
  /// with the spare nodes kept, 1.15–1.19× the nodes of the pruned G2 output, under the G3
  /// bar's 1.2×).
  bool remove_spare_nodes = false;
  /// Spare nodes next to an inflection node removed also where that node's tangent turns a
  /// little (SpareNodeLimits::turn_inflection_nodes); a try that turns none is given up before
  /// its rounding. Set only by fair_contour's fairing after the first, never by the options:
  /// see there.
  bool turn_inflection_nodes = false;
  /// With remove_spare_nodes, after the windows, each run of cubics between inflections,
  /// corners and lines fitted again whole without its spare nodes (SpareNodeLimits::fit_runs).
  /// Cleared by fair_contour's fairing again of a contour that this leaves with faults: see
  /// there.
  bool fit_spare_runs = true;
  /// Text: the kinks where curves meet lines kept as corners, as drawn, instead of the curves
  /// made tangential to the lines (fair_contour's last fairing again of a contour whose runs
  /// faired only on another basis than their own outlines).
  bool line_kinks_as_drawn = false;
  /// The share of the tolerance (after rounding's reserve) the log-aesthetic chain may use;
  /// the cubics get the rest. Text 0.4; handwriting 0.7, where the chain follows a smoothed
  /// guide and the cubics follow the chain closely.
  double chain_share = 0.4;
  /// Handwriting: how far the smoothing guide may stray from the source, as a share of the
  /// chain's budget (0.8: as smooth as leaves the chain room to follow it).
  double guide_share = 0.8;
  /// Handwriting: the guide's lobes of curvature merged into their neighbours
  /// (geom/smoothing_spline): those turning less than 30°, held to bend at least 0.3 per em.
  LobeMerging guide_lobes;
  /// Handwriting: each chain's free junction tangents start inside the wedge between their
  /// chords (fair/initial_tangents); on text, g2-jumps moved both ways (seven fonts 20 → 21).
  bool tangents_between_chords = false;
  /// Where given, a line shorter than this (units) that a curve meets tangentially is the
  /// curve's stretch drawn straight, faired with it (fair/contour_plan's
  /// PlanOptions::stub_line_units, whose own 2 units text keeps): handwriting twice the
  /// tolerance, where a tracer draws the flat top of a round stroke end as a line of a few
  /// units and the joins' κ = 0 split it into two peaks (Tomson Talks's N: TV 622 → 513).
  std::optional<double> stub_line_units{};
  /// Where given, a curve meeting such a line within this (degrees) counts as meeting it
  /// tangentially (PlanOptions::stub_turn_deg). Handwriting: half its corner angle, as a
  /// scan breaks its curves by 3–20° at lines too (Tomson Talks's H: its tip's one-unit line
  /// met 13° off the curve before it, and the corner there split the tip into two stretches;
  /// Tomson Talks's TV 0.277× → 0.228× of its source's, the same at 10°, 20° and 30°; at 10°
  /// Because We Build kept more nodes, at 20° and 30° Femke Klaver's inflections rose 0.40× →
  /// 0.47×).
  std::optional<double> stub_turn_deg{};
  bool operator==(const FairSettings&) const = default;
};

FairSettings resolve_settings(const FairOptions& options, double units_per_em);

/// `rounding` for the outline made of `contours`: as_source resolved to integers or none.
Rounding resolve_rounding(Rounding rounding, std::span<const Contour> contours);

std::optional<FairProfile> parse_fair_profile(const std::string& name);
std::optional<Continuity> parse_continuity(const std::string& name);
const char* to_string(FairProfile profile);
const char* to_string(Continuity continuity);

}  // namespace gf
