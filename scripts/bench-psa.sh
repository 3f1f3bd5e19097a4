#!/usr/bin/env bash
# samplescope's `analyze` against PSA's `--summary` on the same point file, process start
# included: the median wall time of several runs of each and their ratio. Builds nothing.
#
# Usage: scripts/bench-psa.sh SAMPLESCOPE PSA [POINTS.csv] [RUNS_ANALYZE] [RUNS_PSA]
#   SAMPLESCOPE  a release build of samplescope (e.g. target/release/samplescope)
#   PSA          PSA's binary (built as tests/data/psa/README.md says; its folder holds
#                common/psa.cfg, which PSA reads from its working directory)
#   POINTS.csv   `x,y` rows (default: `points jitter -n 4096 --seed 1`, written by SAMPLESCOPE)
#   RUNS_*       runs of each (default 9 and 3; the median is reported)
# samplescope runs `analyze --points F --size 640 --json` (every measure); PSA runs
# `--summary` on the same points in its text format (the count, then `x y` per line).
set -eu
if [ $# -lt 2 ]; then
    sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'
    exit 2
fi
ss=$(realpath "$1")
psa=$(realpath "$2")
runs_a=${4:-9}
runs_p=${5:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ $# -ge 3 ]; then
    cp "$3" "$work/points.csv"
else
    "$ss" points jitter -n 4096 --seed 1 --out "$work/points.csv"
fi
# PSA's format: the count on the first line, then `x y`.
tail -n +2 "$work/points.csv" | tr ',' ' ' > "$work/rows"
{ wc -l < "$work/rows"; cat "$work/rows"; } > "$work/points.txt"
mkdir -p "$work/common"
cp "$(dirname "$psa")/common/psa.cfg" "$work/common/"

# Median wall time in ms of running "$@" $1 times (in $work, output discarded).
median_ms() {
    local runs=$1
    shift
    local times=()
    for _ in $(seq "$runs"); do
        local t0 t1
        t0=$(date +%s%N)
        (cd "$work" && "$@" > /dev/null 2>&1)
        t1=$(date +%s%N)
        times+=($(((t1 - t0) / 1000)))
    done
    printf '%s\n' "${times[@]}" | sort -n | sed -n "$(((runs + 1) / 2))p" | awk '{printf "%.1f", $1 / 1000}'
}

n=$(wc -l < "$work/rows")
echo "points: $n ($( [ $# -ge 3 ] && echo "$3" || echo 'jitter -n 4096 --seed 1'))"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg), cores: $(nproc)"
a=$(median_ms "$runs_a" "$ss" analyze --points points.csv --size 640 --json)
echo "samplescope analyze --points F --size 640 --json: median of $runs_a: $a ms"
p=$(median_ms "$runs_p" "$psa" --summary points.txt)
echo "psa --summary F: median of $runs_p: $p ms"
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
awk -v a="$a" -v p="$p" 'BEGIN { printf "ratio (psa / analyze): %.0f\n", p / a }'
