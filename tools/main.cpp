// glyphfair: the command. Parses the subcommand, runs it, and turns every failure into one
// line on stderr and an exit code (exit_codes.hpp).
#include <iostream>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "io/input_error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"glyphfair: fair glyph outlines with log-aesthetic curves, check them, and proof them"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "glyphfair 0.1.0");
  gf::ConvertCommand convert;
  gf::ProofCommand proof;
  gf::CurveCommand curve;
  gf::CheckCommand check;
  gf::FairCommand fair;
  convert.add_to(app);
  proof.add_to(app);
  curve.add_to(app);
  check.add_to(app);
  fair.add_to(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::cerr << "glyphfair: error: " << e.what() << " (see glyphfair --help)\n";
    return gf::exit_code::bad_input;
  }
  try {
    if (convert.chosen()) return convert.run();
    if (proof.chosen()) return proof.run();
    if (curve.chosen()) return curve.run();
    if (check.chosen()) return check.run();
    if (fair.chosen()) return fair.run();
    return gf::exit_code::bad_input;
  } catch (const gf::InputError& e) {
    std::cerr << "glyphfair: error: " << e.what() << "\n";
    return gf::exit_code::bad_input;
  } catch (const gf::OutputError& e) {
    std::cerr << "glyphfair: error: " << e.what() << "\n";
    return gf::exit_code::cannot_write;
  } catch (const std::exception& e) {
    std::cerr << "glyphfair: internal error: " << e.what() << "\n";
    return gf::exit_code::internal_error;
  }
}
