#include "command_line.h"

#include <cmath>
#include <sstream>

namespace garment::cli {

CommandLine::CommandLine(const std::vector<std::string>& args,
                         const std::set<std::string>& switches,
                         const std::set<std::string>& options) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& word = args[i];
    if (word.size() > 1 && word[0] == '-' &&
        !(word.size() > 1 && std::isdigit(static_cast<unsigned char>(word[1])))) {
      std::string name = word;
      std::optional<std::string> inline_value;
      if (const auto equals = word.find('='); equals != std::string::npos) {
        name = word.substr(0, equals);
        inline_value = word.substr(equals + 1);
      }
      if (switches.count(name)) {
        if (inline_value) throw UsageError(name + " takes no value");
        switches_set_.insert(name);
      } else if (options.count(name)) {
        if (inline_value) {
          values_[name] = *inline_value;
        } else {
          if (i + 1 >= args.size()) throw UsageError(name + " needs a value");
          values_[name] = args[++i];
        }
      } else {
        throw UsageError("unknown option " + name);
      }
    } else {
      positional_.push_back(word);
    }
  }
}

const std::string& CommandLine::only_positional(const std::string& what) const {
  if (positional_.size() != 1)
    throw UsageError("expected exactly one " + what + ", got " +
                     std::to_string(positional_.size()) + " arguments");
  return positional_[0];
}

bool CommandLine::has(const std::string& name) const {
  return switches_set_.count(name) || values_.count(name);
}

std::optional<std::string> CommandLine::value(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

double CommandLine::number(const std::string& name, double fallback) const {
  const auto text = value(name);
  if (!text) return fallback;
  std::istringstream in(*text);
  double result = 0.0;
  if (!(in >> result) || !in.eof() || !std::isfinite(result))
    throw UsageError(name + " needs a number, got '" + *text + "'");
  return result;
}

int CommandLine::integer(const std::string& name, int fallback) const {
  const auto text = value(name);
  if (!text) return fallback;
  std::istringstream in(*text);
  int result = 0;
  if (!(in >> result) || !in.eof())
    throw UsageError(name + " needs an integer, got '" + *text + "'");
  return result;
}

std::vector<std::string> CommandLine::list(const std::string& name) const {
  std::vector<std::string> items;
  const auto text = value(name);
  if (!text) return items;
  std::istringstream in(*text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) items.push_back(item);
  return items;
}

}  // namespace garment::cli
