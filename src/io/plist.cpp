#include "io/plist.hpp"

#include <charconv>
#include <sstream>

#include <pugixml.hpp>

#include "io/input_error.hpp"

namespace gf {

std::optional<double> PlistValue::number() const {
  if (const auto* i = std::get_if<long long>(&value)) return static_cast<double>(*i);
  if (const auto* d = std::get_if<double>(&value)) return *d;
  return std::nullopt;
}
const PlistArray* PlistValue::array() const {
  const auto* p = std::get_if<std::shared_ptr<PlistArray>>(&value);
  return p ? p->get() : nullptr;
}
const PlistDict* PlistValue::dict() const {
  const auto* p = std::get_if<std::shared_ptr<PlistDict>>(&value);
  return p ? p->get() : nullptr;
}

PlistValue plist_array(PlistArray a) { return {std::make_shared<PlistArray>(std::move(a))}; }
PlistValue plist_dict(PlistDict d) { return {std::make_shared<PlistDict>(std::move(d))}; }

namespace {

PlistValue parse(const pugi::xml_node& n, const std::string& file) {
  const std::string name = n.name();
  if (name == "string") return {std::string(n.child_value())};
  if (name == "integer") return {n.text().as_llong()};
  if (name == "real") return {n.text().as_double()};
  if (name == "true") return {true};
  if (name == "false") return {false};
  if (name == "array") {
    PlistArray a;
    for (const pugi::xml_node c : n.children())
      if (c.type() == pugi::node_element) a.push_back(parse(c, file));
    return plist_array(std::move(a));
  }
  if (name == "dict") {
    PlistDict d;
    std::string key;
    for (const pugi::xml_node c : n.children()) {
      if (c.type() != pugi::node_element) continue;
      if (std::string(c.name()) == "key") key = c.child_value();
      else d[key] = parse(c, file);
    }
    return plist_dict(std::move(d));
  }
  if (name == "data" || name == "date") return {std::string(n.child_value())};
  throw InputError(file + ": unexpected <" + name + "> in a property list");
}

void emit(std::ostringstream& out, const PlistValue& v, int depth) {
  const std::string indent(static_cast<std::size_t>(depth), '\t');
  std::visit(
      [&](const auto& x) {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, std::string>) {
          pugi::xml_document doc;
          doc.append_child("string").text() = x.c_str();
          std::ostringstream s;
          doc.first_child().print(s, "", pugi::format_raw);
          out << indent << s.str() << "\n";
        } else if constexpr (std::is_same_v<T, long long>) {
          out << indent << "<integer>" << x << "</integer>\n";
        } else if constexpr (std::is_same_v<T, double>) {
          char buf[64];
          const auto r = std::to_chars(buf, buf + sizeof buf, x);
          out << indent << "<real>" << std::string(buf, r.ptr) << "</real>\n";
        } else if constexpr (std::is_same_v<T, bool>) {
          out << indent << (x ? "<true/>" : "<false/>") << "\n";
        } else if constexpr (std::is_same_v<T, std::shared_ptr<PlistArray>>) {
          out << indent << "<array>\n";
          for (const PlistValue& e : *x) emit(out, e, depth + 1);
          out << indent << "</array>\n";
        } else {
          out << indent << "<dict>\n";
          for (const auto& [k, e] : *x) {
            pugi::xml_document doc;
            doc.append_child("key").text() = k.c_str();
            std::ostringstream s;
            doc.first_child().print(s, "", pugi::format_raw);
            out << indent << "\t" << s.str() << "\n";
            emit(out, e, depth + 1);
          }
          out << indent << "</dict>\n";
        }
      },
      v.value);
}

}  // namespace

PlistValue read_plist(const std::filesystem::path& path) {
  pugi::xml_document doc;
  const pugi::xml_parse_result r = doc.load_file(path.c_str());
  if (!r) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw InputError(path.string() + ": missing");
    throw InputError(path.string() + ": not well-formed XML: " + r.description() + " at byte " + std::to_string(r.offset));
  }
  const pugi::xml_node root = doc.child("plist");
  pugi::xml_node first;
  for (const pugi::xml_node c : root.children())
    if (c.type() == pugi::node_element) { first = c; break; }
  if (!root || !first) throw InputError(path.string() + ": not a property list");
  return parse(first, path.string());
}

std::string plist_to_xml(const PlistValue& root) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<!DOCTYPE plist PUBLIC \"-//Apple//DTD PLIST 1.0//EN\" \"http://www.apple.com/DTDs/PropertyList-1.0.dtd\">\n"
         "<plist version=\"1.0\">\n";
  emit(out, root, 0);
  out << "</plist>\n";
  return out.str();
}

}  // namespace gf
