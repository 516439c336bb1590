#include "io/variation_location.hpp"

#include "io/input_error.hpp"
#include "io/number_format.hpp"
#include "io/text_list.hpp"

namespace gf {

std::vector<AxisValue> parse_variation_location(std::string_view spec) {
  std::vector<AxisValue> location;
  const std::vector<std::string_view> entries = split_trimmed(spec);
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const std::string_view entry = entries[k];
    if (entry.empty()) {
      if (k + 1 == entries.size()) break;  // a trailing comma
      throw InputError("--location: empty entry in '" + std::string(spec) + "'");
    }
    const std::size_t eq = entry.find('=');
    const std::string where = "--location: '" + std::string(entry) + "' ";
    if (eq == std::string_view::npos) throw InputError(where + "is not of the form TAG=VALUE");
    const std::string_view tag = entry.substr(0, eq);
    if (tag.empty() || tag.size() > 4) throw InputError(where + "has an axis tag that is not 1-4 characters");
    for (const char ch : tag)
      if (ch < 0x20 || ch > 0x7E) throw InputError(where + "has an axis tag with a non-ASCII character");
    const std::string_view number = entry.substr(eq + 1);
    const std::optional<double> value = parse_number(number);
    if (!value) throw InputError(where + "has a value that is not a number");
    std::string padded(tag);
    padded.resize(4, ' ');
    for (const AxisValue& a : location)
      if (a.tag == padded) throw InputError(where + "sets axis '" + std::string(tag) + "' twice");
    location.push_back({padded, *value});
  }
  if (location.empty()) throw InputError("--location: no axis values given");
  return location;
}

}  // namespace gf
