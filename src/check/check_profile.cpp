#include "check/check_profile.hpp"

#include <utility>

namespace gf {

const char* to_string(Severity s) {
  switch (s) {
    case Severity::info: return "info";
    case Severity::warning: return "warning";
    case Severity::error: return "error";
  }
  return "info";
}

namespace {

// Every check in report order, with its severity for professional text fonts.
constexpr std::pair<const char*, Severity> checks[] = {
    {"open-contour", Severity::error},         {"wrong-direction", Severity::error},
    {"duplicate-point", Severity::error},      {"kink", Severity::error},
    {"g2-jump", Severity::warning},            {"missing-extremum", Severity::warning},
    {"wobble", Severity::warning},             {"inflection-in-segment", Severity::info},
    {"short-segment", Severity::warning},      {"zero-handle", Severity::warning},
    {"collinear-handles", Severity::warning},  {"semi-horizontal", Severity::warning},
    {"semi-vertical", Severity::warning}};

}  // namespace

const std::vector<std::string>& check_ids() {
  static const std::vector<std::string> ids = [] {
    std::vector<std::string> out;
    for (const auto& [id, severity] : checks) out.emplace_back(id);
    return out;
  }();
  return ids;
}

Severity CheckProfile::severity_of(const std::string& check) const {
  const auto it = severity.find(check);
  return it == severity.end() ? Severity::warning : it->second;
}

std::optional<CheckProfile> check_profile(const std::string& name) {
  CheckProfile p;
  p.name = name;
  for (const auto& [id, severity] : checks) p.severity[id] = severity;
  if (name == "text") return p;
  if (name != "handwriting") return std::nullopt;
  // Traced and pen-drawn letters break their curves at many joins and leave extrema between
  // nodes by design; those become information, structural problems stay as they are.
  for (const char* id : {"kink", "g2-jump", "missing-extremum", "short-segment", "zero-handle", "semi-horizontal",
                         "semi-vertical"}) {
    p.severity[id] = Severity::info;
    p.relaxed.push_back(std::string(id) + " reported as info");
  }
  p.severity["duplicate-point"] = Severity::warning;
  p.relaxed.push_back("duplicate-point reported as a warning");
  return p;
}

}  // namespace gf
