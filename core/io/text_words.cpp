#include "core/io/text_words.h"

#include <cctype>

namespace gps {

namespace {
bool is_space(char c) { return std::isspace((unsigned char)c); }
}  // namespace

std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    size_t j = i;
    while (j < line.size() && !is_space(line[j])) ++j;
    if (j > i) words.push_back(line.substr(i, j - i));
    i = j;
  }
  return words;
}

std::string_view next_word(std::string_view& line) {
  size_t i = 0;
  while (i < line.size() && is_space(line[i])) ++i;
  size_t j = i;
  while (j < line.size() && !is_space(line[j])) ++j;
  const std::string_view word = line.substr(i, j - i);
  line.remove_prefix(j);
  return word;
}

void WordCursor::advance() {
  for (;;) {
    while (pos_ < text_.size() && is_space(text_[pos_])) line_ += text_[pos_++] == '\n';
    if (pos_ < text_.size() && text_[pos_] == '#') {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
      continue;
    }
    break;
  }
  const size_t begin = pos_;
  while (pos_ < text_.size() && !is_space(text_[pos_]) && text_[pos_] != '#') ++pos_;
  word_ = std::string_view(text_).substr(begin, pos_ - begin);
}

}  // namespace gps
