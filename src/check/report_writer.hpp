// Check reports, written as glyphs come (a whole font never sits in memory): text grouped by
// glyph with a summary, JSON with a versioned schema (docs/check.schema.json), and Markdown
// for review comments.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "check/check_profile.hpp"
#include "check/contour_checks.hpp"

namespace gf {

inline constexpr int check_report_version = 1;

enum class ReportFormat { text, json, markdown };
std::optional<ReportFormat> report_format(const std::string& name);

struct SourceHeader {
  std::string source;
  std::string family;
  double units_per_em = 1000.0;
};

/// Counts for a source or for the whole run.
struct CheckTotals {
  int glyphs = 0;
  int glyphs_with_findings = 0;
  std::map<Severity, int> by_severity;
  std::map<std::string, int> by_check;
  std::vector<double> total_variations;  ///< one per glyph, for the median

  void add(const GlyphReport& r);
  void add(const CheckTotals& other);
  double median_total_variation() const;
  int count(Severity s) const;
  int at_least(Severity s) const;
};

class ReportWriter {
 public:
  virtual ~ReportWriter() = default;
  virtual void begin_source(const SourceHeader& header) = 0;
  virtual void glyph(const GlyphReport& report) = 0;
  virtual void end_source(const CheckTotals& totals) = 0;
  virtual void finish(const CheckTotals& all) = 0;
};

std::unique_ptr<ReportWriter> make_report_writer(ReportFormat format, std::ostream& out, const CheckProfile& profile);

}  // namespace gf
