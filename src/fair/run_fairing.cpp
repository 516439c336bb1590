#include "fair/run_fairing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <cstdlib>

#include "aesthetic/lcg_slope.hpp"
#include "fair/g2_chain.hpp"
#include "fair/initial_tangents.hpp"
#include "fair/junctions.hpp"
#include "fair/run_reference.hpp"
#include "geom/polyline_distance.hpp"

namespace gf {

namespace {

constexpr double default_alpha = 1.0;  // for arcs (every α fits) and pieces without a usable LCG
constexpr double alpha_candidates[] = {-2.0, -1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0};
constexpr int max_rounds = 10;

double angle_of(Vec2 v) { return std::atan2(v.y, v.x); }

double lcg_alpha(const RunReference& ref, double s0, double s1) {
  const std::vector<Cubic> cubics = ref.cubics_between(s0, s1);
  const std::vector<Segment> segments(cubics.begin(), cubics.end());
  const LcgSlope slope = estimate_lcg_slope(segments);
  return slope.kind == LcgSlope::Kind::slope ? std::clamp(slope.alpha, -2.0, 4.0) : default_alpha;
}

/// A chain over junctions first … last (indices into `junctions`, wrapping for a closed run).
struct ChainSpan {
  std::vector<double> s;  ///< arc lengths of its points (increasing; may pass L on a closed run)
  bool closed = false;
  bool zero_start = false, zero_end = false;
};

std::vector<ChainSpan> chain_spans(const std::vector<Junction>& junctions, const RunReference& ref, const SmoothRun& run) {
  std::vector<ChainSpan> spans;
  const double L = ref.length();
  if (ref.closed()) {
    std::size_t first = junctions.size();
    for (std::size_t i = 0; i < junctions.size(); ++i)
      if (junctions[i].kind == JunctionKind::inflection) {
        first = i;
        break;
      }
    if (first == junctions.size()) {
      ChainSpan c;
      c.closed = true;
      for (const Junction& j : junctions) c.s.push_back(j.s);
      spans.push_back(std::move(c));
      return spans;
    }
    const std::size_t n = junctions.size();
    ChainSpan c;
    for (std::size_t k = 0; k <= n; ++k) {
      const std::size_t i = (first + k) % n;
      const double s = junctions[i].s + (first + k >= n ? L : 0.0);
      c.s.push_back(s);
      if (k > 0 && junctions[i].kind == JunctionKind::inflection) {
        c.zero_start = c.zero_end = true;
        spans.push_back(c);
        c = ChainSpan{};
        c.s.push_back(s);
      }
    }
    return spans;
  }
  ChainSpan c;
  c.zero_start = run.start.kind == RunEndKind::line;
  for (std::size_t i = 0; i < junctions.size(); ++i) {
    c.s.push_back(junctions[i].s);
    const bool last = i + 1 == junctions.size();
    if (i > 0 && (last || junctions[i].kind == JunctionKind::inflection)) {
      c.zero_end = last ? run.end.kind == RunEndKind::line : true;
      spans.push_back(c);
      c = ChainSpan{};
      c.zero_start = true;
      c.s.push_back(junctions[i].s);
    }
  }
  return spans;
}

struct ChainOutcome {
  std::optional<FairedChain> chain;
  std::vector<double> cuts;   ///< arc lengths where the chain needs another junction
  std::vector<double> drops;  ///< junctions (by arc length) the chain cannot use
  double deviation = 0.0;
};

// Samples per segment so that the chords stay within 2 % of the tolerance of the curve.
int samples_for(const LogAestheticSegment& seg, double tolerance) {
  const double k = std::max({std::abs(seg.start().curvature), std::abs(seg.end().curvature), 1e-9});
  const double h = std::sqrt(8.0 * 0.02 * tolerance / k);
  return std::clamp(static_cast<int>(std::ceil(seg.length() / h)), 8, 400);
}

ChainOutcome fair_chain(const ChainSpan& span, const RunReference& ref, const SmoothRun& run, const FairSettings& settings,
                        double budget) {
  ChainOutcome out;
  const double L = ref.length(), w = settings.feature_window_units;
  LacChain chain;
  chain.closed = span.closed;
  chain.zero_curvature_start = span.zero_start;
  chain.zero_curvature_end = span.zero_end;
  const std::size_t points = span.s.size();
  for (std::size_t i = 0; i < points; ++i) chain.points.push_back(ref.mean_point(span.s[i], w));
  // A chain turns one way; a free junction that turns the other way (a wobble the window did
  // not average out) moves across its neighbours' chord, by little more than the wobble.
  const double way = span.closed ? ref.total_turning() : ref.theta_at(span.s.back()) - ref.theta_at(span.s.front());
  for (int pass = 0; pass < 3; ++pass)
    for (std::size_t i = 0; i < points; ++i) {
      if (!span.closed && (i == 0 || i + 1 == points)) continue;
      const Vec2 a = chain.points[(i + points - 1) % points], b = chain.points[(i + 1) % points];
      Vec2& q = chain.points[i];
      if (cross(q - a, b - q) * way > 0.0) continue;
      const Vec2 d = (b - a) / norm(b - a);
      const Vec2 foot = a + d * dot(q - a, d);
      // A left-turning chain bulges to the right of the chord between neighbours.
      const Vec2 moved = foot - perpendicular(d) * (way > 0.0 ? 1.0 : -1.0) * (0.01 * budget);
      if (std::getenv("GF_DEBUG")) fprintf(stderr, "convexify %zu way=%g move=%g\n", i, way, distance(moved, q));
      if (distance(moved, q) < 0.5 * budget) q = moved;
    }
  std::optional<double> start_angle, end_angle;
  if (!span.closed) {
    auto fixed = [&](double s) {
      if (!ref.closed() && s == 0.0) return angle_of(run.start.tangent);
      if (!ref.closed() && s == L) return angle_of(run.end.tangent);
      return angle_of(ref.mean_tangent(s, w));  // an inflection
    };
    start_angle = fixed(span.s.front());
    end_angle = fixed(span.s.back());
  }
  chain.tangent_angles = balanced_tangents(chain.points, chain.closed, start_angle, end_angle, span.zero_start, span.zero_end);
  const std::size_t segments = chain.segment_count();
  auto seg_end_s = [&](std::size_t i) { return i + 1 < points ? span.s[i + 1] : span.s[0] + L; };
  for (std::size_t i = 0; i < segments; ++i) chain.alphas.push_back(lcg_alpha(ref, span.s[i], seg_end_s(i)));

  // Every segment must exist before the solve. A κ = 0 end that the source's shape does not
  // allow (its curvature falls towards the end) becomes a free end: G1 there, not G2. Then
  // the nearest drawable α, else another junction.
  for (std::size_t i = 0; i < segments; ++i) {
    if (build_chain_segment(chain, i).ok()) continue;
    const bool zero_here = !chain.closed && ((i == 0 && chain.zero_curvature_start) ||
                                             (i + 1 == segments && chain.zero_curvature_end));
    if (zero_here) {
      LacChain released = chain;
      (i == 0 && chain.zero_curvature_start ? released.zero_curvature_start : released.zero_curvature_end) = false;
      if (build_chain_segment(released, i).ok()) {
        chain = std::move(released);
        continue;
      }
    }
    // An end tangent on the wrong side of the chord (a wobble merged into the piece): turn it
    // across, so that the piece is convex and splits its turning 2:3 between its ends.
    if (!chain.closed && (i == 0 || i + 1 == segments)) {
      LacChain turned = chain;
      if (i == 0) turned.zero_curvature_start = false;
      if (i + 1 == segments) turned.zero_curvature_end = false;
      const double c = angle_of(chain.points[i + 1] - chain.points[i]);
      const double a0 = std::remainder(chain.tangent_angles[i] - c, 2 * std::numbers::pi);
      const double a1 = std::remainder(chain.tangent_angles[i + 1] - c, 2 * std::numbers::pi);
      if (a0 * a1 >= 0.0) {
        if (i == 0) turned.tangent_angles[0] = c - (2.0 / 3.0) * a1;
        else turned.tangent_angles[i + 1] = c - (2.0 / 3.0) * a0;
        if (build_chain_segment(turned, i).ok()) {
          chain = std::move(turned);
          continue;
        }
      }
    }
    const double wanted = chain.alphas[i];
    std::vector<double> candidates(std::begin(alpha_candidates), std::end(alpha_candidates));
    std::sort(candidates.begin(), candidates.end(),
              [&](double a, double b) { return std::abs(a - wanted) < std::abs(b - wanted); });
    bool found = false;
    for (const double a : candidates) {
      chain.alphas[i] = a;
      if ((found = build_chain_segment(chain, i).ok())) break;
    }
    if (!found) {
      if (std::getenv("GF_DEBUG")) {
        const std::size_t j = (i + 1) % points;
        fprintf(stderr, "seg %zu/%zu s=%g..%g zero=%d%d closed=%d phi0=%g chord=%g phi1=%g: %s\n", i, segments, span.s[i], seg_end_s(i), chain.zero_curvature_start, chain.zero_curvature_end, chain.closed, chain.tangent_angles[i], angle_of(chain.points[j] - chain.points[i]), chain.tangent_angles[j], build_chain_segment(chain, i).reason.c_str());
      }
      chain.alphas[i] = wanted;
      // Junctions that do not turn one way (a wobble between them): drop one; cutting would
      // only make the pieces shorter and the wobble relatively larger.
      const std::size_t j = (i + 1) % points;
      const bool start_free = chain.closed || i > 0, end_free = chain.closed || j + 1 < points;
      if (!tangents_meet_in_front(chain, i) && (start_free || end_free)) out.drops.push_back(span.s[end_free ? j : i]);
      else out.cuts.push_back(0.5 * (span.s[i] + seg_end_s(i)));
    }
  }
  if (!out.cuts.empty() || !out.drops.empty()) return out;

  std::vector<LogAestheticSegment> built;
  double mismatch = 0.0;
  if (settings.continuity == Continuity::g2 && chain.free_junction_count() > 0) {
    const ChainSegments first = build_chain(chain);
    double scale = 0.0;
    for (const LogAestheticSegment& s : first.segments)
      scale = std::max({scale, std::abs(s.start().curvature), std::abs(s.end().curvature)});
    G2Result g2 = make_g2(chain, 1e-10 * scale);
    if (g2.segments.empty()) return out;
    built = std::move(g2.segments);
    mismatch = scale > 0.0 ? g2.max_mismatch / scale : 0.0;
    chain = std::move(g2.chain);
  } else {
    built = build_chain(chain).segments;
  }

  // Fidelity, piece by piece against the source between the same junctions.
  for (std::size_t i = 0; i < segments; ++i) {
    const LogAestheticSegment& seg = built[i];
    std::vector<Vec2> lac;
    if (std::getenv("GF_DEBUG")) fprintf(stderr, "sample seg a=%g L=%g len=%g turn=%g n=%d\n", seg.alpha(), seg.lambda(), seg.length(), seg.turning(), samples_for(seg, budget));
    for (const LacPoint& p : seg.sample(samples_for(seg, budget))) lac.push_back(p.point);
    const double s0 = span.s[i], s1 = seg_end_s(i);
    const std::vector<Vec2> src = ref.polyline(s0, s1);
    const double d = std::max(directed_hausdorff(lac, src).value, directed_hausdorff(src, lac).value);
    out.deviation = std::max(out.deviation, d);
    if (d > budget) out.cuts.push_back(0.5 * (s0 + s1));
  }
  if (!out.cuts.empty()) return out;
  FairedChain faired;
  faired.segments = std::move(built);
  faired.closed = chain.closed;
  faired.zero_curvature_start = chain.zero_curvature_start;
  faired.zero_curvature_end = chain.zero_curvature_end;
  faired.max_mismatch_relative = mismatch;
  out.chain = std::move(faired);
  return out;
}

}  // namespace

FairedRun fair_run(const SmoothRun& run, const FairSettings& settings, double budget) {
  FairedRun result;
  const RunReference ref(run);
  const double L = ref.length();
  std::vector<Junction> junctions = select_junctions(ref, !run.closed && run.start.kind == RunEndKind::line,
                                                     !run.closed && run.end.kind == RunEndKind::line,
                                                     junction_options(settings));
  for (int round = 0; round < max_rounds; ++round) {
    std::vector<double> cuts, drops;
    result.chains.clear();
    result.deviation = 0.0;
    for (const ChainSpan& span : chain_spans(junctions, ref, run)) {
      ChainOutcome o = fair_chain(span, ref, run, settings, budget);
      result.deviation = std::max(result.deviation, o.deviation);
      if (o.chain) result.chains.push_back(std::move(*o.chain));
      else if (o.cuts.empty() && o.drops.empty()) {
        result.reason = "no feasible G2 chain";
        return result;
      }
      for (const double c : o.cuts) cuts.push_back(ref.closed() ? std::fmod(c, L) : c);
      for (const double d : o.drops) drops.push_back(ref.closed() ? std::fmod(d, L) : d);
    }
    for (const double d : drops)
      std::erase_if(junctions, [&](const Junction& j) { return std::abs(j.s - d) < 1e-9; });
    if (cuts.empty() && drops.empty()) {
      result.ok = true;
      return result;
    }
    for (const double c : cuts) junctions.push_back({c, JunctionKind::split});
    std::sort(junctions.begin(), junctions.end(), [](const Junction& a, const Junction& b) { return a.s < b.s; });
  }
  result.reason = "still " + std::to_string(result.deviation) + " units from the source after " +
                  std::to_string(max_rounds) + " rounds of refinement";
  return result;
}

}  // namespace gf
