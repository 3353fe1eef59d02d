#pragma once
/// Every error mmvlab raises, in one place, sorted by whose fault it is and so by the
/// exit code the CLI gives (README, "Exit codes"):
///
///   the user's input              the numbers                 mmvlab or its installation
///   UsageError      64 (command)  NumericalError  1           InternalError     70
///   SceneError      65 (content)                              UnavailableError  69
///   SceneFileError  66 (file)
///   OutputError     73 (--out)
///   StdoutError     74 (standard output cannot be written: a full disk, a closed pipe)
///
/// A user error's what() is one line that points at the cause: for scene content
/// "file:line:col: what is wrong (got X)", for the command line the option and value.
/// A NumericalError names the trouble ("static equilibrium failed: ..."). An
/// InternalError is a broken invariant (a bug), never a consequence of input: input
/// is validated where it is read, before any model is built.
///
/// Two macros in the spirit of Drake's DRAKE_THROW_UNLESS / DRAKE_DEMAND:
///   MMV_THROW_UNLESS(cond, ErrorType, message)  user-facing precondition;
///   MMV_DEMAND(cond)                              internal invariant (InternalError
///                                                 with file:line and the condition).
/// Neither is compiled out, so no build type can turn a checked error into undefined
/// behaviour.

#include <stdexcept>
#include <string>

namespace mmv {

/// Bad command-line value (exit 64, EX_USAGE).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A request an analysis finds it cannot meet once the model is known (a mode number the
/// model does not have, more sensors than candidate stations). The option is kept apart
/// from the message so that each front end names it its own way (the command line
/// `--count`, Python `count`: the Python module's exception translator). Layers below
/// the studies (sim/app) throw this, never a plain UsageError naming an option
/// (tests/architecture_test.cpp).
class OptionError : public UsageError {
 public:
  /// `option` as the command line spells it ("--count"); `rest` follows it in the
  /// message (" 9: there are 8 candidate sensors", or ": no vibration mode below 5 Hz").
  OptionError(const std::string& option, const std::string& rest)
      : UsageError(option + rest), option_(option), rest_(rest) {}
  const std::string& option() const { return option_; }
  const std::string& rest() const { return rest_; }

 private:
  std::string option_, rest_;
};

/// Bad scene content (exit 65, EX_DATAERR). what(): "file:line:col: what is wrong (got X)".
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The scene file does not exist or cannot be read (exit 66, EX_NOINPUT).
class SceneFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Cannot create or write the output (exit 73, EX_CANTCREAT).
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Standard output cannot be written (exit 74, EX_IOERR): the result was not delivered,
/// so nothing is committed to --out either.
class StdoutError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The numbers cannot be trusted (exit 1); what() names the trouble.
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A part of the installation is missing, e.g. the SUNDIALS plugin (exit 69, EX_UNAVAILABLE).
class UnavailableError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A broken internal invariant: a bug in mmvlab (exit 70, EX_SOFTWARE).
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

namespace detail {
[[noreturn]] void throwInternal(const char* condition, const char* file, int line);
}  // namespace detail

}  // namespace mmv

/// Throws ErrorType(message) unless cond holds. For preconditions on user input.
#define MMV_THROW_UNLESS(cond, ErrorType, message) \
  do {                                             \
    if (!(cond)) throw ErrorType(message);         \
  } while (false)

/// Throws InternalError naming the condition, file and line unless cond holds. For
/// invariants that no input can break.
#define MMV_DEMAND(cond)                                                  \
  do {                                                                    \
    if (!(cond)) ::mmv::detail::throwInternal(#cond, __FILE__, __LINE__); \
  } while (false)
