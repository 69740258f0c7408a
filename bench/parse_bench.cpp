// Parse and write throughput of the grammar layer (MB/s), on generated files of 100 000 items:
// BODIES.DAT (100 000 RBDY2 bodies, disks and pentagons) and Vloc_Rloc.INI (100 000 interactions
// of the 2D modules DKDKx, DKJCx, PLJCx, PLPLx). Also reports the heap taken by parsing relative to
// the file size. Each benchmark stops with an error if the generated file does not parse cleanly
// or does not write back byte for byte.
//
// What is timed: parse = building the SourceText (line index) from the file's bytes, then the
// parser; write = the writer producing the whole text. Copying the input and freeing the previous
// AST happen with the timer paused.
// peak_heap_over_file: peak heap allocated while parsing (line index, AST, temporaries), the file's
// own bytes excluded, over the file size. ast_heap_over_file: what stays allocated once the parse
// returns (line index + AST); line_index_over_file: the SourceText's line index alone.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>
#include <optional>
#include <string>

#include "bench/scenes/generated_files.hpp"
#include "grammar/bodies/parser.hpp"
#include "grammar/bodies/writer.hpp"
#include "grammar/vloc_rloc/parser.hpp"
#include "grammar/vloc_rloc/writer.hpp"

// Heap accounting for the memory figure: every allocation of this program goes through here.
namespace {
std::atomic<std::size_t> g_current{0};
std::atomic<std::size_t> g_peak{0};
}  // namespace

void* operator new(std::size_t size) {
  void* p = std::malloc(size + sizeof(std::max_align_t));
  if (!p) throw std::bad_alloc();
  *static_cast<std::size_t*>(p) = size;
  const std::size_t now = g_current.fetch_add(size) + size;
  std::size_t peak = g_peak.load();
  while (now > peak && !g_peak.compare_exchange_weak(peak, now)) {
  }
  return static_cast<char*>(p) + sizeof(std::max_align_t);
}
// GCC cannot see that this delete pairs with the malloc-based new above.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept {
  if (!p) return;
  char* base = static_cast<char*>(p) - sizeof(std::max_align_t);
  g_current.fetch_sub(*reinterpret_cast<std::size_t*>(base));
  std::free(base);
}
void operator delete(void* p, std::size_t) noexcept {
  operator delete(p);
}

