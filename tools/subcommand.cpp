// The options every subcommand shares: SRC, the selection, -o.
#include "commands.hpp"

namespace gf {

CLI::App& Subcommand::add(CLI::App& app, const char* name, const char* description, const char* output_help) {
  command_ = app.add_subcommand(name, description);
  command_->add_option("SRC", source_, "Font (TTF/OTF, static or variable), UFO, SVG or point-sequence JSON")->required();
  command_->add_option("-o,--output", output_, output_help)->required();
  selection_.add_to(*command_);
  return *command_;
}

}  // namespace gf
