#pragma once
// Errors the engine reports for bad input. Bad input is normal input: every reader validates and
// throws InputError with a message that names the file and the place (panel, edge, stitch, line),
// so that the command line and the editor can show it as is.

#include <stdexcept>
#include <string>

namespace garment {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "<file>: <place>: <message>"; place may be empty. Place and message quote the file's text (names,
// values, lines): they are shown through printable(), so that control characters and invalid UTF-8
// are escaped (\x1b) instead of reaching the terminal raw.
[[noreturn]] void throw_input_error(const std::string& file, const std::string& place,
                                    const std::string& message);

// A request the engine refuses because it would exceed a resource budget (vertex count, memory).
class BudgetError : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace garment
