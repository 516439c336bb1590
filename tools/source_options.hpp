// The options every command shares to name a source and choose its glyphs.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "io/source.hpp"

namespace gf {

struct SourceArguments {
  std::string glyphs;
  std::string unicodes;
  std::optional<std::string> text;
  std::string location;
  std::string instance;

  void add_to(CLI::App& command);
  /// Parses the option values; throws InputError for malformed ones.
  SourceOptions parse() const;
};

}  // namespace gf
