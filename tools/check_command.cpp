// glyphfair check SRC... [selection] [--format text|json|markdown] [--profile text|handwriting]
//                 [--fail-on error|warning|never] [--jobs N] [-o FILE]
#include <algorithm>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include <unistd.h>

#include "check/report_writer.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "glyph_stream.hpp"
#include "io/atomic_output.hpp"
#include "io/input_error.hpp"

namespace gf {

namespace {

constexpr std::size_t glyphs_in_flight = 512;  // glyphs in memory at a time

}  // namespace

void CheckCommand::add_to(CLI::App& app) {
  command_ = app.add_subcommand("check", "Find every curve problem in whole fonts: curvature continuity, extrema, structure");
  command_->add_option("SRC", sources_, "Fonts (TTF/OTF, static or variable), UFOs or SVGs")->required();
  selection_.add_to(*command_);
  command_->add_option("--format", format_, "text, json or markdown")->check(CLI::IsMember({"text", "json", "markdown"}));
  command_->add_option("--profile", profile_, "text or handwriting (relaxes what handwriting does by design)")
      ->check(CLI::IsMember({"text", "handwriting"}));
  command_->add_option("--fail-on", fail_on_, "Exit 4 when a finding is at least: error, warning or never")
      ->check(CLI::IsMember({"error", "warning", "never"}));
  command_->add_option("--jobs", jobs_, "Glyphs checked in parallel (default: every core)")->check(CLI::PositiveNumber);
  command_->add_option("-o,--output", output_, "Write the report here instead of standard output");
}

int CheckCommand::run() const {
  const CheckProfile profile = *check_profile(profile_);
  const ReportFormat format = *report_format(format_);
  const SourceOptions options = selection_.parse();
  std::vector<GlyphSource> sources;
  for (const std::string& s : sources_) sources.push_back(GlyphSource::open(s, options));

  std::optional<AtomicOutput> file;
  std::ofstream file_stream;
  if (!output_.empty()) {
    std::vector<std::filesystem::path> inputs(sources_.begin(), sources_.end());
    file.emplace(output_, AtomicOutput::Kind::file, inputs);
    file_stream.open(file->staging_path());
  }
  std::ostream& out = output_.empty() ? std::cout : file_stream;
  const std::unique_ptr<ReportWriter> writer = make_report_writer(format, out, profile);
  const auto limit = limit_parallelism(jobs_);
  // A bar on a terminal, unless the report itself is going to that terminal.
  const Progress progress(isatty(STDERR_FILENO) && (!output_.empty() || !isatty(STDOUT_FILENO)));

  CheckTotals all;
  for (const GlyphSource& source : sources) {
    const FontInfo& font = source.font();
    writer->begin_source({source.path().string(), font.family_name + (font.style_name.empty() ? "" : " " + font.style_name),
                          font.units_per_em});
    CheckTotals totals;
    stream_glyphs<GlyphReport>(
        source, glyphs_in_flight, progress, source.path().filename().string(),
        [&](const Glyph& g) { return check_glyph(g, font, profile); },
        [&](Glyph&, const GlyphReport& r) {
          writer->glyph(r);
          totals.add(r);
        });
    writer->end_source(totals);
    all.add(totals);
  }
  writer->finish(all);
  if (file) {
    file_stream.close();
    if (!file_stream) throw OutputError(output_ + ": write failed");
    file->commit();
  }
  const bool failed = (fail_on_ == "error" && all.at_least(Severity::error) > 0) ||
                      (fail_on_ == "warning" && all.at_least(Severity::warning) > 0);
  return failed ? exit_code::findings : exit_code::ok;
}

}  // namespace gf
