#pragma once
// One function per garment-init command; each returns its exit code (command_line.h) and throws
// UsageError for bad usage and garment::InputError for bad input, which main() turns into exit
// codes.

#include <string>
#include <vector>

namespace garment::cli {

struct Command {
  const char* name;
  const char* synopsis;  // one line: arguments and options
  const char* help;      // what it does and prints
  int (*run)(const std::vector<std::string>& args);
};

int inspect_command(const std::vector<std::string>& args);
int run_command(const std::vector<std::string>& args);
int batch_command(const std::vector<std::string>& args);
int summary_command(const std::vector<std::string>& args);
int body_command(const std::vector<std::string>& args);
int check_command(const std::vector<std::string>& args);
int flat_command(const std::vector<std::string>& args);
int quilt_command(const std::vector<std::string>& args);
int seed_command(const std::vector<std::string>& args);
int train_classifier_command(const std::vector<std::string>& args);
int classify_eval_command(const std::vector<std::string>& args);

}  // namespace garment::cli