namespace {

using lmgc::grammar::DiagnosticSink;
using lmgc::grammar::SourceText;

constexpr std::size_t kItems = 100000;
// One iteration takes 0.15-0.5 s: run each repetition for 2 s so that it holds several iterations.
constexpr double kMinSeconds = 2.0;

const std::string& bodies_text() {
  static const std::string text = lmgc::bench::generated_bodies_dat(kItems);
  return text;
}

const std::string& vloc_rloc_text() {
  static const std::string text = lmgc::bench::generated_vloc_rloc_ini(kItems);
  return text;
}

// Set when a benchmark stopped with an error: the program then exits with status 1.
bool g_failed = false;

void fail(benchmark::State& state, const std::string& message) {
  g_failed = true;
  state.SkipWithError(message.c_str());
}

// The first diagnostic of a sink, for the error message of a benchmark.
std::string first_diagnostic(const DiagnosticSink& sink) {
  if (sink.items().empty()) return "no diagnostic";
  const auto& d = sink.items().front();
  return d.code + " at line " + std::to_string(d.where.span.line) + ": " + d.message;
}

// Throughput counters: bytes_per_second (Google Benchmark's, in MiB/s) and MB_per_s (10^6 bytes per
// second, the unit of the README), both over the CPU time of the iterations.
void set_throughput(benchmark::State& state, std::size_t file_bytes) {
  const double processed = static_cast<double>(state.iterations()) * static_cast<double>(file_bytes);
  state.SetBytesProcessed(static_cast<int64_t>(processed));
  state.counters["MB_per_s"] = benchmark::Counter(processed / 1e6, benchmark::Counter::kIsRate);
  state.counters["file_MB"] = static_cast<double>(file_bytes) / 1e6;
}

// Parses `text` once; reports an error on the benchmark (and returns nothing) unless the parse is
// free of diagnostics and writing the AST gives `text` back.
template <class Parse, class Write>
auto checked_parse(benchmark::State& state, const char* path, const std::string& text, Parse parse,
                   Write write)
    -> std::optional<decltype(parse(std::declval<const SourceText&>(), std::declval<DiagnosticSink&>()))> {
  DiagnosticSink sink;
  auto file = parse(SourceText(path, text), sink);
  if (!sink.items().empty()) {
    fail(state, std::string("generated ") + path + " does not parse cleanly: " + first_diagnostic(sink));
    return std::nullopt;
  }
  if (write(file) != text) {
    fail(state, std::string("generated ") + path + " does not write back byte for byte");
    return std::nullopt;
  }
  return file;
}

template <class Parse, class Write>
void parse_benchmark(benchmark::State& state, const char* path, const std::string& text, Parse parse,
                     Write write) {
  if (!checked_parse(state, path, text, parse, write)) return;
  std::optional<SourceText> source;
  std::optional<decltype(parse(*source, std::declval<DiagnosticSink&>()))> file;
  std::size_t peak = 0, retained = 0, index = 0;
  for (auto _ : state) {
    state.PauseTiming();
    file.reset();
    source.reset();
    std::string bytes = text;  // the file as read from disk: not counted in the parse's heap
    const std::size_t before = g_current.load();
    g_peak.store(before);
    state.ResumeTiming();

    source.emplace(path, std::move(bytes));
    index = g_current.load() - before;
    DiagnosticSink sink;
    file.emplace(parse(*source, sink));
    benchmark::DoNotOptimize(*file);

    peak = std::max(peak, g_peak.load() - before);
    retained = g_current.load() - before;
    if (sink.has_errors()) {
      fail(state, std::string("parse reports errors: ") + first_diagnostic(sink));
      break;
    }
  }
  const double size = static_cast<double>(text.size());
  set_throughput(state, text.size());
  state.counters["peak_heap_over_file"] = static_cast<double>(peak) / size;
  state.counters["ast_heap_over_file"] = static_cast<double>(retained) / size;
  state.counters["line_index_over_file"] = static_cast<double>(index) / size;
}

template <class Parse, class Write>
void write_benchmark(benchmark::State& state, const char* path, const std::string& text, Parse parse,
                     Write write) {
  const auto file = checked_parse(state, path, text, parse, write);
  if (!file) return;
  std::size_t bytes = 0;
  for (auto _ : state) {
    std::string out = write(*file);
    bytes = out.size();
    benchmark::DoNotOptimize(out);
  }
  set_throughput(state, bytes);
}

const auto parse_bodies = [](const SourceText& source, DiagnosticSink& sink) {
  return lmgc::grammar::parse_bodies(source, sink);
};
const auto write_bodies = [](const lmgc::grammar::BodiesFile& file) {
  return lmgc::grammar::write_bodies(file);
};
const auto parse_vloc_rloc = [](const SourceText& source, DiagnosticSink& sink) {
  return lmgc::grammar::parse_vloc_rloc(source, sink);
};
const auto write_vloc_rloc = [](const lmgc::grammar::VlocRlocFile& file) {
  return lmgc::grammar::write_vloc_rloc(file);
};

void BM_ParseBodies(benchmark::State& state) {
  parse_benchmark(state, "BODIES.DAT", bodies_text(), parse_bodies, write_bodies);
}
BENCHMARK(BM_ParseBodies)->Unit(benchmark::kMillisecond)->MinTime(kMinSeconds);

void BM_WriteBodies(benchmark::State& state) {
  write_benchmark(state, "BODIES.DAT", bodies_text(), parse_bodies, write_bodies);
}
BENCHMARK(BM_WriteBodies)->Unit(benchmark::kMillisecond)->MinTime(kMinSeconds);

void BM_ParseVlocRloc(benchmark::State& state) {
  parse_benchmark(state, "Vloc_Rloc.INI", vloc_rloc_text(), parse_vloc_rloc, write_vloc_rloc);
}
BENCHMARK(BM_ParseVlocRloc)->Unit(benchmark::kMillisecond)->MinTime(kMinSeconds);

void BM_WriteVlocRloc(benchmark::State& state) {
  write_benchmark(state, "Vloc_Rloc.INI", vloc_rloc_text(), parse_vloc_rloc, write_vloc_rloc);
}
BENCHMARK(BM_WriteVlocRloc)->Unit(benchmark::kMillisecond)->MinTime(kMinSeconds);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return g_failed ? 1 : 0;
}
