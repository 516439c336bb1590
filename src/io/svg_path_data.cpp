#include "io/svg_path_data.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>

#include "io/input_error.hpp"
#include "io/number_format.hpp"

namespace gf {

namespace {

class PathParser {
 public:
  PathParser(std::string_view d, const std::string& where) : d_(d), where_(where) {}

  std::vector<Contour> parse() {
    char command = 0;
    skip_separators();
    while (i_ < d_.size()) {
      if (std::isalpha(static_cast<unsigned char>(d_[i_]))) {
        command = d_[i_++];
      } else if (command == 0) {
        fail("path data must start with a command");
      } else if (command == 'M' || command == 'm') {
        command = command == 'M' ? 'L' : 'l';  // further pairs after a moveto are linetos
      } else if (command == 'Z' || command == 'z') {
        fail("numbers after a closepath");
      }
      run(command);
      skip_separators();
    }
    finish_contour(false);
    return std::move(contours_);
  }

 private:
  void run(char command) {
    const bool rel = std::islower(static_cast<unsigned char>(command));
    const Vec2 base = rel ? current_ : Vec2{};
    switch (std::toupper(static_cast<unsigned char>(command))) {
      case 'M': {
        const Vec2 p = base + point();
        finish_contour(false);
        start_ = current_ = p;
        open_ = true;
        last_control_ = p;
        return;
      }
      case 'Z':
        finish_contour(true);
        current_ = last_control_ = start_;
        return;
      case 'L': line_to(base + point()); return;
      case 'H': line_to({(rel ? current_.x : 0.0) + number(), current_.y}); return;
      case 'V': line_to({current_.x, (rel ? current_.y : 0.0) + number()}); return;
      case 'C': {
        const Vec2 c1 = base + point(), c2 = base + point(), p = base + point();
        cubic_to(c1, c2, p);
        return;
      }
      case 'S': {
        const Vec2 c1 = previous_ == 'C' ? current_ * 2.0 - last_control_ : current_;
        const Vec2 c2 = base + point(), p = base + point();
        cubic_to(c1, c2, p);
        return;
      }
      case 'Q': {
        const Vec2 c = base + point(), p = base + point();
        quad_to(c, p);
        return;
      }
      case 'T': {
        const Vec2 c = previous_ == 'Q' ? current_ * 2.0 - last_control_ : current_;
        quad_to(c, base + point());
        return;
      }
      case 'A': {
        const double rx = number(), ry = number(), rotation = number();
        const bool large = flag(), sweep = flag();
        arc_to(rx, ry, rotation, large, sweep, base + point());
        return;
      }
      default: fail(std::string("unknown command '") + command + "'");
    }
  }

  void ensure_open() {
    if (!open_) {  // drawing after Z continues from the start point (SVG 1.1 §8.3.3)
      open_ = true;
      start_ = current_;
    }
  }
  void line_to(Vec2 p) {
    ensure_open();
    contour_.segments.push_back(Line{{current_, p}});
    current_ = last_control_ = p;
    previous_ = 'L';
  }
  void quad_to(Vec2 c, Vec2 p) {
    ensure_open();
    contour_.segments.push_back(Quad{{current_, c, p}});
    current_ = p;
    last_control_ = c;
    previous_ = 'Q';
  }
  void cubic_to(Vec2 c1, Vec2 c2, Vec2 p) {
    ensure_open();
    contour_.segments.push_back(Cubic{{current_, c1, c2, p}});
    current_ = p;
    last_control_ = c2;
    previous_ = 'C';
  }

