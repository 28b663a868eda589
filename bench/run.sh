#!/bin/sh
# The benchmarks in one run, written to bench/RESULTS.md (and bench/throughput.svg) by bench/report.py:
# billiards_bench pinned to one core (its shots on every core unpinned, after), then — where pooltool's harness is set up (../shared/peers/pooltool:
# setup.sh has extracted its source) — pooltool's breaks on the same core, where FastFiz's harness is
# built (../shared/peers/fastfiz/setup.sh) its breaks on the same core, and — where
# ../shared/peers/edmd is — the gas against Smallenburg's SingleEvent code on the same core, so that the
# ratios compare programs measured side by side.
#
#   bench/run.sh [BUILD_DIR] [-- extra billiards_bench arguments]     (default build/)
#
# BILLIARDS_BENCH_OUT names the folder RESULTS.md goes to (default bench/).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
build=${1:-$root/build}
[ $# -gt 0 ] && shift
[ "${1:-}" = "--" ] && shift
out=${BILLIARDS_BENCH_OUT:-$here}
bench="$build/bench/billiards_bench"
if [ ! -x "$bench" ]; then
  echo "bench/run.sh: $bench is not built (cmake --build $build --target billiards_bench)" >&2
  exit 2
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
core=0
command="BILLIARDS_BENCH_MAX_PAIRS=10000000 taskset -c $core ${bench#"$root"/} --benchmark_min_time=0.1 --benchmark_repetitions=5 --benchmark_report_aggregates_only=true --benchmark_format=json --benchmark_out=bench.json $*"
BILLIARDS_BENCH_MAX_PAIRS=10000000 taskset -c $core "$bench" --benchmark_min_time=0.1 --benchmark_repetitions=5 \
  --benchmark_report_aggregates_only=true --benchmark_format=json --benchmark_out="$work/bench.json" "$@" > /dev/null
# One shot per thread on every core, unpinned, merged into the same results.
BILLIARDS_BENCH_THREADS=1 "$bench" --benchmark_filter='shot/random.*threads' --benchmark_min_time=0.1 \
  --benchmark_repetitions=5 --benchmark_report_aggregates_only=true --benchmark_format=json \
  --benchmark_out="$work/threads.json" > /dev/null
python3 -c 'import json, sys
runs = json.load(open(sys.argv[1]))
runs["benchmarks"] += json.load(open(sys.argv[2]))["benchmarks"]
json.dump(runs, open(sys.argv[1], "w"))' "$work/bench.json" "$work/threads.json"
peer="$root/../shared/peers/pooltool"
pooltool_arguments=""
if [ -f "$peer/env.sh" ] && [ -d "${POOLTOOL_WORK:-$HOME/.cache/pooltool-peer}/src/pooltool" ]; then
  # env.sh is bash (it finds itself through BASH_SOURCE): sourced by bash, whatever sh runs this script.
  bash -c '. "$1/env.sh" && taskset -c "$2" "$PY" "$1/bench_breaks.py"' sh "$peer" "$core" > "$work/pooltool.json"
  pooltool_arguments="--pooltool $work/pooltool.json"
else
  echo "bench/run.sh: pooltool's harness is not set up ($peer/setup.sh); its breaks are left out" >&2
fi
# FastFiz's breaks on the same core, where ../shared/peers/fastfiz/setup.sh has built its harness (into
# FASTFIZ_WORK, default ~/.cache/fastfiz-peer): five rounds, each our breaks then FastFiz's, alternating,
# so that both sides see the machine as it is within seconds of each other; report.py takes the median
# of the five rounds' ratios (a shared machine changes speed from minute to minute, and not by the same
# factor for both programs).
fastfiz="${FASTFIZ_WORK:-$HOME/.cache/fastfiz-peer}/bench_break"
fastfiz_arguments=""
if [ -x "$fastfiz" ]; then
  for round in 1 2 3 4 5; do
    taskset -c $core "$bench" --benchmark_filter='^shot/break/' --benchmark_min_time=0.2 --benchmark_repetitions=3 \
      --benchmark_report_aggregates_only=true --benchmark_format=json --benchmark_out="$work/breaks$round.json" > /dev/null
    taskset -c $core "$fastfiz" --game both --reps 1000 > "$work/fastfiz$round.json"
    fastfiz_arguments="$fastfiz_arguments --fastfiz $work/fastfiz$round.json --breaks $work/breaks$round.json"
  done
else
  echo "bench/run.sh: FastFiz's harness is not built ($root/../shared/peers/fastfiz/setup.sh); its breaks are left out" >&2
fi
# The gas against Smallenburg's SingleEvent code, side by side on the same core, where its source and
# harness are beside the checkout (../shared/peers/edmd: run.py builds it with gcc).
edmd="$root/../shared/peers/edmd"
edmd_arguments=""
if [ -f "$edmd/run.py" ] && [ -x "$build/programs/billiards-gas" ]; then
  python3 "$edmd/run.py" "$build/programs/billiards-gas" --sizes 4000,32000,256000,1048576 --etas 0.3,0.45 \
    --pairs 3 --seconds 3 --cpu $core > "$work/edmd.txt"
  edmd_arguments="--edmd $work/edmd.txt"
else
  echo "bench/run.sh: ../shared/peers/edmd/run.py or $build/programs/billiards-gas is missing; the gas's comparison is left out" >&2
fi
# The Python package, where it is built: its breaks and one-thread batch pinned to the same core, then its
# batch on every core and on a local Dask cluster, unpinned; Debian's python3, where its numpy is.
python_arguments=""
if ls "$build"/python/billiards/_billiards*.so > /dev/null 2>&1; then
  taskset -c $core /usr/bin/python3 "$here/bench_python.py" --build "$build" --part one-core > "$work/python1.json"
  /usr/bin/python3 "$here/bench_python.py" --build "$build" --part every-core > "$work/python2.json" 2> "$work/dask.log"
  /usr/bin/python3 -c 'import json, sys
one = json.load(open(sys.argv[1]))
one.update(json.load(open(sys.argv[2])))
json.dump(one, open(sys.argv[1], "w"))' "$work/python1.json" "$work/python2.json"
  python_arguments="--python $work/python1.json"
else
  echo "bench/run.sh: the Python package is not built in $build (BILLIARDS_BUILD_PYTHON); its figures are left out" >&2
fi
# shellcheck disable=SC2086
python3 "$here/report.py" "$work/bench.json" --command "$command" --derive "$build/derive/billiards-derive" \
  --out-dir "$out" $pooltool_arguments $fastfiz_arguments $edmd_arguments $python_arguments
echo "wrote $out/RESULTS.md"
