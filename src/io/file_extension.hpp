// A path's extension, compared without regard to case: every format choice by file name
// (sources, outline outputs, proofs) reads it the same way.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace gf {

/// The extension of `path`, lower case (".pdf"; empty when it has none).
inline std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace gf
