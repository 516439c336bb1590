// The two ways a run can fail on its data, kept apart so the tools map them to exit codes.
#pragma once

#include <stdexcept>

namespace gf {

/// The input is missing, unreadable or malformed, or a request does not fit it. The message is
/// one line naming the file (and glyph) and the problem.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// An output could not be written. Nothing partial is left behind.
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace gf
