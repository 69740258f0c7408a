// lmgc-check's cost against pure parsing, on a generated case of 100 000 bodies (disks and
// pentagons on a grid, one law, visibility rows between all of them): reading the case folder
// (every file parsed into its AST) against reading it and running every semantic check.
// The bound: check ≤ 3× parse.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>

#include "bench/scenes/generated_files.hpp"
#include "case_folder/case_files.hpp"
#include "validate/checks.hpp"

namespace {

namespace fs = std::filesystem;

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// A case folder under the temporary directory, written once per run.
const fs::path& generated_case() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / "lmgc_check_bench_100k";
    fs::remove_all(d);
    fs::create_directories(d / "DATBOX");
    write(d / "DATBOX" / "BODIES.DAT", lmgc::bench::generated_bodies_dat(100000));
    write(d / "DATBOX" / "BULK_BEHAV.DAT",
          "$gravy\n                   grv1= 0.0000000D+00  grv2=-0.9810000D+01  grv3= 0.0000000D+00\n\n"
          "$behav  lawty\n PLEXx  RIGID                           Umas= 0.1000000D+04\n");
    write(d / "DATBOX" / "TACT_BEHAV.DAT",
          "$behav  lawty\n iqsc0  IQS_CLB                         fric= 0.3000000D+00\n\n"
          "$seety\n cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert\n"
          " RBDY2  DISKx  BLEUx  iqsc0  RBDY2  DISKx  BLEUx       0.1000000D-03\n"
          "$seety\n cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert\n"
          " RBDY2  DISKx  BLEUx  iqsc0  RBDY2  POLYG  BLEUx       0.1000000D-03\n"
          "$seety\n cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert\n"
          " RBDY2  POLYG  BLEUx  iqsc0  RBDY2  POLYG  BLEUx       0.1000000D-03\n");
    write(d / "DATBOX" / "DRV_DOF.DAT", "! nothing driven\n");
    write(d / "DATBOX" / "DOF.INI",
          "\n! DOF\n\n$steps      0                time= 0.0000000D+00\n\n"
          "!-----------------------------------------------------------------------\n");
    return d;
  }();
  return dir;
}

void BM_ReadCase100k(benchmark::State& state) {
  for (auto _ : state) {
    lmgc::grammar::DiagnosticSink sink(1000);
    auto files = lmgc::case_folder::load_case(generated_case(), sink);
    benchmark::DoNotOptimize(files);
    if (!files || sink.has_errors()) state.SkipWithError("the generated case does not read cleanly");
  }
}
BENCHMARK(BM_ReadCase100k)->Unit(benchmark::kMillisecond);

void BM_ReadAndCheckCase100k(benchmark::State& state) {
  std::size_t diagnostics = 0;
  for (auto _ : state) {
    lmgc::grammar::DiagnosticSink sink(1000);
    auto files = lmgc::case_folder::load_case(generated_case(), sink);
    if (files) lmgc::validate::check_case(*files, sink);
    diagnostics = sink.items().size();
    benchmark::DoNotOptimize(files);
    if (!files || sink.has_errors()) state.SkipWithError("the generated case has errors");
  }
  state.counters["diagnostics"] = static_cast<double>(diagnostics);
}
BENCHMARK(BM_ReadAndCheckCase100k)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
