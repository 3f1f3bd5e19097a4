#!/usr/bin/env bash
# The "every shipped scene renders in ≤ 1.5 s with cold caches" check of BENCHMARKS.md: renders
# each assets/scenes/*.ron with `render SCENE --no-cache --out DIR` (default formats, process start
# included) RUNS times, and prints per scene the median and the fastest wall time, the median CPU
# time (user + system) and whether the median meets the limit; then the worst median and the
# count that meet it. Exits 1 when a median is over the limit.
# Usage: scripts/scene-times.sh [path/to/samplescope] [RUNS] [SCENE.ron …]
# (LIMIT=seconds overrides 1.5; the release build: cargo build --release --bin samplescope).
set -u
cd "$(dirname "$0")/.."
bin=${1:-target/release/samplescope}
runs=${2:-3}
shift $(($# < 2 ? $# : 2))
scenes=("$@")
[ ${#scenes[@]} -eq 0 ] && scenes=(assets/scenes/*.ron)
limit=${LIMIT:-1.5}
[ -x "$bin" ] || { echo "scene-times: $bin: not an executable (build it: cargo build --release --bin samplescope)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
printf 'load average before: %s; %s runs per scene; limit %s s\n\n' "$(cut -d' ' -f1-3 /proc/loadavg)" "$runs" "$limit"
printf '| scene | median wall | fastest | median CPU | ≤ %s s |\n|---|---|---|---|---|\n' "$limit"
worst=0 worst_scene= met=0 total=0 failed=0
for s in "${scenes[@]}"; do
    name=$(basename "$s" .ron)
    : > "$tmp/wall"
    : > "$tmp/cpu"
    for _ in $(seq "$runs"); do
        rm -rf "$tmp/out"
        t0=$(date +%s.%N)
        if ! /usr/bin/time -f '%U %S' -o "$tmp/time" "$bin" render "$s" --no-cache --out "$tmp/out" > /dev/null 2> "$tmp/err"; then
            echo "scene-times: $name: render failed: $(grep -v '^Command exited' "$tmp/err" | tail -1)" >&2
            failed=1
            continue 2
        fi
        t1=$(date +%s.%N)
        echo "$t1 - $t0" | bc >> "$tmp/wall"
        awk '{ print $1 + $2 }' "$tmp/time" >> "$tmp/cpu"
    done
    wall=$(median < "$tmp/wall")
    fast=$(sort -g "$tmp/wall" | head -1)
    cpu=$(median < "$tmp/cpu")
    ok=$(awk -v w="$wall" -v l="$limit" 'BEGIN { print (w <= l) ? "yes" : "**no**" }')
    total=$((total + 1))
    [ "$ok" = yes ] && met=$((met + 1))
    if awk -v w="$wall" -v m="$worst" 'BEGIN { exit !(w > m) }'; then
        worst=$wall worst_scene=$name
    fi
    printf '| `%s` | %.2f s | %.2f s | %.2f s | %s |\n' "$name" "$wall" "$fast" "$cpu" "$ok"
done
printf '\nworst median: %.2f s (`%s`); %d of %d scenes within %s s; load average after: %s\n' \
    "$worst" "$worst_scene" "$met" "$total" "$limit" "$(cut -d' ' -f1-3 /proc/loadavg)"
[ "$failed" -eq 0 ] && [ "$met" -eq "$total" ]
