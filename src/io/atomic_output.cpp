#include "io/atomic_output.hpp"

#include <fstream>
#include <random>
#include <system_error>

#include <unistd.h>

#include "io/input_error.hpp"

namespace fs = std::filesystem;

namespace gf {

namespace {

fs::path sibling(const fs::path& target, const char* what) {
  std::random_device rd;
  const auto tag = std::to_string(::getpid()) + "-" + std::to_string(rd() % 1000000);
  return target.parent_path() / ("." + target.filename().string() + "." + what + "-" + tag);
}

bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec);
  return fs::weakly_canonical(a, ec) == fs::weakly_canonical(b, ec);
}

}  // namespace

AtomicOutput::AtomicOutput(fs::path target, Kind kind, std::span<const fs::path> inputs)
    : target_(std::move(target)), kind_(kind) {
  for (const fs::path& input : inputs)
    if (same_file(input, target_))
      throw OutputError(target_.string() + ": refusing to overwrite an input");
  if (target_.filename().empty()) throw OutputError(target_.string() + ": not a file name");
  std::error_code ec;
  const fs::path dir = target_.parent_path().empty() ? fs::path(".") : target_.parent_path();
  if (!fs::is_directory(dir, ec))
    throw OutputError(target_.string() + ": directory " + dir.string() + " does not exist");
  staging_ = sibling(target_, "tmp");
  if (kind_ == Kind::directory && !fs::create_directory(staging_, ec))
    throw OutputError(target_.string() + ": cannot create a directory beside it: " + ec.message());
}

AtomicOutput::~AtomicOutput() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

void AtomicOutput::commit() {
  std::error_code ec;
  if (kind_ == Kind::file) {
    fs::rename(staging_, target_, ec);
    if (ec) throw OutputError(target_.string() + ": cannot move the finished file into place: " + ec.message());
  } else {
    // A directory cannot replace a non-empty one in one rename: move the old one aside first.
    fs::path old;
    if (fs::exists(target_, ec)) {
      old = sibling(target_, "old");
      fs::rename(target_, old, ec);
      if (ec) throw OutputError(target_.string() + ": cannot replace it: " + ec.message());
    }
    fs::rename(staging_, target_, ec);
    if (ec) {
      std::error_code ignored;
      if (!old.empty()) fs::rename(old, target_, ignored);
      throw OutputError(target_.string() + ": cannot move the finished directory into place: " + ec.message());
    }
    if (!old.empty()) fs::remove_all(old, ec);
  }
  committed_ = true;
}

void write_file_atomically(const fs::path& target, const std::string& bytes,
                           std::span<const fs::path> inputs) {
  AtomicOutput out(target, AtomicOutput::Kind::file, inputs);
  {
    std::ofstream f(out.staging_path(), std::ios::binary);
    f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    f.close();
    if (!f) throw OutputError(target.string() + ": write failed");
  }
  out.commit();
}

}  // namespace gf
