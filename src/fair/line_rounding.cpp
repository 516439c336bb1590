#include "fair/line_rounding.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "fair/cubic_change.hpp"
#include "geom/polyline_distance.hpp"
#include "geom/tangent_crossing.hpp"

namespace gf {

namespace {

constexpr double off_line = 0.75;        // units a slid end may lie off the line
constexpr double slide_weight = 0.02;    // a unit of slide costs this much of a unit moved
constexpr double step_weight = 0.1;      // a unit of primitive step costs this much
constexpr double tie_weight = 0.01;      // of a unit moved, at the ends of a line no curve meets
constexpr double fold_unit = 4.0;        // the cost of a curve the line's step bends into an extremum
constexpr int curve_samples = 32;
constexpr int slid_samples = 12;
constexpr double max_slide = 16.0;       // units, and at most half the curve's handle
constexpr double max_back_slide = 96.0;  // units back along the line, and at most half the line
constexpr double short_step = 3.0;       // units: no slide gives a shorter step than (2, 1)
constexpr double stray_share = 0.25;     // of its length, a handle on the line may change by
constexpr double fold_share = 0.75;      // of its curve's chord, a handle on the line may reach
constexpr int most_room = 3;             // units an end may move beyond its grid neighbours
// A join the curve cannot leave with κ = 0 costs as much as moving an end by what the line has
// left of the tolerance, and at least as much as the most an end may move: a brush font's 10
// units of room go to G2 before a shorter step, and no shorter step or unmoved end is worth a
// curvature jump (at one unit, DejaVu Serif's s spine took the step (3, −1) and left its curve's
// far handle 2.85 units off the line; docs/fairing.md, stop 47).
constexpr double far_handle_unit = most_room;
constexpr double most_line_turn = 0.1;   // radians, as a node may turn on the grid (handle_steps)

struct EndPlace {
  Vec2 point;
  double moved;     ///< from the exact end: its distance, or as Slide::moved measures a slid end
  bool slid = false;  ///< its curve's handle keeps its tip, not its length
};

// How a curve's end may slide along the line it meets tangentially: to a grid point near the
// line, its handle's tip staying where it was. The cost of a place is how far the curve from
// there (its first cubic, started at the place) strays from the exact line and curve, plus a
// fiftieth of the slide: sliding into the curve puts the join where the curve has bent off the
// line, sliding back along the line bends the curve's start.
class Slide {
 public:
  /// `curve`: the exact cubic, starting at the join; `line_end`: the line's other end;
  /// `line_step`: the length of the line's primitive step on the grid; `off_limit`: what the
  /// line has left of the tolerance.
  Slide(const Cubic& curve, Vec2 line_end, double line_step, double off_limit) : curve_(curve), off_limit_(off_limit) {
    const Vec2 tangent = curve.p[1] - curve.p[0];
    into_ = tangent / norm(tangent);
    reach_ = std::min(max_slide, 0.5 * norm(tangent));
    // Back far enough for the curve's handle to take one whole step of the line with its tip
    // where it was, where the line has room for two (Gentium Plus's M: a 1110-unit leg of step
    // (1, −111) and a 4-unit curve at its foot); a line of one step is no guide.
    const double half_line = 0.5 * distance(line_end, curve.p[0]);
    const double back = line_step + reach_ <= half_line ? std::max(max_back_slide, line_step + reach_) : max_back_slide;
    back_reach_ = std::max(reach_, std::min(back, half_line));
    path_.push_back(line_end);
    for (int k = 0; k <= curve_samples; ++k) path_.push_back(curve.point_at(static_cast<double>(k) / curve_samples));
  }

  double reach() const { return reach_; }
  /// How far back along the line, away from the curve, the end may slide.
  double back_reach() const { return back_reach_; }
  Vec2 into() const { return into_; }

