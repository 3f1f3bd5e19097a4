#!/usr/bin/env bash
# The "Cost budget" table of BENCHMARKS.md: for each command, the estimate that the budget
# checks (`--estimate`) beside the measured wall time, CPU time (user + system) and peak
# memory of the real run. Usage: scripts/budget-table.sh [path/to/samplescope]
set -u
bin=${1:-target/release/samplescope}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
printf '| command | estimate | wall | CPU | peak RSS | load |\n|---|---|---|---|---|---|\n'
row() {
    local est
    est=$("$bin" "$@" --estimate | tail -1 | sed -E 's/total: about (.*) here, (.*) at most/\1, \2/')
    local t0 t1
    t0=$(date +%s.%N)
    /usr/bin/time -f '%U %S %M' -o "$out/time" "$bin" "$@" > /dev/null 2> "$out/err"
    t1=$(date +%s.%N)
    read -r user sys kb < <(tail -1 "$out/time")
    printf '| `%s` | %s | %.2f s | %.2f s | %d MiB | %s |\n' "$*" "$est" \
        "$(echo "$t1 - $t0" | bc)" "$(echo "$user + $sys" | bc)" $((kb / 1024)) \
        "$(cut -d' ' -f1 /proc/loadavg)"
}
row points best-candidate -n 20000 --out "$out/p.csv"
row points best-candidate -n 40000 --out "$out/p.csv"
row points poisson-dart -n 1000000 --out "$out/p.csv"
row points poisson-bridson -n 1000000 --out "$out/p.csv"
row points jitter -n 4194304 --out "$out/p.csv"
row recon --size 4096 -n 1024
row recon --size 2048 -n 1024 --mode radial
row recon --size 8192 -n 16777216
row recon --size 1024 --spp 16
row recon --size 512 --spp 64 --pattern sobol --set scramble=owen
row recon --size 256 --spp 64 --pattern best-candidate
row recon --signal checkerboard --size 1024 -n 1024
row recon --signal grating --size 4096 -n 1024
row analyze jitter -n 65536 --size 16
row analyze jitter -n 4096 --size 1024 --exact
row analyze jitter -n 1048576 --size 256
row analyze jitter -n 4096 --size 2048 --realizations 8
row render assets/scenes/texture-1spp.ron --out "$out/r" --no-cache
row render assets/scenes/texture-256spp.ron --out "$out/r" --no-cache
row render assets/scenes/default.ron --out "$out/r" --no-cache
