// Apple property lists, the small part UFO 3 uses: dictionaries, arrays, strings, integers,
// reals and booleans, read and written with pugixml.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace gf {

struct PlistValue;
using PlistArray = std::vector<PlistValue>;
using PlistDict = std::map<std::string, PlistValue>;

struct PlistValue {
  std::variant<std::string, long long, double, bool, std::shared_ptr<PlistArray>, std::shared_ptr<PlistDict>> value;

  const std::string* string() const { return std::get_if<std::string>(&value); }
  std::optional<double> number() const;
  const PlistArray* array() const;
  const PlistDict* dict() const;
};

PlistValue plist_array(PlistArray a);
PlistValue plist_dict(PlistDict d);

/// Throws InputError naming the file when it is missing or not a property list.
PlistValue read_plist(const std::filesystem::path& path);
std::string plist_to_xml(const PlistValue& root);

}  // namespace gf
