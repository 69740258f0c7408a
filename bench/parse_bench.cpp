// Parse and write throughput of the grammar layer (MB/s), on generated files of 100 000 items.
// Also reports the peak heap held by a parsed AST relative to the file size.
#include <benchmark/benchmark.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "bench/scenes/generated_files.hpp"
#include "grammar/bodies/parser.hpp"
#include "grammar/bodies/writer.hpp"

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
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }

namespace {

const std::string& bodies_text() {
  static const std::string text = lmgc::bench::generated_bodies_dat(100000);
  return text;
}

void BM_ParseBodies(benchmark::State& state) {
  const std::string& text = bodies_text();
  const lmgc::grammar::SourceText source("BODIES.DAT", text);
  std::size_t ast_peak = 0;
  for (auto _ : state) {
    lmgc::grammar::DiagnosticSink sink;
    const std::size_t before = g_current.load();
    g_peak.store(before);
    auto file = lmgc::grammar::parse_bodies(source, sink);
    ast_peak = std::max(ast_peak, g_peak.load() - before);
    benchmark::DoNotOptimize(file);
    if (sink.has_errors()) state.SkipWithError("generated BODIES.DAT has errors");
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
  state.counters["file_MB"] = static_cast<double>(text.size()) / 1e6;
  state.counters["peak_heap_over_file"] = static_cast<double>(ast_peak) / static_cast<double>(text.size());
}
BENCHMARK(BM_ParseBodies)->Unit(benchmark::kMillisecond);

void BM_WriteBodies(benchmark::State& state) {
  lmgc::grammar::DiagnosticSink sink;
  const auto file = lmgc::grammar::parse_bodies(lmgc::grammar::SourceText("BODIES.DAT", bodies_text()), sink);
  std::size_t bytes = 0;
  for (auto _ : state) {
    std::string out = lmgc::grammar::write_bodies(file);
    bytes = out.size();
    benchmark::DoNotOptimize(out);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * bytes));
}
BENCHMARK(BM_WriteBodies)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
