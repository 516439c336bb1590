// glyphfair fair SRC [selection] -o OUT.ufo|.svg|.json [--continuity g1|g2|g3] [--tolerance UNITS]
//                [--profile text|handwriting] [--corner-angle DEG] [--round|--no-round] [--proof FILE.pdf]
//                [--segments FILE.json] [--jobs N]
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>

#include <unistd.h>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "fair/glyph_fairing.hpp"
#include "glyph_stream.hpp"
#include "io/file_extension.hpp"
#include "io/input_error.hpp"
#include "io/ufo_writer.hpp"
#include "faired_segments_output.hpp"
#include "outline_output.hpp"
#include "render/proof_document.hpp"

namespace fs = std::filesystem;

namespace gf {

namespace {

// Glyphs in memory at a time. Glyphs are taken in order, so a slow glyph stops the other
// threads once they run this many ahead of it: whole DejaVu Sans averages 17 ms a glyph, and
// its U+2765 takes 9 s, against the 4 s 256 glyphs gave (52.4 s against 57.2–58.6; WenQuanYi
// Zen Hei's U+4E00–52FF 113 MB against 107).
constexpr std::size_t glyphs_in_flight = 1024;

}  // namespace

void FairCommand::add_to(CLI::App& app) {
  CLI::App& c = add(app, "fair",
                    "Fair outlines: G2 log-aesthetic curves within a stated distance of the source, written as cubics",
                    "OUT.ufo, OUT.svg or OUT.json");
  c.add_option("--profile", profile_, "text (professional fonts: tight) or handwriting (smooths scan noise)")
      ->check(CLI::IsMember({"text", "handwriting"}));
  c.add_option("--continuity", continuity_,
               "g2 (curvature matched at every smooth join), g3 (its rate of change too) or g1")
      ->check(CLI::IsMember({"g1", "g2", "g3"}));
  c.add_option("--tolerance", tolerance_,
               "Largest distance from the source, font units (default 0.125 % of the em for text, 1.4 % for handwriting)")
      ->check(CLI::PositiveNumber);
  c.add_option("--corner-angle", corner_angle_,
               "Joins turning by more than this many degrees stay corners (default 3 for text, 30 for handwriting)")
      ->check(CLI::Range(0.0, 180.0));
  CLI::Option* round = c.add_flag("--round", round_,
                                  "Round to the integer grid even a glyph the source draws off it (the default for SVG and point sequences)");
  c.add_flag("--no-round", no_round_, "Keep fractional coordinates instead of rounding to the integer grid")->excludes(round);
  c.add_option("--proof", proof_, "Also draw a before/after proof of every faired glyph (PDF)");
  c.add_option("--segments", segments_,
               "Also write the faired curve before the cubic writeback: every piece with its end κ and κ′ (JSON)");
  c.add_option("--jobs", jobs_, "Glyphs faired in parallel (default: every core)")->check(CLI::PositiveNumber);
}

int FairCommand::run() const {
  const OutlineFormat format = outline_format_for(output_);
  if (!proof_.empty() && lower_extension(proof_) != ".pdf") throw InputError(proof_ + ": the proof must be a .pdf");
  if (!segments_.empty() && lower_extension(segments_) != ".json")
    throw InputError(segments_ + ": the segments must go to a .json file");
  FairOptions options;
  options.profile = *parse_fair_profile(profile_);
  options.continuity = *parse_continuity(continuity_);
  options.tolerance_units = tolerance_;
  options.corner_angle_deg = corner_angle_;
  const GlyphSource source = GlyphSource::open(source_, selection_.parse());
  // A font or UFO glyph drawn off the integer grid keeps its fractions; SVG paths and fitted
  // point sequences have no grid of their own, and a font made from them wants integers.
  const bool own_grid = source.kind() == SourceKind::font || source.kind() == SourceKind::ufo;
  options.rounding = no_round_ ? Rounding::none : round_ || !own_grid ? Rounding::integers : Rounding::as_source;
  const FontInfo& font = source.font();
  const FairSettings settings = resolve_settings(options, font.units_per_em);
  const fs::path inputs[] = {source_};

  std::optional<UfoWriter> ufo;
  if (format == OutlineFormat::ufo) ufo.emplace(output_, font, inputs);
  GlyphSet whole{font, {}};  // for the single-document formats
  std::vector<ProofGlyph> proof_pages;
  const auto limit = limit_parallelism(jobs_);
  const Progress progress(isatty(STDERR_FILENO));
  const std::string name = fs::path(source_).filename().string();

  std::optional<FairedSegmentsOutput> segments;
  if (!segments_.empty()) segments.emplace(name, settings, font.units_per_em);
  std::size_t glyphs_faired = 0, contours_kept = 0, runs_as_drawn = 0, g1_nodes = 0, guide_stretches = 0, g3_runs = 0,
              g2_runs = 0, g2_line_joins = 0;
  double deviation = 0.0, mismatch = 0.0;
  G3CubicReport g3_cubics;
  G3JoinCount g3_joins;
  FairedContours faired_contours;  // composites repeat their components' contours
  stream_glyphs<GlyphFairing>(
      source, glyphs_in_flight, progress, name, [&](const Glyph& g) { return fair_glyph(g, settings, faired_contours); },
      [&](Glyph& original, GlyphFairing& r) {
        const auto tell = [&](const char* level, const std::vector<std::string>& whys, const char* outcome) {
          for (const std::string& why : whys) {
            progress.clear();
            std::cerr << "glyphfair: " << level << ": " << name << ": glyph '" << r.glyph.name << "': " << why << " ("
                      << outcome << ")\n";
          }
        };
        tell("warning", r.kept, "kept unfaired");
        tell("warning", r.runs_as_drawn, "the rest of the contour faired");
        tell("note", r.g3_shortfalls, "kept G2");
        g3_runs += static_cast<std::size_t>(r.g3_runs);
        g2_line_joins += static_cast<std::size_t>(r.g2_line_joins);
        g2_runs += r.g3_shortfalls.size();
        g3_cubics += r.g3_cubics;
        g3_joins += r.g3_joins;
        if (segments) segments->add(r);
        contours_kept += r.kept.size();
        runs_as_drawn += r.runs_as_drawn.size();
        g1_nodes += static_cast<std::size_t>(r.g1_nodes);
        guide_stretches += static_cast<std::size_t>(r.guide_stretches);
        ++glyphs_faired;
        deviation = std::max(deviation, r.deviation);
        mismatch = std::max(mismatch, r.max_curvature_mismatch);
        if (!proof_.empty()) proof_pages.push_back({r.glyph, std::move(original)});
        if (ufo) ufo->add(r.glyph);
        else whole.glyphs.push_back(std::move(r.glyph));
      });
  if (ufo) ufo->commit();
  else write_outlines(whole, output_, format, inputs);
  if (segments) segments->write(segments_, inputs);
  if (!proof_.empty()) {
    ProofOptions proof;
    proof.title = name + " faired (" + to_string(options.profile) + ", tolerance " + std::to_string(settings.tolerance_units) + " units)";
    proof.has_compare = true;
    proof.compare_label = name + " (source)";
    const fs::path proof_inputs[] = {source_, output_};
    write_proof(proof_pages, font, proof, proof_, proof_inputs);
  }
  std::cerr << "glyphfair: " << name << ": " << glyphs_faired << " glyphs faired, " << contours_kept
            << " contours kept as they were, " << runs_as_drawn
            << " runs kept as drawn in contours faired otherwise; largest distance from the source " << deviation
            << " units (tolerance " << settings.tolerance_units << "); largest relative curvature mismatch left by a chain solve " << mismatch
            << "; " << g1_nodes << " smooth nodes G1 only; " << guide_stretches
            << " spans written from the smoothing guide (no G2 log-aesthetic chain within the budget)";
  if (settings.continuity == Continuity::g3)
    std::cerr << "; G3 on " << g3_runs << " of " << g3_runs + g2_runs << " smooth runs (" << g2_line_joins
              << " of their line joins G2 only: too little line to slide along); written cubics G3 (before rounding) on "
              << g3_cubics.runs_g3 << " of " << g3_cubics.runs << " runs of smooth nodes, nearer it on "
              << g3_cubics.runs_moved - g3_cubics.runs_g3 << " more, " << g3_cubics.nodes_added
              << " nodes added; as written, dκ/ds within 5 % across " << g3_joins.matched << " of " << g3_joins.joins
              << " smooth joins between curves";
  std::cerr << "\n";
  return exit_code::ok;
}

}  // namespace gf
