// garment-init: the headless face of garment-studio. Wiring only: each command lives in its own
// file.

#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "command_line.h"
#include "commands.h"
#include "engine/core/error.h"

namespace {

using garment::cli::Command;

const Command kCommands[] = {
    {"inspect", "inspect PATTERN.json [--json] [--edge-length M]",
     "Imports and meshes a GarmentCode pattern. Prints per piece its name, vertices, triangles "
     "and\n"
     "area (m²); per stitch its two sides and number of vertex pairs; darts; totals. --json prints "
     "one\n"
     "object {pieces, stitches, darts, vertices, triangles}.",
     garment::cli::inspect_command},
};

void print_help(std::ostream& out) {
  out << "usage: garment-init COMMAND [ARGS]\n\n"
         "Arranges the pieces of a sewing pattern around a body (Liu et al., SIGGRAPH 2024).\n\n"
         "Commands:\n";
  for (const Command& command : kCommands) {
    out << "  garment-init " << command.synopsis << "\n";
    std::string help = command.help;
    std::string line;
    for (char c : help + "\n") {
      if (c == '\n') {
        out << "      " << line << "\n";
        line.clear();
      } else {
        line += c;
      }
    }
    out << "\n";
  }
  out << "Exit status: 0 success, 1 bad input (the message names file and place), 2 bad usage,\n"
         "3 a garment was written but fails the quality check.\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    print_help(std::cerr);
    return garment::cli::kUsage;
  }
  if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    print_help(std::cout);
    return garment::cli::kSuccess;
  }
  for (const Command& command : kCommands) {
    if (args[0] != command.name) continue;
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    for (const std::string& word : rest) {
      if (word == "--help" || word == "-h") {
        std::cout << "usage: garment-init " << command.synopsis << "\n\n" << command.help << "\n";
        return garment::cli::kSuccess;
      }
    }
    try {
      return command.run(rest);
    } catch (const garment::cli::UsageError& error) {
      std::cerr << "garment-init " << command.name << ": " << error.what() << "\n"
                << "usage: garment-init " << command.synopsis << "\n";
      return garment::cli::kUsage;
    } catch (const garment::InputError& error) {
      std::cerr << "error: " << error.what() << "\n";
      return garment::cli::kBadInput;
    } catch (const std::bad_alloc&) {
      std::cerr << "error: out of memory\n";
      return garment::cli::kBadInput;
    } catch (const std::exception& error) {
      std::cerr << "error: " << error.what() << "\n";
      return garment::cli::kBadInput;
    }
  }
  std::cerr << "garment-init: unknown command '" << args[0] << "' (see garment-init --help)\n";
  return garment::cli::kUsage;
}
