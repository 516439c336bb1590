#include "io/sfnt_directory.hpp"

#include "io/input_error.hpp"

namespace gf {

std::optional<std::uint16_t> read_u16(std::span<const std::uint8_t> b, std::size_t o) {
  if (o + 2 > b.size()) return std::nullopt;
  return static_cast<std::uint16_t>(b[o] << 8 | b[o + 1]);
}

std::optional<std::uint32_t> read_u32(std::span<const std::uint8_t> b, std::size_t o) {
  if (o + 4 > b.size()) return std::nullopt;
  return static_cast<std::uint32_t>(b[o]) << 24 | static_cast<std::uint32_t>(b[o + 1]) << 16 |
         static_cast<std::uint32_t>(b[o + 2]) << 8 | b[o + 3];
}

std::optional<SfntDirectory> read_sfnt_directory(std::span<const std::uint8_t> bytes,
                                                 const std::string& file) {
  const auto version = read_u32(bytes, 0);
  if (!version) return std::nullopt;
  std::size_t base = 0;
  if (*version == 0x74746366u) {  // 'ttcf': a collection; glyphfair reads its first face
    const auto first = read_u32(bytes, 12);
    if (!first) throw InputError(file + ": truncated font collection header");
    base = *first;
  } else if (*version != 0x00010000u && *version != 0x4F54544Fu && *version != 0x74727565u) {
    return std::nullopt;  // not 1.0, 'OTTO' or 'true'
  }
  const auto num_tables = read_u16(bytes, base + 4);
  if (!num_tables || base + 12 + 16u * *num_tables > bytes.size())
    throw InputError(file + ": truncated font: the table directory extends past the end of the file");
  SfntDirectory dir;
  for (unsigned i = 0; i < *num_tables; ++i) {
    const std::size_t rec = base + 12 + 16u * i;
    std::string tag(reinterpret_cast<const char*>(bytes.data() + rec), 4);
    const std::uint32_t offset = *read_u32(bytes, rec + 8);
    const std::uint32_t length = *read_u32(bytes, rec + 12);
    if (std::uint64_t{offset} + length > bytes.size())
      throw InputError(file + ": truncated font: table '" + tag + "' needs " +
                       std::to_string(std::uint64_t{offset} + length) + " bytes, the file has " +
                       std::to_string(bytes.size()));
    dir.tables[tag] = {offset, length};
  }
  return dir;
}

}  // namespace gf
