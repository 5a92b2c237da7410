#pragma once
// Argument handling shared by the garment-init commands: positional arguments, `--name value`
// options and `--switch` flags, with unknown or malformed arguments reported as usage errors (exit
// 2).

#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace garment::cli {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum ExitCode { kSuccess = 0, kBadInput = 1, kUsage = 2, kQualityFailed = 3 };

class CommandLine {
 public:
  // args: the words after the command name. `switches` take no value, `options` take one.
  CommandLine(const std::vector<std::string>& args, const std::set<std::string>& switches,
              const std::set<std::string>& options);

  const std::vector<std::string>& positional() const { return positional_; }
  // The single positional argument `what`, or a usage error.
  const std::string& only_positional(const std::string& what) const;
  bool has(const std::string& name) const;
  std::optional<std::string> value(const std::string& name) const;
  double number(const std::string& name, double fallback) const;
  int integer(const std::string& name, int fallback) const;
  // Comma-separated list ("a,b,c"), empty when absent.
  std::vector<std::string> list(const std::string& name) const;

 private:
  std::vector<std::string> positional_;
  std::set<std::string> switches_set_;
  std::map<std::string, std::string> values_;
};

}  // namespace garment::cli
