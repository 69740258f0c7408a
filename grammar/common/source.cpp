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

std::string_view SourceText::line_text(std::uint32_t number) const {
  if (number == 0 || number > lines_.size()) return {};
  return lines_[number - 1].text;
}

}  // namespace lmgc::grammar
