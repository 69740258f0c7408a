// command.py, read without running it (script.hpp). Logical lines (brackets and backslashes join
// physical ones), indentation blocks, a small expression evaluator for literal arithmetic.
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <set>
#include <string_view>

#include "grammar/command_py/script.hpp"

namespace lmgc::grammar {
namespace {

struct Position {
  std::uint32_t line = 0;
  std::uint16_t column = 0;
};

// One logical line: its text (comments removed) and where each of its characters came from.
struct LogicalLine {
  std::string text;
  std::vector<Position> origin;  // origin[k] is the position of text[k]
  std::size_t indent = 0;
};

bool identifier_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool identifier_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

std::vector<LogicalLine> logical_lines(std::string_view text) {
  std::vector<LogicalLine> out;
  LogicalLine current;
  int depth = 0;
  bool continued = false;
  std::uint32_t number = 0;
  std::size_t begin = 0;
  char quote = 0;  // inside a string spanning lines (triple quotes are read as strings too)
  while (begin <= text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(begin, end - begin);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    ++number;
    const bool fresh = depth == 0 && !continued && quote == 0;
    if (fresh) {
      current = LogicalLine{};
      std::size_t indent = 0;
      while (indent < line.size() && (line[indent] == ' ' || line[indent] == '\t')) ++indent;
      current.indent = indent;
    }
    continued = false;
    for (std::size_t k = 0; k < line.size(); ++k) {
      const char c = line[k];
      if (quote) {
        if (c == '\\' && k + 1 < line.size()) {
          current.text += c;
          current.origin.push_back({number, static_cast<std::uint16_t>(std::min<std::size_t>(k + 1, 65535))});
          ++k;
        } else if (c == quote) {
          quote = 0;
        }
      } else if (c == '#') {
        break;
      } else if (c == '\'' || c == '"') {
        quote = c;
      } else if (c == '(' || c == '[' || c == '{') {
        ++depth;
      } else if (c == ')' || c == ']' || c == '}') {
        depth = depth > 0 ? depth - 1 : 0;
      } else if (c == '\\' && k + 1 == line.size()) {
        continued = true;
        break;
      }
      current.text += c;
      current.origin.push_back({number, static_cast<std::uint16_t>(std::min<std::size_t>(k + 1, 65535))});
    }
    // A string left open at the end of a line ends there (Python would need a triple quote).
    if (quote && !continued) quote = 0;
    if (depth == 0 && !continued) {
      const auto first = current.text.find_first_not_of(" \t");
      if (first != std::string::npos) out.push_back(current);
    } else {
      current.text += ' ';
      current.origin.push_back(
          {number, static_cast<std::uint16_t>(std::min<std::size_t>(line.size() + 1, 65535))});
    }
    if (end == text.size()) break;
    begin = end + 1;
  }
  if (depth > 0 && current.text.find_first_not_of(" \t") != std::string::npos) out.push_back(current);
  return out;
}

// Literal arithmetic: numbers, strings, names bound to literals, + - * / // % ** and brackets.
class Evaluator {
 public:
  Evaluator(std::string_view text, const std::map<std::string, ScriptValue>& names)
      : s_(text), names_(names) {}

  ScriptValue evaluate() {
    ScriptValue v = sum();
    skip();
    if (p_ != s_.size()) return {};
    return v;
  }

