#pragma once
// Typed errors with messages a user understands. Core throws these; the CLI prints them and exits
// non-zero, the GUI shows them and leaves the document unchanged.
#include <stdexcept>
#include <string>

namespace kerf {

// Bad input: a missing or corrupt file, a malformed project, a parameter out of range.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Long work stopped on request (std::stop_token). Not a failure: callers usually just discard results.
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled") {}
};

}  // namespace kerf
