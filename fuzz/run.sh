#!/usr/bin/env bash
# Runs every fuzz target for SECONDS seconds each (default 60) and prints each one's execution
# count. Needs cargo-fuzz (`cargo install cargo-fuzz`); libFuzzer needs nightly compiler
# features, which RUSTC_BOOTSTRAP=1 enables on the stable toolchain. Seeds come from
# fuzz/seeds/TARGET (checked in), the growing corpus lives in fuzz/corpus/TARGET (ignored), and
# a crash leaves its input in fuzz/artifacts/TARGET: turn it into a regression test of the
# normal suite (see fuzz/README.md).
#
#   fuzz/run.sh SECONDS [TARGET...]
set -euo pipefail
cd "$(dirname "$0")"
seconds="${1:-60}"
shift || true
targets=("$@")
if [ "${#targets[@]}" -eq 0 ]; then
  targets=(ron_reader literal expression graph_eval grasshopper)
fi
export RUSTC_BOOTSTRAP=1
# Build once, with debug assertions, for all targets.
cargo fuzz build --debug-assertions
status=0
for target in "${targets[@]}"; do
  mkdir -p "corpus/$target" "artifacts/$target"
  seeds=()
  [ -d "seeds/$target" ] && seeds=("seeds/$target")
  log="artifacts/$target/last-run.log"
  # Grasshopper files are larger than graphs and formulas: the seeds are 12 and 27 kB.
  max_len=4096
  [ "$target" = grasshopper ] && max_len=65536
  echo "== $target: ${seconds}s"
  # -max_total_time bounds the run; -timeout fails an input that runs for more than 10 s;
  # -rss_limit_mb fails one that needs more than 2 GB; the outer timeout is a backstop.
  if timeout "$((seconds + 120))" cargo fuzz run --debug-assertions "$target" \
      "corpus/$target" "${seeds[@]}" -- \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len="$max_len" \
      -print_final_stats=1 >"$log" 2>&1; then
    result="ok"
  else
    result="FAILED (see $log and artifacts/$target/)"
    status=1
  fi
  runs="$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')"
  echo "$target: $runs executions, $result"
done
exit "$status"
