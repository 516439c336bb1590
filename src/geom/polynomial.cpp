#include "geom/polynomial.hpp"

#include <algorithm>
#include <cmath>

namespace gf {

Polynomial::Polynomial(std::span<const double> coefficients) {
  const int n = std::min<int>(static_cast<int>(coefficients.size()), max_degree + 1);
  for (int i = 0; i < n; ++i) c_[i] = coefficients[i];
  degree_ = std::max(0, n - 1);
}

double Polynomial::operator()(double t) const {
  double v = c_[degree_];
  for (int i = degree_ - 1; i >= 0; --i) v = v * t + c_[i];
  return v;
}

Polynomial Polynomial::derivative() const {
  Polynomial d;
  d.degree_ = std::max(0, degree_ - 1);
  for (int i = 1; i <= degree_; ++i) d.c_[i - 1] = i * c_[i];
  return d;
}

Polynomial Polynomial::antiderivative() const {
  Polynomial a;
  a.degree_ = std::min(degree_ + 1, max_degree);
  for (int i = 0; i < a.degree_; ++i) a.c_[i + 1] = c_[i] / (i + 1);
  return a;
}

double Polynomial::magnitude() const {
  double m = 0.0;
  for (int i = 0; i <= degree_; ++i) m = std::max(m, std::abs(c_[i]));
  return m;
}

Polynomial operator+(const Polynomial& a, const Polynomial& b) {
  Polynomial r;
  r.degree_ = std::max(a.degree_, b.degree_);
  for (int i = 0; i <= r.degree_; ++i) r.c_[i] = a.coefficient(i) + b.coefficient(i);
  return r;
}

Polynomial operator-(const Polynomial& a, const Polynomial& b) { return a + (-1.0) * b; }

Polynomial operator*(double s, const Polynomial& a) {
  Polynomial r = a;
  for (int i = 0; i <= r.degree_; ++i) r.c_[i] *= s;
  return r;
}

Polynomial operator*(const Polynomial& a, const Polynomial& b) {
  Polynomial r;
  r.degree_ = std::min(a.degree_ + b.degree_, Polynomial::max_degree);
  for (int i = 0; i <= a.degree_; ++i)
    for (int j = 0; j <= b.degree_ && i + j <= Polynomial::max_degree; ++j)
      r.c_[i + j] += a.c_[i] * b.c_[j];
  return r;
}

namespace {

using Bernstein = std::array<double, Polynomial::max_degree + 1>;

// Power basis on [0,1] -> Bernstein basis: b_i = sum_{j<=i} C(i,j)/C(n,j) a_j.
Bernstein to_bernstein(const Polynomial& p) {
  const int n = p.degree();
  Bernstein b{};
  for (int i = 0; i <= n; ++i) {
    double sum = 0.0;
    double cij = 1.0;  // C(i, j)
    double cnj = 1.0;  // C(n, j)
    for (int j = 0; j <= i; ++j) {
      sum += cij / cnj * p.coefficient(j);
      cij = cij * (i - j) / (j + 1);
      cnj = cnj * (n - j) / (j + 1);
    }
    b[i] = sum;
  }
  return b;
}

int sign_of(double v) { return (v > 0.0) - (v < 0.0); }

int sign_variations(const Bernstein& b, int n) {
  int count = 0;
  int last = 0;
  for (int i = 0; i <= n; ++i) {
    const int s = sign_of(b[i]);
    if (s == 0) continue;
    if (last != 0 && s != last) ++count;
    last = s;
  }
  return count;
}

// de Casteljau split of Bernstein coefficients at 1/2.
void split_half(const Bernstein& b, int n, Bernstein& left, Bernstein& right) {
  Bernstein w = b;
  for (int k = 0; k <= n; ++k) {
    left[k] = w[0];
    right[n - k] = w[n - k];
    for (int i = 0; i < n - k; ++i) w[i] = 0.5 * (w[i] + w[i + 1]);
  }
}

int first_sign(const Bernstein& b, int n) {
  for (int i = 0; i <= n; ++i)
    if (const int s = sign_of(b[i]); s != 0) return s;
  return 0;
}

int last_sign(const Bernstein& b, int n) {
  for (int i = n; i >= 0; --i)
    if (const int s = sign_of(b[i]); s != 0) return s;
  return 0;
}

struct Isolator {
  const Polynomial& p;
  int n;
  std::vector<SignChange>& out;

  // Bisection on the sign of p; the signs just inside the ends come from the Bernstein form,
  // so an exact zero at an end cannot mislead it. Runs to the resolution of double.
  double refine(double lo, double hi, int sign_lo) const {
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      const int s = sign_of(p(mid));
      if (s == 0) return mid;
      (s == sign_lo ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }

  void isolate(const Bernstein& b, double lo, double hi, int depth) {
    const int v = sign_variations(b, n);
    if (v == 0) return;
    if (v == 1) {
      out.push_back({refine(lo, hi, first_sign(b, n))});
      return;
    }
    if (depth >= 60 || hi - lo < 1e-14) {
      // A cluster narrower than the resolution of t: one root if the ends differ in sign.
      if (first_sign(b, n) != last_sign(b, n)) out.push_back({0.5 * (lo + hi)});
      return;
    }
    Bernstein left{}, right{};
    split_half(b, n, left, right);
    const double mid = 0.5 * (lo + hi);
    isolate(left, lo, mid, depth + 1);
    // A root exactly at the split point is invisible to both halves' sign counts.
    if (left[n] == 0.0 && last_sign(left, n) != 0 && first_sign(right, n) != 0 &&
        last_sign(left, n) != first_sign(right, n))
      out.push_back({mid});
    isolate(right, mid, hi, depth + 1);
  }
};

}  // namespace

std::vector<SignChange> sign_changes_in_unit_interval(const Polynomial& p, double negligible) {
  std::vector<SignChange> roots;
  if (p.magnitude() <= negligible) return roots;
  // Trim leading coefficients that are pure cancellation noise so the degree is honest.
  std::array<double, Polynomial::max_degree + 1> c{};
  int n = p.degree();
  while (n > 0 && std::abs(p.coefficient(n)) <= negligible) --n;
  for (int i = 0; i <= n; ++i) c[i] = p.coefficient(i);
  const Polynomial trimmed(std::span<const double>(c.data(), n + 1));
  if (n == 0) return roots;
  Isolator iso{trimmed, n, roots};
  // An end where p is noise is a zero of p, not a change of sign a hair inside it (a cubic whose
  // first or last three points lie on one line of the grid: its inflection polynomial vanishes
  // at that end, and rounding left a sign change just inside).
  Bernstein b = to_bernstein(trimmed);
  if (std::abs(b[0]) <= negligible) b[0] = 0.0;
  if (std::abs(b[n]) <= negligible) b[n] = 0.0;
  iso.isolate(b, 0.0, 1.0, 0);
  // Neighbouring sub-intervals can both report a root that sits on their shared edge.
  std::sort(roots.begin(), roots.end(), [](SignChange a, SignChange b) { return a.t < b.t; });
  roots.erase(std::unique(roots.begin(), roots.end(),
                          [](SignChange a, SignChange b) { return std::abs(a.t - b.t) < 1e-12; }),
              roots.end());
  return roots;
}

}  // namespace gf
