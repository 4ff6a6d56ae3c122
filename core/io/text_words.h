#pragma once
// The words of the text file formats (OBJ, OFF, ASCII STL, PLY): runs of characters between white
// space, as the C locale's isspace separates them. One place for every reader's tokenizing.
#include <string>
#include <string_view>
#include <vector>

namespace gps {

/// The whitespace-separated words of one line, as views into it.
std::vector<std::string_view> words_of(std::string_view line);

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
