// The subcommands: each adds itself to the application and runs when chosen.
#pragma once

#include <CLI/CLI.hpp>

#include "source_options.hpp"

namespace gf {

class ConvertCommand {
 public:
  void add_to(CLI::App& app);
  bool chosen() const { return command_ && command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_ = nullptr;
  std::string source_;
  std::string output_;
  SourceArguments selection_;
};

class ProofCommand {
 public:
  void add_to(CLI::App& app);
  bool chosen() const { return command_ && command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_ = nullptr;
  std::string source_;
  std::string compare_;
  std::string output_;
  SourceArguments selection_;
};

}  // namespace gf
