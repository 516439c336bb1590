#!/usr/bin/env bash
# Run glyphfair's Google Benchmark programs (built by scripts/dev.sh) and keep the figures.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p out
build/bench/glyphfair_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_out=out/bench.json --benchmark_out_format=json "$@"
echo "figures in out/bench.json"
