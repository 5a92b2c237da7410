#include "engine/core/error.h"

#include "engine/core/text.h"

namespace garment {

void throw_input_error(const std::string& file, const std::string& place,
                       const std::string& message) {
  std::string text = file.empty() ? std::string("<input>") : file;
  if (!place.empty()) text += ": " + printable(place);
  text += ": " + printable(message);
  throw InputError(text);
}

}  // namespace garment
