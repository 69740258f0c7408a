#!/usr/bin/env bash
# Runs every fuzz target of fuzz/ with libFuzzer for SECONDS each (default 600), seeded from
# LMGC90's example files (../shared, when present), the shipped reference cases and fuzz/seeds/,
# with the keyword dictionary fuzz/lmgc.dict; then writes docs/fuzzing.md (one row per target:
# executions, coverage, corpus, findings, date, machine) and bench/results/<machine>/fuzzing.csv.
# This run's findings are left in build/fuzz/findings/<target>/ (emptied at the start of each target's
# run): each becomes a seed in fuzz/seeds/<target>/ (replayed by CI, ctest -R Fuzz) and a regression test.
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
shift || true
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  targets=(bodies bulk_behav tact_behav models drv_dof evolution dof vloc_rloc gpv ptpt3_network postpro command
           command_py case fclib)
fi
scripts/install_deps.sh
command -v clang++ >/dev/null || { echo "fuzz: clang++ is needed (apt-get install clang)" >&2; exit 1; }
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz --target $(printf 'fuzz_%s ' "${targets[@]}")

shared=${LMGC_SHARED_DIR:-../shared}
machine=${LMGC_MACHINE:-debian12-2core}  # the label of bench/results/<machine>/, as the benches
cpu=$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')
date=$(date -u +%Y-%m-%d)
declare -A names=([bodies]=BODIES.DAT [bulk_behav]=BULK_BEHAV.DAT [tact_behav]=TACT_BEHAV.DAT [models]=MODELS.DAT
                  [drv_dof]=DRV_DOF.DAT [dof]=DOF.INI [vloc_rloc]=Vloc_Rloc.INI [gpv]=GPV.INI
                  [ptpt3_network]=PTPT3_NETWORK.DAT [postpro]=POSTPRO.DAT [command]=COMMAND.DAT
                  [command_py]=command.py)
# Leaks inside libraries lmgc cannot fix (fuzz/lsan.supp says which and why).
export LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
results=build/fuzz/results.csv
echo "target,seconds,executions,coverage,features,corpus,findings" > "$results"
for t in "${targets[@]}"; do
  program=build/fuzz/fuzz/fuzz_$t
  [ -x "$program" ] || { echo "fuzz: $program not built (fclib needs HDF5)" >&2; continue; }
  corpus=build/fuzz/corpus/$t findings=build/fuzz/findings/$t
  # This run's findings only: earlier ones are seeds of fuzz/seeds/<target>/ (replayed by CI).
  rm -rf "$findings"
  mkdir -p "$corpus" "$findings"
  if [ -n "${names[$t]:-}" ]; then
    find "$shared/lmgc90-examples" reference_cases -name "${names[$t]}" 2>/dev/null |
      while read -r f; do cp "$f" "$corpus/$(echo "$f" | md5sum | cut -c1-16)"; done
  fi
  [ "$t" = fclib ] && find "$shared/fc3d" -name '*.hdf5' -size -200k 2>/dev/null | head -20 | xargs -r cp -t "$corpus"
  [ -d "fuzz/seeds/$t" ] && find "fuzz/seeds/$t" -type f -exec cp -t "$corpus" {} +
  log=build/fuzz/$t.log
  set +e
  "$program" -max_total_time="$seconds" -dict=fuzz/lmgc.dict -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$findings/" "$corpus" > "$log" 2>&1
  set -e
  # A run stopped by a finding prints no final statistics: count what it printed, and go on.
  executions=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1 || true)
  coverage=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || true)
  features=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || true)
  corpus_size=$(ls "$corpus" | wc -l)
  found=$(find "$findings" -type f | wc -l)
  echo "$t,$seconds,${executions:-0},${coverage:-0},${features:-0},$corpus_size,$found" >> "$results"
  echo "fuzz: $t: ${executions:-0} executions, coverage ${coverage:-0}, $found finding(s)"
done

mkdir -p "bench/results/$machine"
cp "$results" "bench/results/$machine/fuzzing.csv"
{
  echo "# Fuzzing"
  echo
  echo "The last long run of every fuzz target (\`scripts/fuzz.sh $seconds\`, libFuzzer with ASan and UBSan,"
  echo "clang), $date, on $machine ($cpu). Raw data: \`bench/results/$machine/fuzzing.csv\`."
  echo "What each target checks: \`fuzz/fuzz_target.hpp\` and \`fuzz/targets/\`. CI replays the seeds of"
  echo "\`fuzz/seeds/\` (the findings) and a short seeded mutation pass of every target (\`ctest -R Fuzz\`)."
  echo
  echo "| target | seconds | executions | coverage (edges) | features | corpus | findings |"
  echo "| --- | --- | --- | --- | --- | --- | --- |"
  tail -n +2 "$results" | while IFS=, read -r t s e c f k n; do echo "| $t | $s | $e | $c | $f | $k | $n |"; done
  echo
  # The findings, kept by hand below this heading, stay from one run to the next.
  if [ -f docs/fuzzing.md ] && grep -q '^## Findings' docs/fuzzing.md; then
    sed -n '/^## Findings/,$p' docs/fuzzing.md
  else
    echo "## Findings"
  fi
} > docs/fuzzing.md.new
mv docs/fuzzing.md.new docs/fuzzing.md
echo "fuzz: results in $results and docs/fuzzing.md"