  /// How far the end at `p` moves from `exact`, or nothing where it may not go.
  std::optional<double> moved(Vec2 exact, Vec2 p) const {
    const double signed_along = dot(into_, p - exact), along = std::abs(signed_along);
    if (along > (signed_along < 0.0 ? back_reach_ : reach_) || std::abs(cross(into_, p - exact)) > off_limit_)
      return std::nullopt;
    const Cubic slid{p, curve_.p[1], curve_.p[2], curve_.p[3]};
    std::array<Vec2, slid_samples + 1> samples;
    for (int k = 0; k <= slid_samples; ++k) samples[k] = slid.point_at(static_cast<double>(k) / slid_samples);
    double strays = directed_hausdorff(samples, path_, off_limit_);
    // Slid back beyond its handle, the curve takes over a stretch of the line: it must also
    // pass near every point of the curve it replaces.
    if (strays <= off_limit_ && signed_along < -distance(curve_.p[0], curve_.p[1]))
      strays = std::max(strays, directed_hausdorff(std::span(path_).subspan(1), samples, off_limit_));
    if (strays > off_limit_) return std::nullopt;
    return strays + slide_weight * along;
  }

 private:
  Cubic curve_;
  double off_limit_;
  Vec2 into_;
  double reach_, back_reach_;
  std::vector<Vec2> path_;  ///< the line's far end, then the curve
};

// Where a line's end may go: its nearest grid point and the neighbours, and the grid points
// within `room` (units, up to `most_room`) of it: a line a degree off the vertical has a
// primitive step of 60 units or more, and a few units more of room let it stand upright (Comic
// Neue's i: its stem's step (1, 63) folded the 52-unit foot into a loop); a curve's end also
// the grid points its slide allows. Without `any_neighbour`, only the neighbours within `room`
// (HandleStepLimits::any_grid_neighbour).
std::vector<EndPlace> end_places(Vec2 exact, const std::optional<Slide>& slide, double room, bool any_neighbour) {
  std::vector<EndPlace> out;
  const Vec2 base = nearest_grid_point(exact);
  const double neighbour_reach =
      any_neighbour ? std::numeric_limits<double>::infinity() : std::max(room, distance(base, exact)) + 1e-9;
  const int square = std::clamp(static_cast<int>(std::floor(room)), 1, most_room);
  const int reach = std::max(square, slide ? static_cast<int>(std::ceil(slide->reach() + off_line)) : 1);
  const auto consider = [&](Vec2 p, bool neighbour) {
    const std::optional<double> slid = slide ? slide->moved(exact, p) : std::nullopt;
    if (slid) out.push_back({p, *slid, true});
    else if (neighbour) out.push_back({p, distance(p, exact)});
  };
  for (int dx = -reach; dx <= reach; ++dx)
    for (int dy = -reach; dy <= reach; ++dy) {
      const Vec2 p = base + Vec2{double(dx), double(dy)};
      consider(p, (std::abs(dx) <= 1 && std::abs(dy) <= 1 && distance(p, exact) <= neighbour_reach) ||
                      (std::abs(dx) <= square && std::abs(dy) <= square && distance(p, exact) <= room));
    }
  // Back along the line beyond the square: the grid points beside it, unit by unit.
  if (slide && slide->back_reach() > reach) {
    std::vector<Vec2> seen;
    for (int t = reach; t <= static_cast<int>(slide->back_reach()) + 1; ++t) {
      const Vec2 c = nearest_grid_point(exact - static_cast<double>(t) * slide->into());
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy) {
          const Vec2 p = c + Vec2{double(dx), double(dy)};
          if (std::max(std::abs(p.x - base.x), std::abs(p.y - base.y)) <= reach) continue;  // in the square
          if (std::find(seen.begin(), seen.end(), p) != seen.end()) continue;
          seen.push_back(p);
          consider(p, false);
        }
    }
  }
  return out;
}

// The cubic between a line's end `end` (its handle there `near`) and its far node `far` (its
// handle there `h`): arriving at the line's end where `arrives`, else leaving it.
Cubic curve_at_line_end(Vec2 end, Vec2 near, Vec2 h, Vec2 far, bool arrives) {
  return arrives ? Cubic{far, h, near, end} : Cubic{end, near, h, far};
}

// The outline's line from node i to node i + 1 and what rounding must keep of it.
struct LineOnGrid {
  std::size_t i, j;
  bool curve_arrives;  ///< at node i a curve meets the line tangentially (node i's in-handle)
  bool curve_leaves;   ///< at node j likewise (node j's out-handle)
};

// Whether a curve leaving a along u and arriving at b along v can seat both its handles where
// its tangents meet: ahead of a and behind b (tangent_crossing), or on one line with b ahead of a.
bool tangents_seat_handles(Vec2 a, Vec2 u, Vec2 b, Vec2 v) {
  if (cross(u, v) == 0.0) return cross(u, b - a) == 0.0 && dot(b - a, u) > 0.0;
  return tangent_crossing(a, u, b, v).has_value();
}

// How a line placed with its ends at a and b fares.
struct LinePlacement {
  double cost = std::numeric_limits<double>::infinity();
  Vec2 step;
  std::optional<Vec2> in_handle, out_handle;  ///< the curves' handles on the line, at i and j
  double in_moved = 0.0, out_moved = 0.0;     ///< how far each moved from where it was
};

class LinePlacer {
 public:
  LinePlacer(const std::vector<OutlineNode>& exact, const std::vector<OutlineNode>& rounded,
             const std::vector<std::optional<Vec2>>& steps, const HandleStepLimits& limits)
      : exact_(exact), rounded_(rounded), steps_(steps), limits_(limits), exact_extrema_(exact.size(), 0) {
    // Each exact cubic's H/V extrema, once: every placement of its line weighs its far handle.
    for (std::size_t i = 0; i < exact.size(); ++i)
      if (exact[i].out_handle && exact[(i + 1) % exact.size()].in_handle)
        exact_extrema_[i] = inner_axis_extrema(outline_cubic(exact, i));
  }