 private:
  void skip() {
    while (p_ < s_.size() && (s_[p_] == ' ' || s_[p_] == '\t')) ++p_;
  }
  bool eat(std::string_view token) {
    skip();
    if (s_.substr(p_, token.size()) != token) return false;
    p_ += token.size();
    return true;
  }
  static ScriptValue number(double x) {
    ScriptValue v;
    if (std::isfinite(x)) v.number = x;
    return v;
  }
  ScriptValue sum() {
    ScriptValue left = product();
    for (;;) {
      skip();
      if (p_ < s_.size() && (s_[p_] == '+' || s_[p_] == '-')) {
        const char op = s_[p_++];
        const ScriptValue right = product();
        if (left.text && right.text && op == '+') {
          left.text = *left.text + *right.text;
          continue;
        }
        if (!left.number || !right.number) return {};
        left = number(op == '+' ? *left.number + *right.number : *left.number - *right.number);
      } else {
        return left;
      }
    }
  }
  ScriptValue product() {
    ScriptValue left = unary();
    for (;;) {
      skip();
      if (s_.substr(p_, 2) == "**") return left;  // handled in power()
      if (p_ < s_.size() && (s_[p_] == '*' || s_[p_] == '/' || s_[p_] == '%')) {
        char op = s_[p_++];
        bool floor_division = false;
        if (op == '/' && p_ < s_.size() && s_[p_] == '/') {
          ++p_;
          floor_division = true;
        }
        const ScriptValue right = unary();
        if (!left.number || !right.number) return {};
        const double a = *left.number, b = *right.number;
        if (op == '*') {
          left = number(a * b);
        } else if (b == 0.0) {
          return {};
        } else if (op == '%') {
          left = number(a - b * std::floor(a / b));
        } else {
          left = number(floor_division ? std::floor(a / b) : a / b);
        }
      } else {
        return left;
      }
    }
  }
  ScriptValue unary() {
    if (eat("-")) {
      const ScriptValue v = unary();
      return v.number ? number(-*v.number) : ScriptValue{};
    }
    if (eat("+")) return unary();
    return power();
  }
  ScriptValue power() {
    ScriptValue base = atom();
    if (eat("**")) {
      const ScriptValue exponent = unary();
      if (!base.number || !exponent.number) return {};
      return number(std::pow(*base.number, *exponent.number));
    }
    return base;
  }
  ScriptValue atom() {
    skip();
    if (p_ >= s_.size()) return {};
    const char c = s_[p_];
    if (c == '(') {
      ++p_;
      ScriptValue v = sum();
      if (!eat(")")) return {};
      return v;
    }
    if (c == '\'' || c == '"') {
      std::string text;
      ++p_;
      while (p_ < s_.size() && s_[p_] != c) {
        if (s_[p_] == '\\' && p_ + 1 < s_.size()) ++p_;
        text += s_[p_++];
      }
      if (p_ >= s_.size()) return {};
      ++p_;
      ScriptValue v;
      v.text = text;
      return v;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      std::string digits;
      const std::size_t start = p_;
      while (p_ < s_.size() &&
             (std::isdigit(static_cast<unsigned char>(s_[p_])) || s_[p_] == '.' || s_[p_] == '_'))
        ++p_;
      if (p_ < s_.size() && (s_[p_] == 'e' || s_[p_] == 'E')) {
        ++p_;
        if (p_ < s_.size() && (s_[p_] == '+' || s_[p_] == '-')) ++p_;
        while (p_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[p_]))) ++p_;
      }
      for (std::size_t k = start; k < p_; ++k)
        if (s_[k] != '_') digits += s_[k];
      char* stop = nullptr;
      const double x = std::strtod(digits.c_str(), &stop);
      if (digits.empty() || stop != digits.c_str() + digits.size()) return {};
      return number(x);
    }
    if (identifier_start(c)) {
      const std::size_t start = p_;
      while (p_ < s_.size() && (identifier_char(s_[p_]) || s_[p_] == '.')) ++p_;
      const std::string name(s_.substr(start, p_ - start));
      skip();
      if (p_ < s_.size() && s_[p_] == '(') return {};  // a call: not a literal
      if (name == "True") return number(1.0);
      if (name == "False") return number(0.0);
      const auto it = names_.find(name);
      return it == names_.end() ? ScriptValue{} : it->second;
    }
    return {};
  }

  std::string_view s_;
  const std::map<std::string, ScriptValue>& names_;
  std::size_t p_ = 0;
};

// Splits "a, b=(1, 2), c" at top-level commas.
std::vector<std::string> split_arguments(std::string_view text) {
  std::vector<std::string> parts;
  std::string current;
  int depth = 0;
  char quote = 0;
  for (char c : text) {
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '(' || c == '[' || c == '{') {
      ++depth;
    } else if (c == ')' || c == ']' || c == '}') {
      --depth;
    } else if (c == ',' && depth == 0) {
      parts.push_back(current);
      current.clear();
      continue;
    }
    current += c;
  }
  if (current.find_first_not_of(" \t") != std::string::npos) parts.push_back(current);
  return parts;
}

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t");
  return std::string(s.substr(b, e - b + 1));
}

bool starts_with_word(std::string_view text, std::string_view word) {
  return text.substr(0, word.size()) == word &&
         (text.size() == word.size() || !identifier_char(text[word.size()]));
}

