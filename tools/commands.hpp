// The subcommands: each adds itself to the application and runs when chosen.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "source_options.hpp"

namespace gf {

/// A subcommand of the application, which knows whether it was chosen.
class Command {
 public:
  bool chosen() const { return command_ && command_->parsed(); }

 protected:
  CLI::App* command_ = nullptr;
};

/// What the outline subcommands share: a source, a selection and an output.
class Subcommand : public Command {
 protected:
  CLI::App& add(CLI::App& app, const char* name, const char* description, const char* output_help);

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

class CurveCommand : public Command {
 public:
  void add_to(CLI::App& app);
  int run() const;

 private:
  std::string segment() const;        ///< --points: the log-aesthetic segment, as text
  std::string interpolation() const;  ///< --through: the G3 interpolating curve, as text

  std::optional<double> alpha_;
  std::vector<std::string> points_;
  bool inflection_start_ = false;
  std::vector<std::string> through_, curvatures_, slopes_, angles_;
  int samples_ = 64;
  std::string format_ = "json";
  std::string output_;
};

class FairCommand : public Subcommand {
 public:
  void add_to(CLI::App& app);
  int run() const;

 private:
  std::string profile_ = "text";
  std::string continuity_ = "g2";
  std::optional<double> tolerance_;
  std::optional<double> corner_angle_;
  bool round_ = false;
  bool no_round_ = false;
  std::string proof_;
  std::string segments_;
  int jobs_ = 0;
};

class CheckCommand : public Command {
 public:
  void add_to(CLI::App& app);
  int run() const;

 private:
  std::vector<std::string> sources_;
  SourceArguments selection_;
  std::string format_ = "text";
  std::string profile_ = "text";
  std::string fail_on_ = "error";
  int jobs_ = 0;
  std::string output_;
};

}  // namespace gf
