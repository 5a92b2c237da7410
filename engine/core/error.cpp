#include "engine/core/error.h"

namespace garment {

void throw_input_error(const std::string& file, const std::string& place,
                       const std::string& message) {
  std::string text = file.empty() ? std::string("<input>") : file;
  if (!place.empty()) text += ": " + place;
  text += ": " + message;
  throw InputError(text);
}

}  // namespace garment