// The closing bracket matching the '(' at `open`, or npos.
std::size_t closing_bracket(std::string_view text, std::size_t open) {
  int depth = 0;
  char quote = 0;
  for (std::size_t k = open; k < text.size(); ++k) {
    const char c = text[k];
    if (quote) {
      if (c == '\\')
        ++k;
      else if (c == quote)
        quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '(') {
      ++depth;
    } else if (c == ')' && --depth == 0) {
      return k;
    }
  }
  return std::string_view::npos;
}

const std::set<std::string, std::less<>> kPythonBuiltins = {
    "range",      "print",     "len",  "int",     "float",   "str",   "open",   "abs",   "min",
    "max",        "enumerate", "zip",  "list",    "dict",    "tuple", "set",    "round", "sum",
    "isinstance", "format",    "exit", "sorted",  "bool",    "map",   "filter", "any",   "all",
    "iter",       "next",      "type", "getattr", "hasattr", "super", "repr"};

enum class BlockKind { conditional, loop, plain };

}  // namespace

std::vector<const ScriptCall*> CommandScript::calls_to(std::string_view name) const {
  std::vector<const ScriptCall*> found;
  for (const ScriptCall& c : calls)
    if (c.name == name) found.push_back(&c);
  return found;
}

const ScriptLoop* CommandScript::step_loop() const {
  for (const ScriptLoop& loop : loops)
    if (loop.steps) return &loop;
  return nullptr;
}

const ScriptArgument* script_argument(const ScriptCall& call, std::size_t position,
                                      std::string_view keyword) {
  std::size_t positional = 0;
  for (const ScriptArgument& a : call.arguments) {
    if (!a.keyword.empty()) {
      if (!keyword.empty() && a.keyword == keyword) return &a;
      continue;
    }
    if (positional++ == position) return &a;
  }
  return nullptr;
}