  /// Past `bound`, only that it is past (the cost then is at least the bound).
  LinePlacement place(const LineOnGrid& line, const EndPlace& a, const EndPlace& b,
                      double bound = std::numeric_limits<double>::infinity()) const {
    LinePlacement out;
    const std::optional<Vec2> step = primitive_step(b.point - a.point);
    if (!step || turns_too_far(line, b.point - a.point) || leaves_its_axis(line, a.point, b.point)) return out;
    out.step = *step;
    const double unseated = std::max(far_handle_unit, limits_.allowance_at(line.i));
    const auto bent_corners = [&] {
      return corner_curve_cost(line.i, a.point, true, unseated) + corner_curve_cost(line.j, b.point, false, unseated);
    };
    // A line no curve meets tangentially needs no short step, and its ends' moves only break
    // ties: the lines beside it that a curve does meet decide where they go.
    if (!line.curve_arrives && !line.curve_leaves) {
      out.cost = tie_weight * std::max(a.moved, b.moved) + bent_corners();
      return out;
    }
    const double step_cost = step_weight * norm(out.step);
    out.cost = std::max(a.moved, b.moved) + step_cost;
    if (out.cost >= bound) return out;  // past already: the corners' curves not measured
    out.cost += bent_corners();
    if (out.cost >= bound) return out;
    // A curve's handle on the line: as long as it was (a slid end: its tip where it was, so the
    // curve keeps its shape); then its far handle nearest the line, so the join can keep κ = 0.
    const auto on_line = [&](const EndPlace& end, std::size_t node, Vec2 wanted, double sign) {
      return stepped_handle(end.point, out.step, sign, end.slid ? end.point : exact_[node].point, wanted);
    };
    if (line.curve_arrives) {
      const Vec2 wanted = *exact_[line.i].in_handle;
      out.in_handle = on_line(a, line.i, wanted, -1.0);
      out.in_moved = distance(*out.in_handle, wanted);
    }
    if (line.curve_leaves) {
      const Vec2 wanted = *exact_[line.j].out_handle;
      out.out_handle = on_line(b, line.j, wanted, 1.0);
      out.out_moved = distance(*out.out_handle, wanted);
    }
    out.cost = std::max({out.cost, out.in_moved, out.out_moved});
    if (out.cost >= bound) return out;
    if (out.in_handle) out.cost += far_handle_cost(previous(line.i), true, a.point, *out.in_handle, out.step, unseated);
    if (out.out_handle)
      out.cost += far_handle_cost((line.j + 1) % exact_.size(), false, b.point, *out.out_handle, out.step, unseated);
    return out;
  }

 private:
  std::size_t previous(std::size_t k) const { return (k + exact_.size() - 1) % exact_.size(); }

  // Whether a line that is horizontal or vertical on the grid (a baseline, an x-height, a
  // stem's side) would leave that very line with its ends at a and b. Such a line stays put
  // across itself, its ends sliding only along it: a corner moved to a neighbour for a
  // shorter step of the line beside it had tilted Open Sans's baseline under the w by 2 units
  // and Lato's A crossbar by 1, and put corners 1 or 2 units off the baseline and x-height.
  bool leaves_its_axis(const LineOnGrid& line, Vec2 a, Vec2 b) const {
    const Vec2 from = exact_[line.i].point, to = exact_[line.j].point;
    const auto kept = [](double exact, double u, double v) { return u == v && (u == exact || exact != std::round(exact)); };
    return (from.x == to.x && !kept(from.x, a.x, b.x)) || (from.y == to.y && !kept(from.y, a.y, b.y));
  }

