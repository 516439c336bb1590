// The table directory of an OpenType/TrueType file, read from its bytes, so that truncated
// files are refused with a precise message before any table is used.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>

namespace gf {

struct SfntTable {
  std::uint32_t offset = 0;
  std::uint32_t length = 0;
};

struct SfntDirectory {
  std::map<std::string, SfntTable> tables;  // by four-character tag
};

/// nullopt when the bytes do not start like an sfnt (then it is not an OpenType font, though
/// FreeType may still read it, e.g. as WOFF or Type 1). Throws InputError naming `file` when
/// the directory or a table extends past the end of the bytes.
std::optional<SfntDirectory> read_sfnt_directory(std::span<const std::uint8_t> bytes,
                                                 const std::string& file);

/// Big-endian readers that return nullopt past the end instead of reading out of bounds.
std::optional<std::uint16_t> read_u16(std::span<const std::uint8_t> bytes, std::size_t offset);
std::optional<std::uint32_t> read_u32(std::span<const std::uint8_t> bytes, std::size_t offset);

}  // namespace gf
