#include "engine/core/text.h"

#include <cstdint>

namespace garment {
namespace {

// The UTF-8 sequence starting at text[at]: its length in bytes, or 0 when it is not valid UTF-8
// (a stray continuation byte, an overlong form, a surrogate, beyond U+10FFFF, or cut short).
std::size_t sequence_length(std::string_view text, std::size_t at, std::uint32_t& code_point) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[at + k]); };
  const unsigned char lead = byte(0);
  if (lead < 0x80) {
    code_point = lead;
    return 1;
  }
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xbf;  // the valid range of the second byte
  if (lead >= 0xc2 && lead <= 0xdf) {
    length = 2;
    code_point = lead & 0x1fu;
  } else if (lead >= 0xe0 && lead <= 0xef) {
    length = 3;
    code_point = lead & 0x0fu;
    if (lead == 0xe0) low = 0xa0;   // overlong
    if (lead == 0xed) high = 0x9f;  // surrogates
  } else if (lead >= 0xf0 && lead <= 0xf4) {
    length = 4;
    code_point = lead & 0x07u;
    if (lead == 0xf0) low = 0x90;   // overlong
    if (lead == 0xf4) high = 0x8f;  // beyond U+10FFFF
  } else {
    return 0;
  }
  if (at + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    const unsigned char next = byte(k);
    if (next < (k == 1 ? low : 0x80) || next > (k == 1 ? high : 0xbf)) return 0;
    code_point = (code_point << 6) | (next & 0x3fu);
  }
  return length;
}

bool is_control(std::uint32_t code_point) {
  return code_point < 0x20 || (code_point >= 0x7f && code_point <= 0x9f) || code_point == 0x2028 ||
         code_point == 0x2029;
}

void append_escaped(std::string& out, std::string_view bytes) {
  static constexpr char kHex[] = "0123456789abcdef";
  for (const char c : bytes) {
    const auto byte = static_cast<unsigned char>(c);
    out += "\\x";
    out += kHex[byte >> 4];
    out += kHex[byte & 0xf];
  }
}

}  // namespace

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t at = 0; at < text.size();) {
    std::uint32_t code_point = 0;
    const std::size_t length = sequence_length(text, at, code_point);
    if (length == 0) {
      append_escaped(out, text.substr(at, 1));
      ++at;
      continue;
    }
    if (is_control(code_point))
      append_escaped(out, text.substr(at, length));
    else
      out.append(text.substr(at, length));
    at += length;
  }
  return out;
}

std::string name_fault(std::string_view name) {
  if (name.empty()) return "the name is empty";
  for (std::size_t at = 0; at < name.size();) {
    std::uint32_t code_point = 0;
    const std::size_t length = sequence_length(name, at, code_point);
    if (length == 0) return "the name is not valid UTF-8";
    if (is_control(code_point))
      return "the name contains the control character " + printable(name.substr(at, length));
    at += length;
  }
  if (name.front() == ' ' || name.back() == ' ')
    return "the name begins or ends with a space, which an OBJ `g` line does not keep";
  return "";
}

}  // namespace garment
