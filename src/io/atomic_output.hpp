// Outputs appear whole or not at all: everything is written to a temporary sibling first and
// renamed into place on commit(); an uncommitted temporary is removed.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace gf {

class AtomicOutput {
 public:
  enum class Kind { file, directory };

  /// Refuses (OutputError) when `target` is one of `inputs`: inputs are never overwritten.
  AtomicOutput(std::filesystem::path target, Kind kind,
               std::span<const std::filesystem::path> inputs = {});
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;
  ~AtomicOutput();

  /// Where to write now: a file path or an (existing, empty) directory.
  const std::filesystem::path& staging_path() const { return staging_; }
  /// Replace the target with what was written.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path staging_;
  Kind kind_;
  bool committed_ = false;
};

/// Write bytes to a file atomically.
void write_file_atomically(const std::filesystem::path& target, const std::string& bytes,
                           std::span<const std::filesystem::path> inputs = {});

}  // namespace gf
