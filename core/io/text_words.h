#pragma once
// The words of the text file formats (OBJ, OFF, ASCII STL, PLY): runs of characters between white
// space, as the C locale's isspace separates them. One place for every reader's tokenizing.
#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

namespace gps {

/// The whitespace-separated words of one line, as views into it.
std::vector<std::string_view> words_of(std::string_view line);

/// The first word of `line` (empty when there is none), which is then cut off `line`.
std::string_view next_word(std::string_view& line);

/// The lines of a text one at a time as views into it, with their numbers from 1: no copy of a line,
/// however long. A line ends at '\n', "\r\n" or a lone '\r' (old Mac files), the end not in the line.
class LineCursor {
public:
  explicit LineCursor(std::string_view text) : text_(text) { advance(); }
  bool done() const { return begin_ >= text_.size(); }
  std::string_view line() const { return line_; }
  int number() const { return number_; }
  void next() {
    begin_ = next_begin_;
    advance();
  }

private:
  void advance() {
    ++number_;
    if (done()) return;
    const size_t newline = std::min(text_.find('\n', begin_), text_.size());
    const size_t cr = text_.substr(begin_, newline - begin_).find('\r');
    end_ = cr == std::string_view::npos ? newline : begin_ + cr;
    next_begin_ = end_ + (end_ + 1 == newline ? 2 : 1);  // "\r\n" is one end
    line_ = text_.substr(begin_, end_ - begin_);
  }
  std::string_view text_;
  size_t begin_ = 0, end_ = 0, next_begin_ = 0;
  int number_ = 0;
  std::string_view line_;
};

/// The words of a whole text one at a time with their line numbers, '#' comments skipped (OFF). No
/// word list: memory stays that of the text, whatever a hostile file's lines hold.
class WordCursor {
public:
  explicit WordCursor(const std::string& text) : text_(text) { advance(); }
  bool done() const { return word_.empty(); }
  std::string_view word() const { return word_; }
  int line() const { return line_; }
  void next() { advance(); }
  /// Skips the remaining words of line `line` (extra values: normals, colours).
  void skip_line(int line) {
    while (!done() && line_ == line) advance();
  }

private:
  void advance();
  const std::string& text_;
  size_t pos_ = 0;
  int line_ = 1;
  std::string_view word_;
};

}  // namespace gps