  // A corner at the line's end (`at_start`: node k the line's first) that a curve meets on its
  // other side moves that curve's handle along (RunPlacement::write) but not its far handle:
  // moved to `to`, the curve may bulge past an axis it ran along at the corner, an H/V
  // extremum its exact self lacks (Breip's M under G3: a corner 2 units over for the (1, −6)
  // step of its line, its curve leaving upright, bent right and back, x-extremum inside).
  // It costs what a curve meeting the line tangentially pays for one (far_handle_cost).
  double corner_curve_cost(std::size_t k, Vec2 to, bool at_start, double unseated) const {
    const std::size_t n = exact_.size();
    const std::optional<Vec2>& handle = at_start ? rounded_[k].in_handle : rounded_[k].out_handle;
    if (exact_[k].smooth || !handle) return 0.0;
    const std::size_t far = at_start ? previous(k) : (k + 1) % n;
    const std::optional<Vec2>& far_handle = at_start ? rounded_[far].out_handle : rounded_[far].in_handle;
    if (!far_handle) return 0.0;
    const Vec2 moved = *handle + (to - rounded_[k].point);
    const Cubic c = curve_at_line_end(to, moved, *far_handle, rounded_[far].point, at_start);
    return inner_axis_extrema(c) > exact_extrema_[at_start ? far : k] ? unseated + fold_unit : 0.0;
  }

  // Whether a line placed along `placed` turns from its exact direction by more than a node may
  // turn on the grid, or than its nearest grid points turn it (a 4-unit line of dkg Bold's n,
  // its ends moved two units each, stood across its stroke and the curve after it looped).
  bool turns_too_far(const LineOnGrid& line, Vec2 placed) const {
    const Vec2 from = exact_[line.i].point, to = exact_[line.j].point;
    const double nearest = std::abs(turning_angle(to - from, nearest_grid_point(to) - nearest_grid_point(from)));
    return std::abs(turning_angle(to - from, placed)) > std::max(most_line_turn, nearest);
  }

