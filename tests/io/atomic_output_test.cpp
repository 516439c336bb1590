#include "io/atomic_output.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "io/input_error.hpp"
#include "scratch.hpp"

namespace gf {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir() {
  const fs::path dir = test::scratch_dir();
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::size_t entries(const fs::path& dir) { return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), {})); }

TEST(AtomicOutput, UncommittedLeavesNothing) {
  const fs::path dir = fresh_dir();
  {
    AtomicOutput out(dir / "a.pdf", AtomicOutput::Kind::file);
    std::ofstream(out.staging_path()) << "half";
  }
  EXPECT_EQ(entries(dir), 0u);
  {
    AtomicOutput out(dir / "b.ufo", AtomicOutput::Kind::directory);
    std::ofstream(out.staging_path() / "x") << "half";
  }
  EXPECT_EQ(entries(dir), 0u);
}

TEST(AtomicOutput, CommitReplacesAWholeDirectory) {
  const fs::path dir = fresh_dir();
  fs::create_directories(dir / "c.ufo");
  std::ofstream(dir / "c.ufo" / "stale") << "old";
  {
    AtomicOutput out(dir / "c.ufo", AtomicOutput::Kind::directory);
    std::ofstream(out.staging_path() / "new") << "new";
    out.commit();
  }
  EXPECT_TRUE(fs::exists(dir / "c.ufo" / "new"));
  EXPECT_FALSE(fs::exists(dir / "c.ufo" / "stale"));
  EXPECT_EQ(entries(dir), 1u);
}

TEST(AtomicOutput, NeverOverwritesAnInput) {
  const fs::path dir = fresh_dir();
  std::ofstream(dir / "in.ttf") << "font";
  const fs::path inputs[] = {dir / "in.ttf"};
  EXPECT_THROW(write_file_atomically(dir / "." / "in.ttf", "x", inputs), OutputError);
  std::ifstream in(dir / "in.ttf");
  EXPECT_EQ(std::string((std::istreambuf_iterator<char>(in)), {}), "font");
}

TEST(AtomicOutput, MissingDirectoryIsAnError) {
  EXPECT_THROW(write_file_atomically(fresh_dir() / "no" / "such.svg", "x"), OutputError);
}

}  // namespace
}  // namespace gf
