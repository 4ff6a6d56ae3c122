#pragma once
// Text from files and paths as one-line messages show it: every byte a terminal could act on, and
// every byte that is not UTF-8, written as \xNN, so that a message is one harmless line.
#include <string>
#include <string_view>

namespace gps {

/// How many characters of a token from a file a message shows before it cuts it with "…".
inline constexpr size_t kMaxQuotedCharacters = 40;

/// `text` with control bytes (C0, DEL and the C1 controls U+0080–U+009F) and bytes that are not
/// UTF-8 written as \xNN; everything else as given. For paths and whole messages: nothing is cut.
std::string escaped(std::string_view text);

/// A token or line from a file for a message: escaped, between single quotes, and cut after
/// kMaxQuotedCharacters characters with "…".
std::string quoted_token(std::string_view token);

}  // namespace gps