  // The curve meeting the line at `end` with its near handle `near` on the line: its far handle
  // (node k's out-handle when the curve arrives, its in-handle when it leaves) at the whole
  // step nearest the line (a corner's: the grid point of the line nearest it, where the handle
  // steps seat it; Delphine's l, whose curve so seated turned back to its vertical corner), or
  // where rounding put it; an H/V extremum's also from a unit across its axis (a unit more).
  // Its cost: how far that handle moves (three tenths), or `unseated` when even there the
  // curvature at the join stays visible; and that and four more where every
  // such handle gives the curve an H/V extremum its exact self lacks, so that a missing
  // extremum weighs more than a jump (a short curve bent back on itself by a handle of the
  // line's long step: Because We Build's M, a 2-unit curve from the bowl's foot to a (14, 1)
  // line; dkg Bold's n, a 9-unit curve between two near-vertical lines).
  double far_handle_cost(std::size_t k, bool out, Vec2 end, Vec2 near, Vec2 d, double unseated) const {
    const std::optional<Vec2> wanted = out ? exact_[k].out_handle : exact_[k].in_handle;
    const std::optional<Vec2> placed = out ? rounded_[k].out_handle : rounded_[k].in_handle;
    if (!wanted || !placed || (!steps_[k] && exact_[k].smooth)) return 0.0;
    const int extrema = exact_extrema_[out ? k : previous(k)];
    const double fold = unseated + fold_unit;
    double best = unseated + fold;
    // A far node whose tangent does not meet the line ahead of both the join and itself: no
    // handle seats the curve, which must bend both ways to leave one tangent for the other, an
    // S. Parallel to the line and off it (Caladea's z: a curve from its extremum down into a
    // line 2.1° off the level that would stand level 3 units under it); or, where the far node
    // is a line's end too (its tangent that line's, not a direction rounding may still turn),
    // crossing the line at the far node or behind either (Carlito's w: the line under its
    // middle apex slid to where it passed through the end of the line from the apex, and the
    // curve between took two inflections).
    const bool far_line = !(out ? exact_[k].in_handle : exact_[k].out_handle);
    const auto no_seat = [&](Vec2 far) {
      if (!steps_[k]) return false;
      const Vec2 step = out ? *steps_[k] * -1.0 : *steps_[k];
      return far_line ? !tangents_seat_handles(end, out ? d * -1.0 : d, far, step)
                      : cross(*steps_[k], d) == 0.0 && cross(d, far - end) != 0.0;
    };
    // A handle on the line reaching past the curve's far node along their chord folds the curve
    // back into it, whatever the far handle (Gentium Plus's M: one step of a (1, −111) leg, 2
    // units past a 91-unit curve's end, an S at its foot).
    const auto overshoots = [&](Vec2 far) { return dot(near - end, far - end) > dot(far - end, far - end); };
    const auto weigh = [&](Vec2 far, Vec2 h) {
      const Cubic c = curve_at_line_end(end, near, h, far, out);
      const double kappa = node_curvature(c, out ? SegmentEnd::end : SegmentEnd::start);
      const double seated = 0.3 * distance(h, *wanted) + distance(far, rounded_[k].point);
      const double cost = (std::abs(kappa) <= 0.05 * limits_.flat_curvature ? seated : unseated) +
                          (no_seat(far) || overshoots(far) || inner_axis_extrema(c) > extrema ? fold : 0.0);
      best = std::min(best, cost);
    };
    const Vec2 far = rounded_[k].point;
    if (steps_[k]) {
      for (const Vec2 h : handles_near_line(far, *steps_[k], out ? 1.0 : -1.0, end, d)) weigh(far, h);
      // An H/V extremum joining two cubics may also sit a unit across its axis, as the passes
      // after the lines seat it (node_seats' seat_line_joins), where both its cubics have half
      // a unit of allowance left (past that, only the band around the source may admit the
      // move). Its handle crosses a line of step (5, 8) at a whole step only every fifth unit
      // across: Gentium Plus's X, whose line was placed where its extremum had to move 2.4
      // units, and left κ·UPM 10.6 at the join. a–z A–Z rounded: g2-jumps EB Garamond 97 → 83,
      // Gentium Plus 9 → 7, Pagella 27 → 26, FreeSerif 6 → 7 (8 without the room: its w's
      // extremum could not follow; with a whole unit asked, EB Garamond kept 96).
      const Vec2 across{std::abs(steps_[k]->y), std::abs(steps_[k]->x)};
      const bool extremum = !far_line && (across.x == 0.0 || across.y == 0.0);
      if (extremum && std::min(limits_.allowance_at(k), limits_.allowance_at(previous(k))) >= 0.5)
        for (const Vec2 moved : {far - across, far + across})
          for (const Vec2 h : handles_near_line(moved, *steps_[k], out ? 1.0 : -1.0, end, d)) weigh(moved, h);
    } else if (const double m = whole_steps(end, *wanted, d, 1.0); m != 0.0) {
      weigh(far, end + d * m);  // not the join itself: no curve leaves from there
    }
    weigh(far, *placed);
    return best;
  }

  const std::vector<OutlineNode>& exact_;
  const std::vector<OutlineNode>& rounded_;
  const std::vector<std::optional<Vec2>>& steps_;
  const HandleStepLimits& limits_;
  std::vector<int> exact_extrema_;  ///< of the exact cubic from each node
};

// The runs of consecutive lines (each run's lines in order), split where a curve comes between.
std::vector<std::vector<LineOnGrid>> line_runs(const std::vector<OutlineNode>& exact, bool closed) {
  const std::size_t n = exact.size();
  const auto open_end = [&](std::size_t i) { return !closed && (i == 0 || i + 1 == n); };
  const auto is_line = [&](std::size_t i) {
    return (closed || i + 1 < n) && !exact[i].out_handle && !exact[(i + 1) % n].in_handle;
  };
  // Start where a run cannot continue from the node before: after a curve, or at an open start.
  std::size_t first = n;
  for (std::size_t i = 0; i < n && first == n; ++i)
    if (is_line(i) && (open_end(i) || !is_line((i + n - 1) % n))) first = i;
  std::vector<std::vector<LineOnGrid>> runs;
  if (first == n) return runs;  // no lines, or nothing but lines (no curve meets them)
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = (first + k) % n, j = (i + 1) % n;
    if (!is_line(i)) continue;
    const bool starts = runs.empty() || open_end(i) || !is_line((i + n - 1) % n);
    if (starts) runs.emplace_back();
    runs.back().push_back({i, j, exact[i].smooth && exact[i].in_handle && !open_end(i),
                           exact[j].smooth && exact[j].out_handle && !open_end(j)});
  }
  return runs;
}

