#include "fair/g3_cubics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include <Eigen/Dense>

#include "fair/cubic_change.hpp"
#include "geom/curvature.hpp"
#include "geom/foot_point.hpp"

namespace gf {
namespace {

// Samples per cubic for the distance rows, and for the allowance check.
constexpr int fit_samples = 10;
constexpr int check_samples = 24;
// Weights of the rows: κ held (relative to the turning over a chord), dκ/ds asked for more
// and more strongly, node moves damped a little so a node the curve cannot see stays put.
constexpr double curvature_weight = 1e4;
constexpr double node_move_weight = 0.01;
constexpr double slope_weights[] = {1.0, 100.0, 1e4};
// A run counts as G3 when every dκ/ds jump is under this, relative to the larger side.
constexpr double g3_relative = 1e-4;
// How much more a cubic may turn than the one it replaces: less than a loop or cusp adds.
constexpr double fold_turn = 0.25;
// How short a handle may get against the one it replaces: a handle drawn back to its node
// leaves a cusp's curvature there.
constexpr double shortest_handle_share = 0.1;

bool has_cubic(const std::vector<OutlineNode>& nodes, bool closed, std::size_t i) {
  const std::size_t n = nodes.size();
  if (i + 1 == n && !closed) return false;
  return nodes[i].out_handle && nodes[(i + 1) % n].in_handle;
}

// A run of cubics: node indices along the contour; cubic k joins nodes[k] and nodes[k + 1]
// (a closed run's last cubic returns to nodes[0]).
struct CubicRun {
  std::vector<std::size_t> nodes;
  bool closed = false;
  std::size_t cubic_count() const { return closed ? nodes.size() : nodes.size() - 1; }
};

std::vector<CubicRun> smooth_runs(const std::vector<OutlineNode>& nodes, bool closed) {
  const std::size_t n = nodes.size();
  std::vector<CubicRun> out;
  if (n < 2) return out;
  std::vector<bool> inner(n);
  for (std::size_t i = 0; i < n; ++i)
    inner[i] = (closed || i > 0) && nodes[i].smooth && has_cubic(nodes, closed, i) &&
               has_cubic(nodes, closed, (i + n - 1) % n);
  if (closed && std::all_of(inner.begin(), inner.end(), [](bool b) { return b; })) {
    CubicRun run{{}, true};
    for (std::size_t i = 0; i < n; ++i) run.nodes.push_back(i);
    out.push_back(std::move(run));
    return out;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (inner[i] || !has_cubic(nodes, closed, i)) continue;
    CubicRun run;
    std::size_t j = i;
    run.nodes.push_back(j);
    do {
      j = (j + 1) % n;
      run.nodes.push_back(j);
    } while (inner[j]);
    if (run.nodes.size() >= 3) out.push_back(std::move(run));
  }
  return out;
}

// The far handle's length that puts it on a flat end's tangent line: `reach` how far the far
// node lies across that line, `turn` the sine between the two tangents. Not finite (a cubic no
// step takes) where it would reach backwards or the tangents run nearly parallel.
double flat_handle(double reach, double turn) {
  if (std::abs(turn) < 1e-3) return std::numeric_limits<double>::quiet_NaN();
  const double h = reach / turn;
  return h > 0.0 ? h : std::numeric_limits<double>::quiet_NaN();
}

struct NodeFrame {
  Vec2 point;
  double angle = 0.0;
  bool movable = false, turnable = false;
  bool flat = false;  // κ held at 0: an inflection, or a line join at a run's end
  // At a corner ending the run, κ held (left free, the cubic from DejaVu's c's stroke end
  // turned S-shaped).
  double end_curvature = 0.0;
};

// One run's problem, in the unknowns x: each movable node's offset (2) and, if turnable, its
// turn (1); then each cubic's log handle lengths (2).
struct RunProblem {
  std::vector<Cubic> targets;
  std::vector<double> allowance;
  std::vector<NodeFrame> frames;
  bool closed = false;
  std::vector<int> offset_at, turn_at;  // index into x per node, −1 where fixed
  int handles_at = 0;

  std::size_t cubic_count() const { return targets.size(); }
  std::size_t end_node(std::size_t k) const { return closed ? (k + 1) % frames.size() : k + 1; }

