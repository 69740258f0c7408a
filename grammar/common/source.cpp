#include "grammar/common/source.hpp"

namespace lmgc::grammar {

SourceText::SourceText(std::string path, std::string text) : path_(std::move(path)), text_(std::move(text)) {
  std::string_view all(text_);
  std::size_t begin = 0;
  std::uint32_t number = 1;
  while (begin < all.size()) {
    std::size_t end = all.find('\n', begin);
    const bool has_newline = end != std::string_view::npos;
    if (!has_newline) end = all.size();
    std::size_t stop = end;
    if (stop > begin && all[stop - 1] == '\r') --stop;  // CRLF record terminator
    lines_.push_back(Line{all.substr(begin, stop - begin), number++});
    if (!has_newline) {
      final_newline_ = false;
      break;
    }
    begin = end + 1;
  }
}

SourceText::SourceText(const SourceText& other)
    : path_(other.path_), text_(other.text_), lines_(other.lines_), final_newline_(other.final_newline_) {
  rebase(other.text_.data());
}

SourceText::SourceText(SourceText&& other) noexcept
    : path_(std::move(other.path_)), lines_(std::move(other.lines_)), final_newline_(other.final_newline_) {
  const char* old_text = other.text_.data();
  text_ = std::move(other.text_);
  rebase(old_text);
}

SourceText& SourceText::operator=(const SourceText& other) {
  if (this != &other) *this = SourceText(other);
  return *this;
}

SourceText& SourceText::operator=(SourceText&& other) noexcept {
  if (this == &other) return *this;
  path_ = std::move(other.path_);
  lines_ = std::move(other.lines_);
  final_newline_ = other.final_newline_;
  const char* old_text = other.text_.data();
  text_ = std::move(other.text_);
  rebase(old_text);
  return *this;
}

void SourceText::rebase(const char* old_text) {
  if (old_text == text_.data()) return;
  for (Line& line : lines_)
    line.text = std::string_view(text_.data() + (line.text.data() - old_text), line.text.size());
}

std::string_view SourceText::line_text(std::uint32_t number) const {
  if (number == 0 || number > lines_.size()) return {};
  return lines_[number - 1].text;
}

}  // namespace lmgc::grammar