// The places of a run's nodes (Viterbi over the run, least total cost); empty where every
// choice is degenerate.
std::vector<std::size_t> cheapest_places(const std::vector<LineOnGrid>& run, const std::vector<std::vector<EndPlace>>& places,
                                         const LinePlacer& placer) {
  std::vector<std::vector<double>> best(places.size());
  std::vector<std::vector<std::size_t>> from(places.size());
  best[0].assign(places[0].size(), 0.0);
  for (std::size_t t = 0; t < run.size(); ++t) {
    best[t + 1].assign(places[t + 1].size(), std::numeric_limits<double>::infinity());
    from[t + 1].assign(places[t + 1].size(), 0);
    for (std::size_t a = 0; a < places[t].size(); ++a)
      for (std::size_t b = 0; b < places[t + 1].size(); ++b) {
        const double bound = best[t + 1][b] - best[t][a];
        if (bound <= 0.0) continue;
        const double c = best[t][a] + placer.place(run[t], places[t][a], places[t + 1][b], bound).cost;
        if (c < best[t + 1][b]) best[t + 1][b] = c, from[t + 1][b] = a;
      }
  }
  const std::vector<double>& last = best.back();
  std::vector<std::size_t> chosen(places.size());
  chosen.back() = static_cast<std::size_t>(std::min_element(last.begin(), last.end()) - last.begin());
  if (!std::isfinite(last[chosen.back()])) return {};
  for (std::size_t t = places.size() - 1; t > 0; --t) chosen[t - 1] = from[t][chosen[t]];
  return chosen;
}

// One run of lines placed on the grid: first each end at its grid point or a neighbour; where
// a curve's handle on the line then strays, with the curves' ends sliding along their lines.
class RunPlacement {
 public:
  RunPlacement(const std::vector<OutlineNode>& exact, const std::vector<LineOnGrid>& run, const LinePlacer& placer,
               const HandleStepLimits& limits)
      : exact_(exact), run_(run), placer_(placer), limits_(limits) {}

  /// The cheapest placement with ends sliding or not; false (the placement as it was) where
  /// every choice is degenerate.
  bool choose(bool slides) {
    // A pinned node (fair/line_splits.hpp) stays where it is.
    const auto places_of = [&](std::size_t k, const std::optional<Slide>& slid) {
      if (exact_[k].pinned) return std::vector<EndPlace>{{exact_[k].point, 0.0}};
      return end_places(exact_[k].point, slid, room(k), limits_.any_grid_neighbour);
    };
    std::vector<std::vector<EndPlace>> places;
    places.push_back(places_of(run_.front().i, slides ? slide(run_.front(), true) : std::nullopt));
    for (const LineOnGrid& l : run_) places.push_back(places_of(l.j, slides ? slide(l, false) : std::nullopt));
    std::vector<std::size_t> chosen = cheapest_places(run_, places, placer_);
    if (chosen.empty()) return false;
    places_ = std::move(places), chosen_ = std::move(chosen);
    placed_.clear();
    for (std::size_t t = 0; t < run_.size(); ++t) placed_.push_back(placer_.place(run_[t], place(t), place(t + 1)));
    return true;
  }

  /// Whether a curve's handle on a line grows or shrinks by more than a quarter, and by more
  /// than its curve's allowance (on a line of long step: a handle slid along its own tangent
  /// moves the curve little, and only a long step can be made shorter by sliding) or to more
  /// than three quarters of its curve's chord (where a short curve folds, whatever the step).
  bool strays() const {
    const std::size_t n = exact_.size();
    const auto strays_at = [&](std::size_t node, bool in, double moved, std::size_t cubic, Vec2 at, Vec2 handle,
                               Vec2 step) {
      const Vec2 h = in ? *exact_[node].in_handle : *exact_[node].out_handle;
      if (moved <= stray_share * distance(h, exact_[node].point)) return false;
      const Cubic c = outline_cubic(exact_, cubic);
      return (norm(step) > short_step && moved > limits_.allowance_at(cubic)) ||
             distance(handle, at) > fold_share * distance(c.p[0], c.p[3]);
    };
    for (std::size_t t = 0; t < run_.size(); ++t) {
      const LineOnGrid& l = run_[t];
      const LinePlacement& p = placed_[t];
      if ((p.in_handle && strays_at(l.i, true, p.in_moved, (l.i + n - 1) % n, place(t).point, *p.in_handle, p.step)) ||
          (p.out_handle && strays_at(l.j, false, p.out_moved, l.j, place(t + 1).point, *p.out_handle, p.step)))
        return true;
    }
    return false;
  }