  /// Numbers the unknowns and the rows, from the frames as they stand.
  void index() {
    offset_at.assign(frames.size(), -1), turn_at.assign(frames.size(), -1);
    int count = 0;
    for (std::size_t j = 0; j < frames.size(); ++j) {
      if (!frames[j].movable) continue;
      offset_at[j] = count, count += 2;
      if (frames[j].turnable) turn_at[j] = count++;
    }
    handles_at = count;
    node_of_unknown.assign(static_cast<std::size_t>(count), 0);
    for (std::size_t j = 0; j < frames.size(); ++j) {
      if (offset_at[j] >= 0) node_of_unknown[static_cast<std::size_t>(offset_at[j])] = node_of_unknown[static_cast<std::size_t>(offset_at[j]) + 1] = j;
      if (turn_at[j] >= 0) node_of_unknown[static_cast<std::size_t>(turn_at[j])] = j;
    }
    move_first_row = cubic_count() * fit_samples;
    row_count = move_first_row;
    move_row_of_unknown.assign(static_cast<std::size_t>(count), -1);
    for (std::size_t j = 0; j < frames.size(); ++j)
      if (offset_at[j] >= 0)
        for (int axis = 0; axis < 2; ++axis) move_row_of_unknown[static_cast<std::size_t>(offset_at[j] + axis)] = static_cast<int>(row_count++);
    node_first_row.assign(frames.size(), 0), node_row_count.assign(frames.size(), 0);
    for (std::size_t j = 0; j < frames.size(); ++j) {
      node_first_row[j] = row_count;
      node_row_count[j] = (frames[j].flat ? 0 : 1) + (inner(j) ? 1 : 0);
      row_count += static_cast<std::size_t>(node_row_count[j]);
    }
  }

  /// The unknowns where the targets stand: no moves or turns, their handles' lengths.
  Eigen::VectorXd initial() const {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(handles_at + 2 * static_cast<int>(cubic_count()));
    for (std::size_t k = 0; k < cubic_count(); ++k) {
      const Cubic& c = targets[k];
      x[handles_at + 2 * static_cast<int>(k)] = std::log(distance(c.p[0], c.p[1]));
      x[handles_at + 2 * static_cast<int>(k) + 1] = std::log(distance(c.p[3], c.p[2]));
    }
    return x;
  }

  Vec2 point(const Eigen::VectorXd& x, std::size_t j) const {
    const int o = offset_at[j];
    return o < 0 ? frames[j].point : frames[j].point + Vec2{x[o], x[o + 1]};
  }
  Vec2 tangent(const Eigen::VectorXd& x, std::size_t j) const {
    const int r = turn_at[j];
    return direction_of(frames[j].angle + (r < 0 ? 0.0 : x[r]));
  }

  Cubic cubic(const Eigen::VectorXd& x, std::size_t k) const {
    const std::size_t j0 = k, j1 = end_node(k);
    const Vec2 p0 = point(x, j0), p3 = point(x, j1), u0 = tangent(x, j0), u3 = tangent(x, j1);
    double a = std::exp(x[handles_at + 2 * static_cast<int>(k)]);
    double b = std::exp(x[handles_at + 2 * static_cast<int>(k) + 1]);
    // κ = 0 at a flat end exactly: the far handle on that end's tangent line.
    if (frames[j0].flat) b = flat_handle(cross(u0, p3 - p0), cross(u0, u3));
    if (frames[j1].flat) a = flat_handle(cross(u3, p3 - p0), cross(u3, u0));
    return Cubic{p0, p0 + u0 * a, p3 - u3 * b, p3};
  }

  std::vector<Cubic> cubics(const Eigen::VectorXd& x) const {
    std::vector<Cubic> out(cubic_count());
    for (std::size_t k = 0; k < cubic_count(); ++k) out[k] = cubic(x, k);
    return out;
  }

  /// The cubics an unknown moves: those of its node, or the one whose handle it is.
  std::array<std::optional<std::size_t>, 2> cubics_moved_by(int unknown) const {
    if (unknown >= handles_at) return {static_cast<std::size_t>((unknown - handles_at) / 2), std::nullopt};
    const std::size_t j = node_of_unknown[static_cast<std::size_t>(unknown)], m = cubic_count();
    std::array<std::optional<std::size_t>, 2> out;
    if (closed || j > 0) out[0] = (j + m - 1) % m;
    if (closed || j < m) out[1] = j % m;
    return out;
  }

