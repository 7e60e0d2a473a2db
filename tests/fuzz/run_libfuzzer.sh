#!/usr/bin/env bash
# Runs the libFuzzer target for SECONDS, from the samples and what earlier runs in DIR found.
# A broken rule (or a sanitizer report) stops it with the input kept in DIR: a failure.
# Usage: run_libfuzzer.sh FUZZER DIR SECONDS
set -euo pipefail
fuzzer=$1 dir=$2 seconds=$3
mkdir -p "$dir/seeds" "$dir/corpus"
TOUCHLINE_FUZZ_WRITE_SEEDS="$dir/seeds" "$fuzzer"
exec "$fuzzer" -max_total_time="$seconds" -seed=1 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$dir/" "$dir/corpus" "$dir/seeds"
