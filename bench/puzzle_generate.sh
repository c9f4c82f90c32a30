#!/usr/bin/env bash
# How far `orthoray puzzle generate` goes (docs/puzzles.md, "Generation";
# bench/RESULTS.md "Generated levels"): for each grid size and block set,
# SEEDS runs with seeds 1..SEEDS, each stopped by --timeout LIMIT seconds
# (default 500 attempts). Prints a markdown table on stdout: how many runs
# wrote a unique level, the median wall time of the runs that did (process
# included), the median and largest search nodes the solver took to count
# their solutions (the difficulty, from the level's first line), and the
# median share of closed ('x') cells.
#
#   bench/puzzle_generate.sh [BUILD_DIR] [SEEDS] [LIMIT] [MAX_NODES] ["SIZE BLOCKS LASERS POINTS"...]
#
# MAX_NODES is puzzle generate's --max-nodes (default 50000); configurations
# given after it replace the default list below.
set -euo pipefail
build=${1:-build}
seeds=${2:-5}
limit=${3:-20}
max_nodes=${4:-50000}
bin="$build/orthoray"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

median() { sort -g | awk '{a[NR]=$1} END {if (NR == 0) print "-"; else print (NR % 2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }

# size blocks lasers points
configs=(
    "5x5 A3 1 7" "5x5 A5 1 9" "5x5 A7 1 11"
    "6x6 A4 1 8" "6x6 A6 1 10" "6x6 A8 1 12"
    "7x7 A5 1 9" "7x7 A7 1 11" "7x7 A9 1 13"
    "8x8 A6 1 10" "8x8 A8 1 12" "8x8 A10 1 14"
    "9x9 A7 1 11" "9x9 A9 1 13" "9x9 A11 1 15"
    "10x10 A8 1 12" "10x10 A10 1 14" "10x10 A12 1 16"
    "6x6 A3,C1 1 8" "8x8 A5,C1 1 10" "10x10 A6,C2 1 14"
    "5x5 A2,B1 2 6" "6x6 A3,B1 2 8" "8x8 A4,B2 3 12"
)
if [ $# -gt 4 ]; then configs=("${@:5}"); fi
echo "| size | blocks | lasers | points | unique levels | median time | median nodes | most nodes | closed cells |"
echo "|---|---|---|---|---|---|---|---|---|"
for config in "${configs[@]}"; do
    read -r size blocks lasers points <<<"$config"
    ok=0
    : >"$work/times"
    : >"$work/nodes"
    : >"$work/closed"
    for seed in $(seq 1 "$seeds"); do
        begin=$(date +%s.%N)
        if "$bin" puzzle generate --size "$size" --blocks "$blocks" --lasers "$lasers" \
            --points "$points" --seed "$seed" --timeout "$limit" --max-nodes "$max_nodes" -o "$work/level.bff" \
            >/dev/null 2>&1; then
            end=$(date +%s.%N)
            ok=$((ok + 1))
            awk -v a="$begin" -v b="$end" 'BEGIN {printf "%.3f\n", b - a}' >>"$work/times"
            head -1 "$work/level.bff" | sed 's/.*(\([0-9]*\) search nodes.*/\1/' >>"$work/nodes"
            cells=${size%x*}
            cells=$((cells * ${size#*x}))
            x=$(sed -n '/GRID START/,/GRID STOP/p' "$work/level.bff" | grep -o x | wc -l)
            awk -v x="$x" -v c="$cells" 'BEGIN {printf "%.0f\n", 100 * x / c}' >>"$work/closed"
        fi
    done
    t=$(median <"$work/times")
    n=$(median <"$work/nodes")
    most=$(sort -g "$work/nodes" | tail -1)
    c=$(median <"$work/closed")
    echo "| $size | $blocks | $lasers | $points | $ok / $seeds | ${t} s | $n | ${most:--} | ${c}% |"
done