CommandScript read_command_script(std::string path, std::string_view text) {
  CommandScript script;
  script.path = std::move(path);
  const std::vector<LogicalLine> lines = logical_lines(text);
  bool star_import = false;
  struct Block {
    std::size_t indent;
    BlockKind kind;
    std::size_t loop;  // index in script.loops, for loops
  };
  std::vector<Block> blocks;
  std::map<std::string, ScriptValue> names;  // bindings as the script reads them

  for (const LogicalLine& line : lines) {
    while (!blocks.empty() && blocks.back().indent >= line.indent) blocks.pop_back();
    const std::string statement = trim(line.text);
    const std::size_t offset = line.text.find_first_not_of(" \t");
    bool conditional = false, in_loop = false;
    for (const Block& b : blocks) {
      conditional |= b.kind == BlockKind::conditional;
      in_loop |= b.kind == BlockKind::loop;
    }
    if (statement.find("import") != std::string::npos && statement.find("chipy") != std::string::npos &&
        statement.find('*') != std::string::npos)
      star_import = true;

    // Block headers.
    static constexpr std::string_view kConditionalHeads[] = {"if",      "elif", "else", "try",  "except",
                                                             "finally", "def",  "with", "class"};
    std::optional<BlockKind> opens;
    for (std::string_view head : kConditionalHeads)
      if (starts_with_word(statement, head)) opens = BlockKind::conditional;
    const bool is_for = starts_with_word(statement, "for"), is_while = starts_with_word(statement, "while");
    std::size_t loop_index = 0;
    if (is_for || is_while) {
      opens = BlockKind::loop;
      ScriptLoop loop;
      loop.line = line.origin.empty() ? 0 : line.origin[offset].line;
      loop.header = statement;
      const std::size_t range = statement.find("range(");
      if (is_for && range != std::string::npos) {
        const std::size_t open = range + 5, close = closing_bracket(statement, open);
        if (close != std::string::npos) {
          std::vector<double> bounds;
          bool all = true;
          for (const std::string& part :
               split_arguments(std::string_view(statement).substr(open + 1, close - open - 1))) {
            const ScriptValue v = Evaluator(part, names).evaluate();
            if (!v.number)
              all = false;
            else
              bounds.push_back(*v.number);
          }
          if (all && !bounds.empty() && bounds.size() <= 3) {
            double start = 0, stop = 0, step = 1;
            if (bounds.size() == 1)
              stop = bounds[0];
            else
              start = bounds[0], stop = bounds[1];
            if (bounds.size() == 3) step = bounds[2];
            if (step != 0) {
              const double n = std::ceil((stop - start) / step);
              loop.count = static_cast<std::int64_t>(std::max(0.0, n));
            }
          }
        }
      }
      if (conditional) loop.count.reset();
      loop_index = script.loops.size();
      script.loops.push_back(loop);
    }

    // Calls anywhere on the line (headers included: 'while chipy.TimeEvolution_GetTime() < t').
    const std::string_view s = line.text;
    for (std::size_t k = 0; k < s.size(); ++k) {
      if (!identifier_start(s[k]) || (k > 0 && identifier_char(s[k - 1]))) continue;
      std::size_t e = k;
      while (e < s.size() && identifier_char(s[e])) ++e;
      const std::string name(s.substr(k, e - k));
      const bool qualified =
          k >= 6 && s.substr(k - 6, 6) == "chipy." && (k == 6 || !identifier_char(s[k - 7]));
      const bool after_dot = k > 0 && s[k - 1] == '.';
      std::size_t open = e;
      while (open < s.size() && s[open] == ' ') ++open;
      const bool called = open < s.size() && s[open] == '(';
      // chipy.Name(...), or Name(...) after 'from pylmgc90.chipy import *' (not a Python builtin).
      const bool chipy_call =
          called && (qualified || (!after_dot && star_import && !kPythonBuiltins.count(name)));
      if (!chipy_call) {
        k = e - 1;
        continue;
      }
      const std::size_t close = closing_bracket(s, open);
      ScriptCall call;
      call.name = name;
      call.line = line.origin[k].line;
      call.column = line.origin[k].column;
      call.conditional = conditional || (opens == BlockKind::conditional);
      call.in_loop = in_loop;
      if (close != std::string::npos)
        for (const std::string& part : split_arguments(s.substr(open + 1, close - open - 1))) {
          ScriptArgument argument;
          std::string expression = trim(part);
          const std::size_t eq = expression.find('=');
          if (eq != std::string::npos && eq > 0 && identifier_start(expression[0]) &&
              expression.find_first_not_of(
                  "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") == eq &&
              (eq + 1 >= expression.size() || expression[eq + 1] != '=')) {
            argument.keyword = trim(std::string_view(expression).substr(0, eq));
            expression = trim(std::string_view(expression).substr(eq + 1));
          }
          argument.expression = expression;
          argument.value = Evaluator(expression, names).evaluate();
          call.arguments.push_back(std::move(argument));
        }
      if (name == "IncrementStep")
        for (auto b = blocks.rbegin(); b != blocks.rend(); ++b)
          if (b->kind == BlockKind::loop) {
            script.loops[b->loop].steps = true;
            break;
          }
      script.calls.push_back(std::move(call));
      k = e - 1;
    }

    // Assignments: 'name = expression' (not '==', not augmented, not a keyword argument).
    if (!opens) {
      std::size_t e = 0;
      while (e < statement.size() && identifier_char(statement[e])) ++e;
      std::size_t eq = e;
      while (eq < statement.size() && statement[eq] == ' ') ++eq;
      if (e > 0 && identifier_start(statement[0]) && eq < statement.size() && statement[eq] == '=' &&
          (eq + 1 >= statement.size() || statement[eq + 1] != '=')) {
        const std::string name = statement.substr(0, e);
        const ScriptValue value = Evaluator(std::string_view(statement).substr(eq + 1), names).evaluate();
        if (value.resolved() && !conditional && !in_loop) {
          names[name] = value;
          script.assignments[name] = value;
        } else {
          // Bound by code the reader does not follow: no longer a known literal.
          names.erase(name);
          script.assignments.erase(name);
        }
      }
    }

    if (opens) {
      // 'if x: foo()' has its body on the header line: nothing to push.
      const std::size_t colon = statement.rfind(':');
      const bool inline_body = colon != std::string::npos && colon + 1 < statement.size() &&
                               statement.find_first_not_of(" \t", colon + 1) != std::string::npos;
      if (!inline_body) blocks.push_back({line.indent, *opens, loop_index});
    }
  }
  return script;
}

}  // namespace lmgc::grammar
