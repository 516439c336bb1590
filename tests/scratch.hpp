// A fresh scratch directory per test, so tests can run in parallel processes.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace gf::test {

inline std::filesystem::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string(info->test_suite_name()) + "." + info->name();
  for (char& c : name)
    if (c == '/') c = '_';
  const auto dir = std::filesystem::temp_directory_path() / "glyphfair-tests" / name;
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::filesystem::path scratch(const std::string& file) {
  const auto path = scratch_dir() / file;
  std::filesystem::remove_all(path);
  return path;
}

}  // namespace gf::test