  // SVG 1.1 implementation notes F.6.5 (endpoint to centre parameterisation), then cubics.
  void arc_to(double rx, double ry, double rotation_deg, bool large, bool sweep, Vec2 p) {
    const Vec2 p0 = current_;
    rx = std::abs(rx);
    ry = std::abs(ry);
    if (p0 == p) return;
    if (rx == 0.0 || ry == 0.0) return line_to(p);
    const double phi = radians(rotation_deg);
    const double cp = std::cos(phi), sp = std::sin(phi);
    const Vec2 h = (p0 - p) * 0.5;
    const Vec2 q{cp * h.x + sp * h.y, -sp * h.x + cp * h.y};
    const double lambda = q.x * q.x / (rx * rx) + q.y * q.y / (ry * ry);
    if (lambda > 1.0) { rx *= std::sqrt(lambda); ry *= std::sqrt(lambda); }
    const double num = rx * rx * ry * ry - rx * rx * q.y * q.y - ry * ry * q.x * q.x;
    const double den = rx * rx * q.y * q.y + ry * ry * q.x * q.x;
    double coef = std::sqrt(std::max(0.0, num / den));
    if (large == sweep) coef = -coef;
    const Vec2 cq{coef * rx * q.y / ry, -coef * ry * q.x / rx};
    const Vec2 mid = (p0 + p) * 0.5;
    const Vec2 centre{cp * cq.x - sp * cq.y + mid.x, sp * cq.x + cp * cq.y + mid.y};
    const auto angle = [](Vec2 u, Vec2 v) { return std::atan2(cross(u, v), dot(u, v)); };
    const Vec2 u{(q.x - cq.x) / rx, (q.y - cq.y) / ry};
    const Vec2 v{(-q.x - cq.x) / rx, (-q.y - cq.y) / ry};
    const double theta1 = angle({1, 0}, u);
    double delta = angle(u, v);
    if (!sweep && delta > 0) delta -= 2 * std::numbers::pi;
    if (sweep && delta < 0) delta += 2 * std::numbers::pi;
    const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(delta) / (std::numbers::pi / 2) - 1e-9)));
    const double step = delta / pieces;
    const double k = 4.0 / 3.0 * std::tan(step / 4.0);
    const auto on_ellipse = [&](double t) {
      const Vec2 e{rx * std::cos(t), ry * std::sin(t)};
      return Vec2{cp * e.x - sp * e.y + centre.x, sp * e.x + cp * e.y + centre.y};
    };
    const auto tangent = [&](double t) {
      const Vec2 e{-rx * std::sin(t), ry * std::cos(t)};
      return Vec2{cp * e.x - sp * e.y, sp * e.x + cp * e.y};
    };
    for (int i = 0; i < pieces; ++i) {
      const double a = theta1 + step * i, b = a + step;
      const Vec2 end = i + 1 == pieces ? p : on_ellipse(b);
      cubic_to(current_ + tangent(a) * k, end - tangent(b) * k, end);
    }
  }

  void finish_contour(bool closed) {
    if (!open_) return;
    if (closed && current_ != start_) contour_.segments.push_back(Line{{current_, start_}});
    if (!contour_.segments.empty()) {
      contour_.closed = closed;
      contour_.nodes.assign(contour_.segments.size() + (closed ? 0 : 1), NodeFlags{});
      contours_.push_back(std::move(contour_));
    }
    contour_ = Contour{};
    open_ = false;
    previous_ = 0;
  }

  void skip_separators() {
    while (i_ < d_.size() && (std::isspace(static_cast<unsigned char>(d_[i_])) || d_[i_] == ',')) ++i_;
  }
  double number() {
    skip_separators();
    if (i_ >= d_.size()) fail("path data ends where a number is expected");
    std::size_t j = i_;
    if (d_[j] == '+') ++j;  // from_chars does not take a plus sign
    double v = 0.0;
    const auto [end, ec] = std::from_chars(d_.data() + j, d_.data() + d_.size(), v);
    if (ec != std::errc() || !std::isfinite(v)) fail("'" + std::string(d_.substr(i_, 12)) + "' is not a number");
    i_ = static_cast<std::size_t>(end - d_.data());
    return v;
  }
  Vec2 point() {
    const double x = number();
    return {x, number()};
  }
  bool flag() {
    skip_separators();
    if (i_ >= d_.size() || (d_[i_] != '0' && d_[i_] != '1')) fail("an arc flag must be 0 or 1");
    return d_[i_++] == '1';
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw InputError(where_ + ": path data at character " + std::to_string(i_) + ": " + why);
  }

  std::string_view d_;
  const std::string& where_;
  std::size_t i_ = 0;
  std::vector<Contour> contours_;
  Contour contour_;
  bool open_ = false;
  Vec2 current_, start_, last_control_;
  char previous_ = 0;
};

void append_point(std::string& out, Vec2 p) {
  out += shortest_decimal(p.x);
  out += ' ';
  out += shortest_decimal(p.y);
}

}  // namespace

std::vector<Contour> parse_svg_path_data(std::string_view d, const std::string& where) {
  return PathParser(d, where).parse();
}

std::string format_svg_path_data(const std::vector<Contour>& contours) {
  std::string out;
  for (const Contour& c : contours) {
    if (c.segments.empty()) continue;
    if (!out.empty()) out += ' ';
    out += 'M';
    append_point(out, c.node_point(0));
    const std::size_t n = c.segments.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Segment& s = c.segments[i];
      // Z draws the closing line; a degenerate one is written so the reader keeps it.
      if (c.closed && i + 1 == n && is_line(s) && start_point(s) != end_point(s)) break;
      std::visit(
          [&](const auto& b) {
            out += b.degree == 1 ? " L" : b.degree == 2 ? " Q" : " C";
            for (std::size_t k = 1; k < b.p.size(); ++k) {
              if (k > 1) out += ' ';
              append_point(out, b.p[k]);
            }
          },
          s);
    }
    if (c.closed) out += " Z";
  }
  return out;
}

}  // namespace gf
