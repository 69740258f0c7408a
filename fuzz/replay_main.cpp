// Runs a fuzz target without libFuzzer: every input file given (files, or folders read
// recursively, optionally only the files of one name), then `--mutations N` inputs made from them
// by a seeded mutator (byte flips, random bytes, deletions, duplications, splices between inputs,
// insertions of the dictionary's words). What CI runs, in the sanitized build: a short, repeatable
// pass of every target. scripts/fuzz.sh runs the real, coverage-guided fuzzer.
//
//   replay [--name FILE] [--dict FILE] [--mutations N] [--seed S] PATH...
#include <fcntl.h>
#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The input being run, saved by the crash handler to ./fuzz-crash-input (as libFuzzer saves its
// crash-* files) so that a finding can be replayed and made a regression seed.
const std::string* g_current = nullptr;

extern "C" void save_current_input(int signal) {
  if (g_current) {
    const int fd = ::open("fuzz-crash-input", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      [[maybe_unused]] const ssize_t written = ::write(fd, g_current->data(), g_current->size());
      ::close(fd);
    }
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

void run(const std::string& input) {
  g_current = &input;
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
  g_current = nullptr;
}

// libFuzzer dictionary lines: name="word" or "word"; \\ and \" and \xNN escapes.
std::vector<std::string> read_dictionary(const fs::path& path) {
  std::vector<std::string> words;
  std::istringstream in(read_bytes(path));
  for (std::string line; std::getline(in, line);) {
    const auto first = line.find('"'), last = line.rfind('"');
    if (first == std::string::npos || last <= first) continue;
    std::string word;
    for (std::size_t k = first + 1; k < last; ++k) {
      if (line[k] == '\\' && k + 1 < last) {
        ++k;
        if (line[k] == 'x' && k + 2 < last) {
          word += static_cast<char>(std::stoi(line.substr(k + 1, 2), nullptr, 16));
          k += 2;
          continue;
        }
      }
      word += line[k];
    }
    words.push_back(word);
  }
  return words;
}

std::string mutate(std::string s, const std::vector<std::string>& inputs,
                   const std::vector<std::string>& words, std::mt19937_64& random) {
  const auto below = [&](std::size_t n) { return n == 0 ? std::size_t{0} : std::size_t(random() % n); };
  const int operations = 1 + static_cast<int>(below(4));
  for (int k = 0; k < operations; ++k) {
    switch (below(7)) {
      case 0:  // flip a bit
        if (!s.empty()) s[below(s.size())] ^= static_cast<char>(1u << below(8));
        break;
      case 1:  // a random byte
        if (!s.empty()) s[below(s.size())] = static_cast<char>(below(256));
        break;
      case 2:  // delete a range
        if (!s.empty()) {
          const std::size_t at = below(s.size());
          s.erase(at, 1 + below(std::min<std::size_t>(64, s.size() - at)));
        }
        break;
      case 3:  // duplicate a range
        if (!s.empty()) {
          const std::size_t at = below(s.size()), n = 1 + below(std::min<std::size_t>(256, s.size() - at));
          s.insert(below(s.size() + 1), s.substr(at, n));
        }
        break;
      case 4:  // splice a range of another input
        if (!inputs.empty()) {
          const std::string& other = inputs[below(inputs.size())];
          if (!other.empty()) {
            const std::size_t at = below(other.size()),
                              n = 1 + below(std::min<std::size_t>(512, other.size() - at));
            s.insert(below(s.size() + 1), other.substr(at, n));
          }
        }
        break;
      case 5:  // a dictionary word
        if (!words.empty()) s.insert(below(s.size() + 1), words[below(words.size())]);
        break;
      default:  // a digit or a blank changed: numbers and columns
        if (!s.empty()) s[below(s.size())] = "0123456789 .-+DE\n"[below(17)];
        break;
    }
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  std::string name;
  std::vector<std::string> words;
  long mutations = 0;
  std::uint64_t seed = 1;
  std::vector<std::string> inputs;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--name" && k + 1 < argc) {
      name = argv[++k];
    } else if (a == "--dict" && k + 1 < argc) {
      words = read_dictionary(argv[++k]);
    } else if (a == "--mutations" && k + 1 < argc) {
      mutations = std::stol(argv[++k]);
    } else if (a == "--seed" && k + 1 < argc) {
      seed = std::stoull(argv[++k]);
    } else if (fs::is_directory(a)) {
      for (const auto& e : fs::recursive_directory_iterator(a))
        if (e.is_regular_file() && (name.empty() || e.path().filename() == name))
          inputs.push_back(read_bytes(e.path()));
    } else if (fs::is_regular_file(a)) {
      inputs.push_back(read_bytes(a));
    }
  }
  for (int signal : {SIGABRT, SIGSEGV, SIGFPE, SIGBUS, SIGILL}) std::signal(signal, save_current_input);
  if (inputs.empty()) inputs.push_back("");
  for (const std::string& input : inputs) run(input);
  std::mt19937_64 random(seed);
  for (long k = 0; k < mutations; ++k) run(mutate(inputs[random() % inputs.size()], inputs, words, random));
  std::printf("%zu inputs and %ld mutations ran\n", inputs.size(), mutations);
  return 0;
}
