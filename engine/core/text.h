#pragma once
// Text from input files is data: it is shown escaped and checked before it becomes a name.

#include <string>
#include <string_view>

namespace garment {

// `text` as it may be shown on a terminal or in a dialog: control characters (C0, DEL, the C1
// range U+0080..U+009F, and the line and paragraph separators U+2028, U+2029) and bytes that are
// not valid UTF-8 become \xNN escapes, one per byte; printable UTF-8 is kept as is. Every error
// message that quotes an input file's text goes through it (throw_input_error does so for its
// place and message), so that a name cannot move the cursor, clear the screen or start a new line
// of the message. printable(printable(t)) == printable(t): escaping twice does no harm.
std::string printable(std::string_view text);

// Why `name` cannot be the name of a panel (piece), or "" when it can. A name is written as is
// into every export (a `g` line of an OBJ, a glTF mesh name, the report), so it must be non-empty,
// valid UTF-8, free of the characters printable() escapes (a line break would end the `g` line
// and shift every later vertex index), and must not begin or end with a space or tab, which an OBJ
// `g` line does not keep.
std::string name_fault(std::string_view name);

}  // namespace garment
