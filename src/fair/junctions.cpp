#include "fair/junctions.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gf {

namespace {

struct Lobe {
  std::size_t first, last;  ///< grid indices, inclusive (last may exceed the grid size on a closed run: wrap)
  double sign;
  double sagitta;
};

// The largest distance of the grid points first … last from the chord between them.
double sagitta_of(const std::vector<Vec2>& pts, std::size_t first, std::size_t last) {
  const std::size_t n = pts.size();
  const Vec2 a = pts[first % n], b = pts[last % n];
  const Vec2 d = b - a;
  const double len = norm(d);
  double m = 0.0;
  for (std::size_t k = first; k <= last; ++k) {
    const Vec2 r = pts[k % n] - a;
    m = std::max(m, len > 0.0 ? std::abs(cross(d, r)) / len : norm(r));
  }
  return m;
}

// Interior extrema of f over grid indices first … last, simplified by persistence: adjacent
// max/min pairs whose difference is below `threshold` are removed, smallest first. The ends
// take part with their values but are never reported.
std::vector<std::size_t> prominent_extrema(const std::vector<double>& f, std::size_t first, std::size_t last,
                                           double threshold) {
  const std::size_t n = f.size();
  auto at = [&](std::size_t k) { return f[k % n]; };
  std::vector<std::size_t> ext{first};
  double direction = 0.0;  // sign of the last non-zero step; a reversal marks an extremum
  std::size_t candidate = first;
  for (std::size_t k = first; k < last; ++k) {
    const double step = at(k + 1) - at(k);
    if (step == 0.0) continue;
    if (direction != 0.0 && (step > 0.0) != (direction > 0.0)) ext.push_back(candidate);
    direction = step;
    candidate = k + 1;
  }
  ext.push_back(last);
  while (ext.size() > 2) {
    std::size_t best = 0;
    double smallest = threshold;
    for (std::size_t i = 1; i < ext.size(); ++i) {
      const double step = std::abs(at(ext[i]) - at(ext[i - 1]));
      if (step < smallest) smallest = step, best = i;
    }
    if (best == 0) break;
    const auto it = ext.begin() + static_cast<std::ptrdiff_t>(best);
    if (best == 1) ext.erase(it);
    else if (best + 1 == ext.size()) ext.erase(it - 1);
    else ext.erase(it - 1, it + 1);
  }
  return {ext.begin() + 1, ext.end() - 1};
}

// An arc between two lines (select_junctions): turning at least this far, and meeting its
// lines with at least this share of its peak curvature.
constexpr double arc_min_turning_rad = 2.0, arc_min_end_share = 0.65;

// Where θ first reaches the share `part` of its turning from a to b (a < b, wrapping past a
// closed run's length).
double where_turned(const RunReference& run, double a, double b, double part) {
  const double turning = run.theta_at(b) - run.theta_at(a), target = run.theta_at(a) + turning * part;
  double lo = a, hi = b;
  for (int it = 0; it < 50; ++it) {
    const double mid = 0.5 * (lo + hi);
    ((run.theta_at(mid) - target) * turning < 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Split junctions inserted where a piece turns by more than `max_turning`, evenly in θ.
std::vector<Junction> cap_turning(std::vector<Junction> out, const RunReference& run, double max_turning) {
  const double L = run.length();
  const bool closed = run.closed();
  if (closed && out.empty()) out.push_back({0.0, JunctionKind::split});
  std::vector<Junction> capped;
  const std::size_t m = out.size();
  for (std::size_t i = 0; i < (closed ? m : m - 1); ++i) {
    const double a = out[i].s, b = i + 1 < m ? out[i + 1].s : out[0].s + L;
    capped.push_back(out[i]);
    const double turning = run.theta_at(b) - run.theta_at(a);
    const int parts = static_cast<int>(std::ceil(std::abs(turning) / max_turning - 1e-9));
    for (int p = 1; p < parts; ++p) {
      const double at = where_turned(run, a, b, static_cast<double>(p) / parts);
      capped.push_back({closed ? std::fmod(at, L) : at, JunctionKind::split});
    }
  }
  if (!closed) capped.push_back(out.back());
  std::sort(capped.begin(), capped.end(), earlier);
  return capped;
}

// Junctions (sorted) closer than `gap` are one; the stronger kind stays (the enum's order).
std::vector<Junction> merge_close(const std::vector<Junction>& sorted, double L, bool closed, double gap) {
  std::vector<Junction> distinct;
  for (const Junction& j : sorted) {
    if (!distinct.empty() && j.s - distinct.back().s < gap) {
      if (j.kind < distinct.back().kind) distinct.back() = j;
      continue;
    }
    distinct.push_back(j);
  }
  if (closed && distinct.size() > 1 && distinct.front().s + L - distinct.back().s < gap) {
    if (distinct.back().kind < distinct.front().kind) distinct.front() = distinct.back();
    distinct.pop_back();
  }
  return distinct;
}

}  // namespace

JunctionOptions junction_options(const FairSettings& settings) {
  const bool hand = settings.profile == FairProfile::handwriting;
  return {settings.feature_window_units, settings.tolerance_units, hand ? 0.35 : 0.15, std::numbers::pi / 2};
}

std::vector<Junction> select_junctions(const RunReference& run, bool zero_curvature_start, bool zero_curvature_end,
                                       const JunctionOptions& options) {
  const double L = run.length();
  const bool closed = run.closed();
  const std::size_t grid = std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(4.0 * L / options.window_units)), 16, 4000);
  const std::size_t count = closed ? grid : grid + 1;
  const double h = L / static_cast<double>(grid);
  std::vector<double> kappa(count);
  std::vector<Vec2> pts(count);
  for (std::size_t k = 0; k < count; ++k) {
    kappa[k] = run.mean_curvature(static_cast<double>(k) * h, options.window_units);
    pts[k] = run.point_at(static_cast<double>(k) * h);
  }

  // Lobes of constant sign (zeros join the lobe before them).
  std::vector<Lobe> lobes;
  std::size_t start = 0;
  if (closed) {  // start the walk at a sign change so that no lobe spans the seam
    for (std::size_t k = 0; k < count; ++k)
      if (kappa[k] * kappa[(k + 1) % count] < 0.0) {
        start = k + 1;
        break;
      }
  }
  const std::size_t end = closed ? start + count : count;  // exclusive; indices wrap
  auto sign_of = [&](std::size_t k) { return kappa[k % count] >= 0.0 ? 1.0 : -1.0; };
  for (std::size_t k = start; k < end; ++k) {
    if (lobes.empty() || (sign_of(k) != lobes.back().sign && kappa[k % count] != 0.0)) {
      if (!lobes.empty()) lobes.back().last = k;
      lobes.push_back({k, end - 1, sign_of(k), 0.0});
    }
  }
  if (closed && lobes.size() > 1) lobes.back().last = start + count;  // back to the first lobe's start
  for (Lobe& l : lobes) l.sagitta = sagitta_of(pts, l.first, l.last);

  // Merge wobbles: the least significant lobe first, while one stays within half the tolerance.
  while (lobes.size() > 1) {
    std::size_t weakest = 0;
    for (std::size_t i = 1; i < lobes.size(); ++i)
      if (lobes[i].sagitta < lobes[weakest].sagitta) weakest = i;
    if (lobes[weakest].sagitta >= 0.5 * options.tolerance_units) break;
    const std::size_t n = lobes.size();
    const bool has_prev = closed || weakest > 0, has_next = closed || weakest + 1 < n;
    const std::size_t prev = (weakest + n - 1) % n, next = (weakest + 1) % n;
    Lobe merged = lobes[weakest];
    if (has_prev) merged.first = lobes[prev].first, merged.sign = lobes[prev].sign;
    if (has_next) merged.last = lobes[next].last, merged.sign = lobes[next].sign;
    if (closed && n == 2) {  // the whole loop turns one way
      lobes = {Lobe{start, start + count, lobes[(weakest + 1) % 2].sign, 0.0}};
      break;
    }
    if (closed && (next < weakest || prev > weakest)) merged.last = lobes[next].last + count;  // across the seam
    merged.sagitta = sagitta_of(pts, merged.first, merged.last);  // the other lobes are as they were
    // Erase prev, weakest, next and insert the merge where prev was.
    std::vector<Lobe> rest;
    for (std::size_t i = 0; i < n; ++i) {
      const bool gone = i == weakest || (has_prev && i == prev) || (has_next && i == next);
      if (i == (has_prev ? prev : weakest)) rest.push_back(merged);
      else if (!gone) rest.push_back(lobes[i]);
    }
    std::sort(rest.begin(), rest.end(), [](const Lobe& a, const Lobe& b) { return a.first < b.first; });
    lobes = std::move(rest);
  }

  std::vector<Junction> out;
  auto s_of = [&](std::size_t k) { return static_cast<double>(k) * h; };
  if (!closed) out.push_back({0.0, JunctionKind::run_end});
  const bool single_closed_lobe = closed && lobes.size() == 1;
  for (std::size_t i = 0; i < lobes.size(); ++i) {
    const Lobe& l = lobes[i];
    if (i > 0 || (closed && !single_closed_lobe)) out.push_back({s_of(l.first), JunctionKind::inflection});
    // Curvature extrema, as |κ| within the lobe; zero-curvature ends take part as 0.
    std::vector<double> f(count);
    for (std::size_t k = 0; k < count; ++k) f[k] = l.sign * kappa[k];
    const bool zero_first = i > 0 || (closed && !single_closed_lobe) || (!closed && zero_curvature_start);
    const bool zero_last = i + 1 < lobes.size() || (closed && !single_closed_lobe) || (!closed && zero_curvature_end);
    double peak = 0.0;
    std::size_t peak_at = l.first;
    for (std::size_t k = l.first; k <= l.last; ++k)
      if (f[k % count] > peak) peak = f[k % count], peak_at = k;
    if (zero_first && zero_last) {
      // A lobe between two κ = 0 ends turning through much of a half turn and meeting them
      // with nearly its peak curvature is an arc the source drew without transitions (a round
      // stroke end, Comic Neue's; its curvature wobbles about the mean where it is drawn as
      // cubics): cut where it has turned a quarter, half and three quarters of the way, two
      // transitions and two halves of the arc, each κ = 0 end with a free junction of its own.
      // With `arcs_by_turning`, every lobe between κ = 0 ends that turns as far.
      const double a = s_of(l.first), b = s_of(l.last);
      const double turning = std::abs(run.theta_at(b) - run.theta_at(a));
      const double ends = std::min(f[l.first % count], f[l.last % count]);
      if (turning >= arc_min_turning_rad && (options.arcs_by_turning || ends >= arc_min_end_share * peak)) {
        for (const double part : {0.25, 0.5, 0.75})
          out.push_back({where_turned(run, a, b, part), part == 0.5 ? JunctionKind::extremum : JunctionKind::split});
        continue;
      }
      if (peak_at > l.first && peak_at < l.last) out.push_back({s_of(peak_at), JunctionKind::extremum});
      continue;
    }
    std::vector<double> g = f;
    if (zero_first) g[l.first % count] = 0.0;
    if (zero_last) g[l.last % count] = 0.0;
    const std::size_t last = single_closed_lobe ? l.first + count : l.last;
    for (const std::size_t k : prominent_extrema(g, l.first, last, options.extremum_prominence * peak))
      out.push_back({s_of(k), JunctionKind::extremum});
  }
  if (!closed) out.push_back({L, JunctionKind::run_end});
  for (Junction& j : out) j.s = closed ? std::fmod(j.s, L) : j.s;
  std::sort(out.begin(), out.end(), earlier);

  return merge_close(cap_turning(out, run, options.max_turning_rad), L, closed, 0.25 * options.window_units);
}

}  // namespace gf
