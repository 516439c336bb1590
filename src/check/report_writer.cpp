#include "check/report_writer.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace gf {

namespace {

using json = nlohmann::ordered_json;

std::string fixed(double v, int digits = 4) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string place(const Finding& f) {
  std::string out;
  if (f.contour >= 0) out += "contour " + std::to_string(f.contour);
  if (f.node) out += (out.empty() ? "" : ", ") + std::string("node ") + std::to_string(*f.node);
  if (f.point) out += " (" + fixed(f.point->x, 6) + ", " + fixed(f.point->y, 6) + ")";
  return out;
}

std::string counts_line(const CheckTotals& t) {
  return std::to_string(t.glyphs) + " glyphs checked, " + std::to_string(t.glyphs_with_findings) +
         " with findings: " + std::to_string(t.count(Severity::error)) + " errors, " +
         std::to_string(t.count(Severity::warning)) + " warnings, " + std::to_string(t.count(Severity::info)) +
         " info; median curvature total variation " + fixed(t.median_total_variation());
}

std::string per_check_line(const CheckTotals& t) {
  std::string out;
  for (const std::string& id : check_ids())
    if (const auto it = t.by_check.find(id); it != t.by_check.end())
      out += (out.empty() ? "" : ", ") + id + " " + std::to_string(it->second);
  return out.empty() ? "no findings" : out;
}

json summary_json(const CheckTotals& t) {
  json by_check = json::object();
  for (const std::string& id : check_ids()) by_check[id] = t.by_check.count(id) ? t.by_check.at(id) : 0;
  return {{"glyphs", t.glyphs},
          {"glyphs_with_findings", t.glyphs_with_findings},
          {"errors", t.count(Severity::error)},
          {"warnings", t.count(Severity::warning)},
          {"info", t.count(Severity::info)},
          {"by_check", by_check},
          {"median_total_variation", t.median_total_variation()}};
}

// The line-by-line formats (text, Markdown): written as the glyphs come, flushed at the end.
class StreamedWriter : public ReportWriter {
 public:
  StreamedWriter(std::ostream& out, const CheckProfile& p) : out_(out), profile_(p) {}
  void finish(const CheckTotals&) override { out_.flush(); }

 protected:
  std::ostream& out_;
  const CheckProfile& profile_;
};

class TextWriter : public StreamedWriter {
 public:
  using StreamedWriter::StreamedWriter;
  void begin_source(const SourceHeader& h) override {
    out_ << "glyphfair check: " << h.source << " (" << h.family << ", UPM " << fixed(h.units_per_em) << "), profile "
         << profile_.name << "\n";
    for (const std::string& r : profile_.relaxed) out_ << "  relaxed: " << r << "\n";
  }
  void glyph(const GlyphReport& r) override {
    if (r.findings.empty()) return;
    out_ << r.glyph << "\n";
    for (const Finding& f : r.findings) {
      char head[64];
      std::snprintf(head, sizeof head, "  %-7s %-21s ", to_string(f.severity), f.check.c_str());
      out_ << head << place(f) << ": " << f.message << "\n";
    }
    const FairnessFigures& q = r.fairness;
    out_ << "  fairness: curvature total variation " << fixed(q.total_variation) << ", " << q.inflections
         << " inflections, " << q.curvature_extrema << " curvature extrema, " << fixed(100 * q.monotone_fraction, 3)
         << "% of curve segments monotone\n";
  }
  void end_source(const CheckTotals& t) override {
    out_ << "summary: " << counts_line(t) << "\n  " << per_check_line(t) << "\n\n";
  }
};

class JsonWriter : public ReportWriter {
 public:
  JsonWriter(std::ostream& out, const CheckProfile& p) : out_(out) {
    json relaxed = json::array();
    for (const auto& r : p.relaxed) relaxed.push_back(r);
    out_ << "{\"format\":\"glyphfair-check\",\"version\":" << check_report_version << ",\"profile\":"
         << json(p.name).dump() << ",\"relaxed\":" << relaxed.dump() << ",\"sources\":[";
  }
  void begin_source(const SourceHeader& h) override {
    out_ << (first_source_ ? "" : ",") << "\n{\"source\":" << json(h.source).dump() << ",\"family\":" << json(h.family).dump()
         << ",\"units_per_em\":" << json(h.units_per_em).dump() << ",\"glyphs\":[";
    first_source_ = false;
    first_glyph_ = true;
  }
  // Written by hand: a whole font's findings go through here, and building a json value
  // per finding costs more than the checks themselves.
  void glyph(const GlyphReport& r) override {
    std::string& o = buffer_;
    o.clear();
    o += first_glyph_ ? "\n{\"name\":" : ",\n{\"name\":";
    o += json(r.glyph).dump();
    o += ",\"findings\":[";
    for (std::size_t i = 0; i < r.findings.size(); ++i) {
      const Finding& f = r.findings[i];
      o += i ? ",{" : "{";
      o += "\"check\":\"" + f.check + "\",\"severity\":\"" + to_string(f.severity) + "\",\"contour\":" +
           std::to_string(f.contour);
      o += ",\"node\":" + (f.node ? std::to_string(*f.node) : "null");
      o += ",\"segment\":" + (f.segment ? std::to_string(*f.segment) : "null");
      o += ",\"t\":" + number(f.t);
      o += ",\"point\":" + (f.point ? "[" + number(f.point->x) + "," + number(f.point->y) + "]" : std::string("null"));
      o += ",\"value\":" + number(f.value) + ",\"threshold\":" + number(f.threshold);
      o += ",\"unit\":\"" + f.unit + "\",\"message\":" + json(f.message).dump() + "}";
    }
    const FairnessFigures& q = r.fairness;
    o += "],\"fairness\":{\"total_variation\":" + number(q.total_variation) +
         ",\"inflections\":" + std::to_string(q.inflections) +
         ",\"curvature_extrema\":" + std::to_string(q.curvature_extrema) +
         ",\"curve_segments\":" + std::to_string(q.curve_segments) +
         ",\"monotone_fraction\":" + number(q.monotone_fraction) + "}}";
    out_ << o;
    first_glyph_ = false;
  }
  void end_source(const CheckTotals& t) override { out_ << "],\"summary\":" << summary_json(t).dump() << "}"; }
  void finish(const CheckTotals& all) override { out_ << "],\n\"summary\":" << summary_json(all).dump() << "}\n"; out_.flush(); }