  std::vector<std::size_t> node_of_unknown;
  std::vector<int> move_row_of_unknown;  // a node offset's damping row, −1 for a turn

  // The rows, in order: fit_samples distances per cubic, two per movable node's move, then
  // each node's conditions (node_row_count[j] of them from node_first_row[j]).
  std::size_t move_first_row = 0, row_count = 0;
  std::vector<std::size_t> node_first_row;
  std::vector<int> node_row_count;

  bool inner(std::size_t j) const { return closed || (j > 0 && j + 1 < frames.size()); }
};

// Where a sample of the new cubic falls on the run's targets, and the target's normal there.
struct Foot {
  std::size_t target = 0;
  double t = 0.5;
  Vec2 point, normal;
};

// The foot of p on the targets, by Newton from `foot`, passing to the neighbouring target
// where t leaves [0, 1].
void settle_foot(const RunProblem& problem, Vec2 p, Foot& foot) {
  const std::size_t m = problem.cubic_count();
  for (int iteration = 0; iteration < 12; ++iteration) {
    const Cubic& c = problem.targets[foot.target];
    const FootStep step = foot_step(c, p, foot.t);
    if (step.slope <= 0.0) break;
    double t = foot.t - step.along / step.slope;
    if (t < 0.0 && (foot.target > 0 || problem.closed) && iteration < 10) {
      foot.target = (foot.target + m - 1) % m, foot.t = 1.0;
      continue;
    }
    if (t > 1.0 && (foot.target + 1 < m || problem.closed) && iteration < 10) {
      foot.target = (foot.target + 1) % m, foot.t = 0.0;
      continue;
    }
    t = std::clamp(t, 0.0, 1.0);
    const bool done = std::abs(t - foot.t) < 1e-12;
    foot.t = t;
    if (done) break;
  }
  const Cubic& c = problem.targets[foot.target];
  foot.point = c.point_at(foot.t);
  const Vec2 d = c.hodograph().point_at(foot.t);
  const double speed = norm(d);
  foot.normal = speed > 0.0 ? perpendicular(d / speed) : Vec2{};
}

double sample_t(int s, int count) { return (s + 0.5) / count; }

struct EndData {
  double kappa = 0.0, slope = 0.0;
};
EndData end_data(const Cubic& c, SegmentEnd end) {
  const EndCurvature e = end_curvature(Segment(c), end);
  return {e.curvature.value_or(0.0), e.curvature_derivative.value_or(0.0)};
}

// Cubic k's distance rows: its samples' offsets along the targets' normals at their feet.
void distance_rows(const Cubic& c, std::size_t k, const std::vector<Foot>& feet, Eigen::VectorXd& r) {
  for (int s = 0; s < fit_samples; ++s) {
    const std::size_t row = k * fit_samples + static_cast<std::size_t>(s);
    r[static_cast<Eigen::Index>(row)] = dot(c.point_at(sample_t(s, fit_samples)) - feet[row].point, feet[row].normal);
  }
}

// Node j's condition rows: at an inner node κ continuous (none at an inflection, whose κ = 0 is
// exact by construction) and dκ/ds, weighed; at a run's end, a corner's κ held.
void node_rows(const RunProblem& problem, const std::vector<Cubic>& cubics, std::size_t j, double slope_weight,
               Eigen::VectorXd& r) {
  if (problem.node_row_count[j] == 0) return;
  const std::size_t m = cubics.size();
  auto row = static_cast<Eigen::Index>(problem.node_first_row[j]);
  const auto chord = [&](std::size_t k) { return distance(cubics[k].p[0], cubics[k].p[3]); };
  if (!problem.inner(j)) {
    const std::size_t k = j == 0 ? 0 : m - 1;
    const double kappa = end_data(cubics[k], j == 0 ? SegmentEnd::start : SegmentEnd::end).kappa;
    r[row] = curvature_weight * (kappa - problem.frames[j].end_curvature) * chord(k);
    return;
  }
  const std::size_t into = (j + m - 1) % m, out_of = j % m;
  const double h = 0.5 * (chord(into) + chord(out_of));
  const EndData a = end_data(cubics[into], SegmentEnd::end), b = end_data(cubics[out_of], SegmentEnd::start);
  if (!problem.frames[j].flat) r[row++] = curvature_weight * (a.kappa - b.kappa) * h;
  r[row] = slope_weight * (a.slope - b.slope) * h * h;
}

// Every row at x (RunProblem's order), the distances through the feet as they stand.
Eigen::VectorXd rows(const RunProblem& problem, const Eigen::VectorXd& x, const std::vector<Cubic>& cubics,
                     const std::vector<Foot>& feet, double slope_weight) {
  Eigen::VectorXd r(static_cast<Eigen::Index>(problem.row_count));
  for (std::size_t k = 0; k < cubics.size(); ++k) distance_rows(cubics[k], k, feet, r);
  for (std::size_t u = 0; u < problem.move_row_of_unknown.size(); ++u)
    if (const int row = problem.move_row_of_unknown[u]; row >= 0) r[row] = node_move_weight * x[static_cast<Eigen::Index>(u)];
  for (std::size_t j = 0; j < problem.frames.size(); ++j) node_rows(problem, cubics, j, slope_weight, r);
  return r;
}

// J by forward differences, each column from the one or two cubics its unknown moves: their
// distance rows and the conditions at their ends.
Eigen::MatrixXd jacobian(const RunProblem& problem, const Eigen::VectorXd& x, const std::vector<Cubic>& cubics,
                         const Eigen::VectorXd& f, const std::vector<Foot>& feet, double slope_weight) {
  Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(f.size(), x.size());
  std::vector<Cubic> moved_cubics = cubics;
  Eigen::VectorXd moved_rows = f;
  Eigen::VectorXd moved = x;
  for (Eigen::Index c = 0; c < x.size(); ++c) {
    const double h = 1e-7 * std::max(1.0, std::abs(x[c]));
    moved[c] = x[c] + h;
    const auto affected = problem.cubics_moved_by(static_cast<int>(c));
    for (const auto& k : affected)
      if (k) moved_cubics[*k] = problem.cubic(moved, *k);
    for (const auto& k : affected) {
      if (!k) continue;
      distance_rows(moved_cubics[*k], *k, feet, moved_rows);
      node_rows(problem, moved_cubics, *k, slope_weight, moved_rows);
      node_rows(problem, moved_cubics, problem.end_node(*k), slope_weight, moved_rows);
    }
    moved[c] = x[c];
    jac.col(c) = (moved_rows - f) / h;
    if (c < problem.handles_at)
      if (const int row = problem.move_row_of_unknown[static_cast<std::size_t>(c)]; row >= 0) jac(row, c) = node_move_weight;
    for (const auto& k : affected) {
      if (!k) continue;
      moved_cubics[*k] = cubics[*k];
      distance_rows(cubics[*k], *k, feet, moved_rows);
      node_rows(problem, cubics, *k, slope_weight, moved_rows);
      node_rows(problem, cubics, problem.end_node(*k), slope_weight, moved_rows);
    }
  }
  return jac;
}

std::vector<Foot> initial_feet(const RunProblem& problem) {
  std::vector<Foot> feet;
  for (std::size_t k = 0; k < problem.cubic_count(); ++k)
    for (int s = 0; s < fit_samples; ++s) {
      Foot f{k, sample_t(s, fit_samples), {}, {}};
      settle_foot(problem, problem.targets[k].point_at(f.t), f);
      feet.push_back(f);
    }
  return feet;
}

void settle_feet(const RunProblem& problem, const std::vector<Cubic>& cubics, std::vector<Foot>& feet) {
  for (std::size_t k = 0; k < cubics.size(); ++k)
    for (int s = 0; s < fit_samples; ++s)
      settle_foot(problem, cubics[k].point_at(sample_t(s, fit_samples)), feet[k * fit_samples + static_cast<std::size_t>(s)]);
}

// Levenberg–Marquardt on the rows at one weight of dκ/ds; the feet follow every step taken.
void least_squares(const RunProblem& problem, Eigen::VectorXd& x, std::vector<Foot>& feet, double slope_weight) {
  std::vector<Cubic> cubics = problem.cubics(x);
  Eigen::VectorXd f = rows(problem, x, cubics, feet, slope_weight);
  double damping = 1e-3;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const Eigen::MatrixXd jac = jacobian(problem, x, cubics, f, feet, slope_weight);
    const Eigen::MatrixXd normal = jac.transpose() * jac;
    const Eigen::VectorXd gradient = jac.transpose() * f;
    bool taken = false;
    while (damping < 1e12) {
      Eigen::MatrixXd lhs = normal;
      lhs.diagonal() += damping * (normal.diagonal().array() + 1e-12).matrix();
      const Eigen::VectorXd step = lhs.ldlt().solve(-gradient);
      if (!step.allFinite()) {
        damping *= 4.0;
        continue;
      }
      Eigen::VectorXd trial = x + step;
      std::vector<Cubic> trial_cubics = problem.cubics(trial);
      std::vector<Foot> trial_feet = feet;
      settle_feet(problem, trial_cubics, trial_feet);
      const Eigen::VectorXd ft = rows(problem, trial, trial_cubics, trial_feet, slope_weight);
      if (ft.allFinite() && ft.squaredNorm() < f.squaredNorm()) {
        const bool small = f.squaredNorm() - ft.squaredNorm() < 1e-12 * f.squaredNorm();
        x = std::move(trial), cubics = std::move(trial_cubics), feet = std::move(trial_feet), f = ft;
        damping = std::max(damping / 3.0, 1e-9);
        taken = true;
        if (small) return;
        break;
      }
      damping *= 4.0;
    }
    if (!taken) return;
  }
}

// How far each cubic lies from the targets at its worst, over its allowance.
std::vector<double> overreach(const RunProblem& problem, const std::vector<Cubic>& cubics) {
  std::vector<double> out(cubics.size());
  for (std::size_t k = 0; k < cubics.size(); ++k) {
    double worst = 0.0;
    Foot f{k, 0.0, {}, {}};
    for (int s = 0; s <= check_samples; ++s) {
      const Vec2 p = cubics[k].point_at(double(s) / check_samples);
      f.t = double(s) / check_samples, f.target = k;
      settle_foot(problem, p, f);
      worst = std::max(worst, distance(p, f.point));
    }
    out[k] = worst / std::max(problem.allowance[k], 1e-9);
  }
  return out;
}

bool finite(const Cubic& c) {
  return std::all_of(c.p.begin(), c.p.end(), [](Vec2 q) { return std::isfinite(q.x) && std::isfinite(q.y); });
}

// Within every allowance, and no cubic bends more ways than the one it replaces, turns
// horizontal or vertical inside, folds into a loop or cusp, or reaches past its chord.
// `over`: overreach(problem, cubics).
bool acceptable(const RunProblem& problem, const std::vector<Cubic>& cubics, const std::vector<double>& over) {
  if (!std::all_of(cubics.begin(), cubics.end(), finite)) return false;
  if (!(*std::max_element(over.begin(), over.end()) <= 1.0)) return false;
  for (std::size_t k = 0; k < cubics.size(); ++k) {
    const Cubic &now = cubics[k], &was = problem.targets[k];
    if (curvature_shape(now, 0.0).sign_changes > curvature_shape(was, 0.0).sign_changes) return false;
    if (inner_axis_extrema_of(now).all > inner_axis_extrema_of(was).all) return false;
    if (cubic_turning(now) > cubic_turning(was) + fold_turn || overreach_length(now) > overreach_length(was)) return false;
    for (const auto& [end, handle] : {std::pair{0, 1}, std::pair{3, 2}})
      if (distance(now.p[end], now.p[handle]) < shortest_handle_share * distance(was.p[end], was.p[handle])) return false;
  }
  return true;
}

// The largest jump of dκ/ds at an inner node, relative to the larger side or, where both are
// nearly 0 (a symmetric extremum of κ), to the node's κ over the cubics' mean chord.
double largest_slope_jump(const RunProblem& problem, const std::vector<Cubic>& cubics) {
  const std::size_t m = cubics.size(), nodes = problem.frames.size();
  double worst = 0.0;
  for (std::size_t j = problem.closed ? 0 : 1; j < (problem.closed ? nodes : nodes - 1); ++j) {
    const Cubic &into = cubics[(j + m - 1) % m], &out_of = cubics[j % m];
    const EndData a = end_data(into, SegmentEnd::end), b = end_data(out_of, SegmentEnd::start);
    const double h = 0.5 * (distance(into.p[0], into.p[3]) + distance(out_of.p[0], out_of.p[3]));
    const double scale = std::max({std::abs(a.slope), std::abs(b.slope), std::abs(a.kappa) / h});
    if (scale > 0.0) worst = std::max(worst, std::abs(a.slope - b.slope) / scale);
  }
  return worst;
}

struct RunSolution {
  std::vector<Cubic> cubics;  // empty: nothing within the allowance improved on the targets
  bool g3 = false;
  std::size_t worst = 0;      // the cubic farthest over its allowance at the last weight tried
};

RunSolution solve(const RunProblem& problem) {
  RunSolution out;
  Eigen::VectorXd x = problem.initial();
  std::vector<Foot> feet = initial_feet(problem);
  for (const double w : slope_weights) {
    least_squares(problem, x, feet, w);
    const std::vector<Cubic> cubics = problem.cubics(x);
    const std::vector<double> over = overreach(problem, cubics);
    if (!x.allFinite() || !acceptable(problem, cubics, over)) {
      out.worst = static_cast<std::size_t>(std::max_element(over.begin(), over.end()) - over.begin());
      return out;
    }
    out.cubics = cubics;
  }
  out.g3 = largest_slope_jump(problem, out.cubics) < g3_relative;
  return out;
}

// The problem for a run as the nodes draw it, each cubic marked in `cut` halved (its middle a
// node free to move and turn).
std::optional<RunProblem> problem_for(const std::vector<OutlineNode>& nodes, const CubicRun& run,
                                      std::span<const double> allowance_by_cubic, const std::vector<bool>& cut,
                                      double flat_curvature) {
  RunProblem p;
  p.closed = run.closed;
  const std::size_t m = run.cubic_count();
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t i = run.nodes[k];
    const Cubic c = outline_cubic(nodes, i);
    if (distance(c.p[0], c.p[1]) <= 0.0 || distance(c.p[2], c.p[3]) <= 0.0) return std::nullopt;
    const double allow = i < allowance_by_cubic.size() ? allowance_by_cubic[i] : 0.0;
    const OutlineNode& node = nodes[i];
    NodeFrame frame{node.point, angle_of(leaving_direction(nodes, i)), false, false, false};
    const bool inner = run.closed || k > 0;
    frame.movable = inner;
    frame.turnable = inner && !node.grid_step;
    const EndCurvature before = inner ? end_curvature(Segment(outline_cubic(nodes, run.nodes[(k + m - 1) % m])), SegmentEnd::end)
                                      : EndCurvature{};
    const EndCurvature after = end_curvature(Segment(c), SegmentEnd::start);
    const auto flat = [&](const EndCurvature& e) { return std::abs(e.curvature.value_or(1.0)) < flat_curvature; };
    frame.flat = inner ? flat(before) && flat(after) : !node.in_handle && node.smooth && flat(after);
    if (!inner) frame.end_curvature = after.curvature.value_or(0.0);
    const std::array<Cubic, 2> halves = c.split(0.5);
    if (cut[k]) {
      p.frames.push_back(frame);
      p.targets.push_back(halves[0]), p.allowance.push_back(allow);
      const double angle = angle_of(halves[1].p[1] - halves[1].p[0]);
      p.frames.push_back({halves[1].p[0], angle, true, true, false});
      p.targets.push_back(halves[1]), p.allowance.push_back(allow);
    } else {
      p.frames.push_back(frame);
      p.targets.push_back(c), p.allowance.push_back(allow);
    }
  }
  if (!run.closed) {
    const OutlineNode& last = nodes[run.nodes.back()];
    const EndCurvature e = end_curvature(Segment(outline_cubic(nodes, run.nodes[m - 1])), SegmentEnd::end);
    // The run's last tangent is the one it arrives by: at a corner between two curves the one
    // leaving is the next run's.
    p.frames.push_back({last.point, angle_of(arriving_direction(nodes, run.nodes.back())), false, false,
                        !last.out_handle && last.smooth && std::abs(e.curvature.value_or(1.0)) < flat_curvature,
                        e.curvature.value_or(0.0)});
  }
  // A flat end whose far handle would have to reach backwards (the cubic is flat there only
  // within flat_curvature) keeps its κ by a row instead.
  p.index();
  const std::vector<Cubic> drawn = p.cubics(p.initial());
  for (std::size_t k = 0; k < drawn.size(); ++k)
    if (!finite(drawn[k])) p.frames[k].flat = p.frames[p.end_node(k)].flat = false;
  p.index();  // the rows of the ends no longer flat
  return p;
}

}  // namespace

