#!/usr/bin/env bash
# Runs TopoSLAM's libFuzzer harnesses (the sanitizer build makes them: cmake --preset asan &&
# cmake --build --preset asan) and prints one line per reader: executions, executions per
# second, CPU seconds, coverage (edges, features), corpus size, peak memory of the fuzzer,
# outcome.
#   tests/fuzz/run-fuzzers.sh [-t seconds] [-j parallel] [-o workdir] [reader ...]
# Each reader runs for `seconds` (default 30) on a fresh working corpus seeded from
# tests/fuzz/corpus/<reader>/ (never modified), with -rss_limit_mb=2048 -timeout=10; `parallel`
# readers at a time (default 2). Crashes, hangs (> 10 s per input) and inputs that need more
# than 2 GB are saved as <workdir>/<reader>/crash-*, timeout-*, oom-*; the exit status is 1
# if there is any. Default readers: all of them.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
seconds=30 jobs=2 work=""
while getopts "t:j:o:" opt; do
    case $opt in
        t) seconds=$OPTARG ;;
        j) jobs=$OPTARG ;;
        o) work=$OPTARG ;;
        *) sed -n '2,10p' "$0" >&2; exit 2 ;;
    esac
done
shift $((OPTIND - 1))
bin="$root/build/asan/bin"
readers=("$@")
if [ ${#readers[@]} -eq 0 ]; then
    readers=(carmen rawlog gridmap gridmap_image ros_map rooms_json rooms_graphml relations
             trajectory ini)
fi
for r in "${readers[@]}"; do
    [ -x "$bin/fuzz_$r" ] || { echo "error: $bin/fuzz_$r not built (cmake --preset asan && cmake --build --preset asan)" >&2; exit 2; }
done
work=${work:-$(mktemp -d "${TMPDIR:-/tmp}/toposlam-fuzz.XXXXXX")}
mkdir -p "$work"

run_one() {
    local r=$1 dir="$work/$1"
    mkdir -p "$dir/corpus"
    local dict=()
    [ -f "$here/dict/$r.dict" ] && dict=(-dict="$here/dict/$r.dict")
    # Scratch files of the harness go to its own TMPDIR, removed afterwards.
    mkdir -p "$dir/tmp"
    TMPDIR="$dir/tmp" /usr/bin/time -o "$dir/time.txt" -f "%U %S %M" \
        "$bin/fuzz_$r" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 \
        -print_final_stats=1 -artifact_prefix="$dir/" "${dict[@]}" \
        "$dir/corpus" "$here/corpus/$r" >"$dir/log.txt" 2>&1 || true
    rm -rf "$dir/tmp"
}
export -f run_one
export work bin here seconds

printf '%s\n' "${readers[@]}" | xargs -P "$jobs" -I{} bash -c 'run_one {}'

status=0
printf '%-14s %10s %8s %8s %8s %8s %7s %8s  %s\n' reader executions exec/s cpu_s coverage features \
    corpus peak_MB outcome
for r in "${readers[@]}"; do
    log="$work/$r/log.txt"
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
    last=$(grep -E '^#[0-9]+.*cov: ' "$log" | tail -1 || true)
    cov=$(echo "$last" | sed -n 's/.*cov: \([0-9]*\).*/\1/p')
    ft=$(echo "$last" | sed -n 's/.*ft: \([0-9]*\).*/\1/p')
    corp=$(echo "$last" | sed -n 's/.*corp: \([0-9]*\).*/\1/p')
    cpu=$(awk '{printf "%.0f", $1 + $2}' "$work/$r/time.txt" 2>/dev/null || true)
    peak=$(awk '{printf "%.0f", $3 / 1024}' "$work/$r/time.txt" 2>/dev/null || true)
    findings=$(find "$work/$r" -maxdepth 1 \( -name 'crash-*' -o -name 'timeout-*' -o -name 'oom-*' -o -name 'leak-*' \) | wc -l)
    outcome="ok"
    if [ "$findings" -gt 0 ] || ! grep -q '^Done [0-9]* runs' "$log"; then
        outcome="FAILED ($findings finding(s), see $log)"
        status=1
    fi
    printf '%-14s %10s %8s %8s %8s %8s %7s %8s  %s\n' "$r" "${runs:-?}" "${rate:-?}" "${cpu:-?}" \
        "${cov:-?}" "${ft:-?}" "${corp:-?}" "${peak:-?}" "$outcome"
done
echo "work directory: $work"
exit $status
