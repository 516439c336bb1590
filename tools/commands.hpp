// The subcommands: each adds itself to the application and runs when chosen.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "source_options.hpp"

namespace gf {

/// What every subcommand has: a source, a selection and an output.
class Subcommand {
 public:
  bool chosen() const { return command_ && command_->parsed(); }

 protected:
  CLI::App& add(CLI::App& app, const char* name, const char* description, const char* output_help);

  CLI::App* command_ = nullptr;
  std::string source_;
  std::string output_;
  SourceArguments selection_;
};

class ConvertCommand : public Subcommand {
 public:
  void add_to(CLI::App& app);
  int run() const;

 private:
  bool cubic_ = false;
};

class ProofCommand : public Subcommand {
 public:
  void add_to(CLI::App& app);
  int run() const;

 private:
  std::string compare_;
};

class CurveCommand {
 public:
  void add_to(CLI::App& app);
  bool chosen() const { return command_ && command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_ = nullptr;
  std::optional<double> alpha_;
  std::vector<std::string> points_;
  bool inflection_start_ = false;
  int samples_ = 64;
  std::string format_ = "json";
  std::string output_;
};

class CheckCommand {
 public:
  void add_to(CLI::App& app);
  bool chosen() const { return command_ && command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_ = nullptr;
  std::vector<std::string> sources_;
  SourceArguments selection_;
  std::string format_ = "text";
  std::string profile_ = "text";
  std::string fail_on_ = "error";
  int jobs_ = 0;
  std::string output_;
};

}  // namespace gf
