#!/usr/bin/env bash
# The "2^20 points stay bounded" table of BENCHMARKS.md: for each `points` and `analyze` command
# at N = 2^20, the memory the budget estimates (`--estimate`'s total) beside the peak resident
# memory of the real run (`/usr/bin/time`'s maximum resident set minus that of the binary at
# rest, `points random -n 1`, as src/core/budget.rs measures it), their ratio, and whether the
# estimate is within 2× of the peak either way. A command the budget refuses shows its one
# line. Exits 1 when an estimate is not within 2×.
# Usage: scripts/peak-memory.sh [path/to/samplescope]
set -u
bin=${1:-target/release/samplescope}
[ -x "$bin" ] || { echo "peak-memory: $bin: not an executable (cargo build --release --bin samplescope)" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
n=1048576
"$bin" points jitter -n $n --out "$out/jitter.csv" 2> /dev/null
"$bin" points sobol -n $n --dims 8 --out "$out/sobol8.csv" 2> /dev/null
mib() { # "12 MiB" / "1.5 GiB" / "800 KiB" -> MiB
    awk -v v="$1" -v u="$2" 'BEGIN { f = (u == "GiB") ? 1024 : (u == "KiB") ? 1 / 1024 : (u == "B") ? 1 / 1048576 : 1; printf "%.1f", v * f }'
}
/usr/bin/time -f '%M' -o "$out/rest" "$bin" points random -n 1 > /dev/null
rest=$(tail -1 "$out/rest")
printf 'binary at rest: %.1f MiB (subtracted)\n\n' "$(awk -v k="$rest" 'BEGIN { print k / 1024 }')"
printf '| command | estimate | peak RSS | estimate / peak | within 2× | wall | CPU |\n|---|---|---|---|---|---|---|\n'
bad=0
row() {
    local est_line est peak ratio ok
    est_line=$("$bin" "$@" --estimate 2>&1 | tail -1)
    # "total: about 0.72 s here, 62 MiB at most"
    est=$(echo "$est_line" | sed -nE 's/.*, ([0-9.e+]+) ([KMG]?i?B) at most.*/\1 \2/p')
    if [ -z "$est" ]; then
        printf '| `%s` | refused: %s | | | | | |\n' "$(echo "$*" | sed "s|$out/||g")" "$("$bin" "$@" 2>&1 >/dev/null | tail -1 | cut -c1-160)"
        return
    fi
    local t0 t1
    t0=$(date +%s.%N)
    /usr/bin/time -f '%M %U %S' -o "$out/time" "$bin" "$@" > /dev/null 2> "$out/err"
    local rc=$?
    t1=$(date +%s.%N)
    if [ $rc -ne 0 ]; then
        printf '| `%s` | %s | exit %d: %s | | | | |\n' "$(echo "$*" | sed "s|$out/||g")" "$est" $rc "$(tail -1 "$out/err" | cut -c1-120)"
        return
    fi
    read -r kb user sys < <(tail -1 "$out/time")
    peak=$(awk -v k="$kb" -v r="$rest" 'BEGIN { printf "%.1f", (k - r) / 1024 }')
    local e
    e=$(mib $est)
    ratio=$(awk -v e="$e" -v p="$peak" 'BEGIN { printf "%.2f", e / p }')
    ok=$(awk -v r="$ratio" 'BEGIN { print (r >= 0.5 && r <= 2) ? "yes" : "**no**" }')
    [ "$ok" = yes ] || bad=1
    printf '| `%s` | %s MiB | %s MiB | %s | %s | %.2f s | %.2f s |\n' "$(echo "$*" | sed "s|$out/||g")" "$e" "$peak" "$ratio" "$ok" \
        "$(echo "$t1 - $t0" | bc)" "$(echo "$user + $sys" | bc)"
}
for p in random jitter sobol halton pmj02 poisson-dart; do
    row points $p -n $n --out "$out/p.csv"
done
row points best-candidate -n $n --out "$out/p.csv"
for p in random sobol halton; do
    row points $p -n $n --dims 8 --out "$out/p.csv"
done
row analyze --points "$out/jitter.csv"
row analyze --points "$out/jitter.csv" --json
row analyze --points "$out/sobol8.csv"
row analyze jitter -n $n
row analyze sobol -n $n --dims 8 --project 0,1
printf '\nload average: %s\n' "$(cut -d' ' -f1-3 /proc/loadavg)"
[ $bad -eq 0 ]