int g3_node_budget(std::size_t cubics, std::size_t nodes, std::size_t source_nodes, double share, double most_share) {
  const double by_share = std::floor(share * static_cast<double>(cubics) + 0.5);
  const double room = std::floor(most_share * static_cast<double>(source_nodes)) - static_cast<double>(nodes);
  return static_cast<int>(std::max(0.0, std::min(by_share, room)));
}

G3CubicReport make_cubics_g3(std::vector<OutlineNode>& nodes, bool closed, std::span<const double> allowance_by_cubic,
                             const G3CubicSettings& settings) {
  G3CubicReport report;
  int budget = settings.node_budget;
  const std::size_t n = nodes.size();
  std::vector<std::vector<OutlineNode>> inserted(n);  // nodes to insert after node i
  std::vector<OutlineNode> updated = nodes;
  for (const CubicRun& run : smooth_runs(nodes, closed)) {
    ++report.runs;
    const std::size_t m = run.cubic_count();
    std::vector<bool> cut(m, false);
    std::optional<RunSolution> kept;
    std::vector<bool> kept_cut = cut;
    for (;;) {
      std::optional<RunProblem> problem = problem_for(nodes, run, allowance_by_cubic, cut, settings.flat_curvature);
      if (!problem) break;
      RunSolution s = solve(*problem);
      if (!s.cubics.empty() && (!kept || s.g3)) kept = s, kept_cut = cut;
      if (s.g3 || budget == 0) break;
      // Cut the cubic of the run (as it was drawn) that strayed farthest; stop when it is cut.
      std::size_t piece = 0, target = 0;
      for (std::size_t k = 0; k < m; ++k) {
        const std::size_t pieces = cut[k] ? 2 : 1;
        if (s.worst < piece + pieces) {
          target = k;
          break;
        }
        piece += pieces;
      }
      if (cut[target]) break;
      cut[target] = true, --budget;
    }
    // Budget spent on cuts the kept solution does not use goes back.
    for (std::size_t k = 0; k < m; ++k)
      if (cut[k] && !kept_cut[k]) ++budget;
    if (!kept) continue;
    ++report.runs_moved;
    report.runs_g3 += kept->g3;
    // Write the run's cubics into its nodes: each node's point and the handles on the run's side.
    const std::vector<Cubic>& cubics = kept->cubics;
    std::size_t piece = 0;
    for (std::size_t k = 0; k < m; ++k) {
      const std::size_t i = run.nodes[k], next = run.nodes[(k + 1) % run.nodes.size()];
      const Cubic& first = cubics[piece];
      updated[i].point = first.p[0], updated[i].out_handle = first.p[1];
      if (kept_cut[k]) {
        const Cubic& second = cubics[piece + 1];
        OutlineNode middle;
        middle.point = second.p[0], middle.in_handle = first.p[2], middle.out_handle = second.p[1];
        inserted[i].push_back(middle);
        ++report.nodes_added;
        updated[next].in_handle = second.p[2], updated[next].point = second.p[3];
        piece += 2;
      } else {
        updated[next].in_handle = first.p[2], updated[next].point = first.p[3];
        piece += 1;
      }
    }
  }
  std::vector<OutlineNode> out;
  out.reserve(n + static_cast<std::size_t>(report.nodes_added));
  for (std::size_t i = 0; i < n; ++i) {
    out.push_back(updated[i]);
    for (OutlineNode& extra : inserted[i]) out.push_back(std::move(extra));
  }
  nodes = std::move(out);
  return report;
}

}  // namespace gf
