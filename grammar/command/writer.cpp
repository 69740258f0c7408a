#include "grammar/command/writer.hpp"

namespace lmgc::grammar {

std::string write_command(const CommandFile& file) {
  std::string out;
  for (std::size_t i = 0; i < file.lines.size(); ++i) {
    const CommandLine& line = file.lines[i];
    out.append(line.indent, ' ');
    out += line.text.value;
    out += line.trailer;
    const bool last = i + 1 == file.lines.size();
    if (!last || file.final_newline)
      out += line.crlf ? "\r\n" : "\n";
    else if (line.crlf)
      out += '\r';
  }
  return out;
}

}  // namespace lmgc::grammar