 private:
  static std::string number(std::optional<double> v) {
    if (!v || !std::isfinite(*v)) return "null";
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, *v);
    return std::string(buf, r.ptr);
  }

  std::ostream& out_;
  bool first_source_ = true, first_glyph_ = true;
  std::string buffer_;
};

std::string markdown_cell(std::string s) {
  std::string out;
  for (const char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

class MarkdownWriter : public StreamedWriter {
 public:
  using StreamedWriter::StreamedWriter;
  void begin_source(const SourceHeader& h) override {
    out_ << "## glyphfair check: `" << markdown_cell(h.source) << "`\n\n" << markdown_cell(h.family) << ", UPM "
         << fixed(h.units_per_em) << ", profile `" << profile_.name << "`";
    for (const std::string& r : profile_.relaxed) out_ << "; " << r;
    out_ << "\n\n| glyph | severity | check | where | what |\n|---|---|---|---|---|\n";
  }
  void glyph(const GlyphReport& r) override {
    for (const Finding& f : r.findings)
      out_ << "| `" << markdown_cell(r.glyph) << "` | " << to_string(f.severity) << " | " << f.check << " | "
           << markdown_cell(place(f)) << " | " << markdown_cell(f.message) << " |\n";
  }
  void end_source(const CheckTotals& t) override {
    out_ << "\n**Summary:** " << counts_line(t) << ". " << per_check_line(t) << ".\n\n";
  }
};

}  // namespace

std::optional<ReportFormat> report_format(const std::string& name) {
  if (name == "text") return ReportFormat::text;
  if (name == "json") return ReportFormat::json;
  if (name == "markdown") return ReportFormat::markdown;
  return std::nullopt;
}

void CheckTotals::add(const GlyphReport& r) {
  ++glyphs;
  if (!r.findings.empty()) ++glyphs_with_findings;
  for (const Finding& f : r.findings) {
    ++by_severity[f.severity];
    ++by_check[f.check];
  }
  total_variations.push_back(r.fairness.total_variation);
}

void CheckTotals::add(const CheckTotals& o) {
  glyphs += o.glyphs;
  glyphs_with_findings += o.glyphs_with_findings;
  for (const auto& [k, v] : o.by_severity) by_severity[k] += v;
  for (const auto& [k, v] : o.by_check) by_check[k] += v;
  total_variations.insert(total_variations.end(), o.total_variations.begin(), o.total_variations.end());
}

double CheckTotals::median_total_variation() const {
  if (total_variations.empty()) return 0.0;
  std::vector<double> v = total_variations;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

int CheckTotals::count(Severity s) const {
  const auto it = by_severity.find(s);
  return it == by_severity.end() ? 0 : it->second;
}

int CheckTotals::at_least(Severity s) const {
  int n = 0;
  for (const auto& [k, v] : by_severity)
    if (k >= s) n += v;
  return n;
}

std::unique_ptr<ReportWriter> make_report_writer(ReportFormat format, std::ostream& out, const CheckProfile& profile) {
  switch (format) {
    case ReportFormat::json: return std::make_unique<JsonWriter>(out, profile);
    case ReportFormat::markdown: return std::make_unique<MarkdownWriter>(out, profile);
    default: return std::make_unique<TextWriter>(out, profile);
  }
}

}  // namespace gf