  /// The nodes as placed, and the lines' steps where a curve meets them.
  void write(std::vector<OutlineNode>& rounded, std::vector<std::optional<Vec2>>& steps) const {
    for (std::size_t t = 0; t < run_.size(); ++t) {
      const LineOnGrid& l = run_[t];
      const LinePlacement& p = placed_[t];
      // A corner moves its curve's handle with it, so the curve leaves it as before: an
      // extremum on it (cubic_writeback's snap: the handle along an axis) stays there, and a
      // curve leaving it just off an axis does not turn past it inside (Because We Connect's R:
      // its stem's line stood upright, its corner 3 units over, and the bowl's curve, its
      // handle left behind, left the corner leaning back, an x-extremum 7 units up).
      const auto move_node = [&](std::size_t k, Vec2 to) {
        const Vec2 by = to - rounded[k].point;
        if (!exact_[k].smooth) {
          if (rounded[k].in_handle) *rounded[k].in_handle = *rounded[k].in_handle + by;
          if (rounded[k].out_handle) *rounded[k].out_handle = *rounded[k].out_handle + by;
        }
        rounded[k].point = to;
      };
      move_node(l.i, place(t).point);
      move_node(l.j, place(t + 1).point);
      if (p.in_handle) rounded[l.i].in_handle = p.in_handle, steps[l.i] = p.step;
      if (p.out_handle) rounded[l.j].out_handle = p.out_handle, steps[l.j] = p.step;
    }
  }

 private:
  const EndPlace& place(std::size_t t) const { return places_[t][chosen_[t]]; }

  // How far node k may move: what both its segments have left of the tolerance.
  double room(std::size_t k) const {
    const std::size_t n = exact_.size();
    return std::min(limits_.allowance_at(k), limits_.allowance_at((k + n - 1) % n));
  }

  // A curve's end slides along its line, off it by no more than the line has left of the
  // tolerance.
  std::optional<Slide> slide(const LineOnGrid& l, bool arrives) const {
    if (!(arrives ? l.curve_arrives : l.curve_leaves)) return std::nullopt;
    const std::size_t n = exact_.size();
    const Cubic c = arrives ? outline_cubic(exact_, (l.i + n - 1) % n) : outline_cubic(exact_, l.j);
    const Cubic from_join = arrives ? c.reversed() : c;
    if (norm(from_join.p[1] - from_join.p[0]) == 0.0) return std::nullopt;
    const std::optional<Vec2> step =
        primitive_step(nearest_grid_point(exact_[l.j].point) - nearest_grid_point(exact_[l.i].point));
    return Slide(from_join, exact_[arrives ? l.j : l.i].point, step ? norm(*step) : 0.0,
                 std::min(off_line, limits_.allowance_at(l.i)));
  }

  const std::vector<OutlineNode>& exact_;
  const std::vector<LineOnGrid>& run_;
  const LinePlacer& placer_;
  const HandleStepLimits& limits_;
  std::vector<std::vector<EndPlace>> places_;
  std::vector<std::size_t> chosen_;
  std::vector<LinePlacement> placed_;
};

}  // namespace

void place_lines_on_grid(const std::vector<OutlineNode>& exact, std::vector<OutlineNode>& rounded,
                         std::vector<std::optional<Vec2>>& steps, bool closed, const HandleStepLimits& limits) {
  const LinePlacer placer(exact, rounded, steps, limits);
  for (const std::vector<LineOnGrid>& run : line_runs(exact, closed)) {
    if (std::none_of(run.begin(), run.end(), [](const LineOnGrid& l) { return l.curve_arrives || l.curve_leaves; })) continue;
    RunPlacement placement(exact, run, placer, limits);
    if (!placement.choose(false)) continue;  // every choice degenerate: keep the nearest grid points
    if (placement.strays()) placement.choose(true);
    placement.write(rounded, steps);
  }
}

}  // namespace gf
