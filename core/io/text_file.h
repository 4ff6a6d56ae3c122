#pragma once
// Reading a whole file with one-line errors: only a regular file is read (a FIFO, device, socket or
// directory is refused by its type before it is opened for reading), never past the size `stat` gives,
// and its first bytes are checked against the expected format before the rest is read, so that a
// file that cannot be one (a device's zeros, a sparse file) is refused at once.
#include <functional>
#include <string>
#include <string_view>

namespace gps {

/// How many bytes of a file its format's check sees before the rest is read.
inline constexpr size_t kHeadBytes = 64 * 1024;

/// Throws gps::Error (without the path: the reader adds it) when `head`, the first bytes of a file
/// of `size` bytes (at most kHeadBytes of them), cannot begin a file of the expected format.
using HeadCheck = std::function<void(std::string_view head, size_t size)>;

/// The bytes of the regular file at `path`; throws gps::Error naming it when it cannot be read or
/// `check_head` refuses its first bytes.
std::string read_text_file(const std::string& path, const HeadCheck& check_head = {});

/// The UTF-8 byte order mark that some editors write at the start of a text file.
inline constexpr std::string_view kUtf8ByteOrderMark = "\xEF\xBB\xBF";

/// `text` without a UTF-8 byte order mark at its start (as it is where there is none).
void drop_byte_order_mark(std::string& text);

}  // namespace gps
