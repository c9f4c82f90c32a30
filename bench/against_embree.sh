#!/usr/bin/env bash
# Issue 17's one run (bench/RESULTS.md, "Issue 17 in one run"): the exact
# engine against Embree and the float grid at 10^2..10^5 mirrors in 2D and
# 3D (speed, setup, peak memory, where Embree's path leaves the exact one),
# then the induction engine on 10^3..10^5 random mirrors with coordinates to
# 10^18, CPU time by perf stat when it is installed. Run it on an idle
# machine; it takes about four minutes on 2 cores.
#
#   bench/against_embree.sh [BUILD_DIR] [OUT_DIR] [CPU]
#
# Writes OUT_DIR/embree.md, OUT_DIR/induction-narrow.md and OUT_DIR/memory.md
# (default bench/results); the machine and load are in each file. The last
# is the machine's load latency and cost of fresh memory, what bounds the
# rows of 10^5 elements (bench/README.md, "The machine's memory").
#
# Every process runs on one core, CPU (default 0), by taskset: the two
# virtual cores of the test VM have differed by up to 1.8x in speed at the
# same moment (bench/README.md, "Pinning"), and a contender the scheduler
# put on the slow one lost a ratio it would have won. CPU "none" leaves the
# placement to the scheduler.
set -euo pipefail
build=${1:-build}
out=${2:-bench/results}
cpu=${3:-0}
mkdir -p "$out"

pin=()
if [[ $cpu != none ]] && command -v taskset >/dev/null; then pin=(taskset -c "$cpu"); fi

# The commit the programs were built from (orthoray version), which is what
# ran, whatever the checkout holds now; unknown without the built program.
build_commit() {
    "$build/orthoray" version --json 2>/dev/null | sed -n 's/.*"commit":"\([^"]*\)".*/\1/p' ||
        echo unknown
}

machine() {
    echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //');" \
        "built from commit $(build_commit); $(date -u '+%F %R UTC');" \
        "load average $(cut -d' ' -f1-3 /proc/loadavg);" \
        "${pin[*]:-not pinned}."
}

"${pin[@]}" "$build/bench/orthoray_bench" --mode embree --steps 3e6 --runs 5 --csv "" >"$out/embree.md"

{
    echo "# Induction on random mirrors, coordinates to 10^18 (issue 17, item 4)"
    echo
    machine
    echo
    echo '```'
    "${pin[@]}" "$build/bench/induction_bench" --mirrors 1000 --mirrors 10000 --runs 5 --sim-cap 0 --csv ""
    "${pin[@]}" "$build/bench/induction_bench" --mirrors 100000 --runs 1 --sim-cap 0 --csv ""
    echo '```'
    if command -v perf >/dev/null; then
        echo
        echo "CPU time of one process each (perf stat -e task-clock; scene generation included):"
        echo
        for n in 1000 10000 100000; do
            "${pin[@]}" perf stat -x, -e task-clock "$build/bench/induction_bench" --mirrors "$n" --runs 1 \
                --sim-cap 0 --csv "" 2>&1 >/dev/null |
                awk -F, -v n="$n" '/task-clock/ {printf "- %s mirrors: %.3f s CPU\n", n, $1 / 1000}'
        done
    fi
    echo
    echo "At the end: load average $(cut -d' ' -f1-3 /proc/loadavg)."
} >"$out/induction-narrow.md"
{
    machine
    echo
    "${pin[@]}" "$build/bench/orthoray_bench" --mode memory --runs 3 | sed -n '/^## /,$p'
} >"$out/memory.md"
echo "wrote $out/embree.md, $out/induction-narrow.md and $out/memory.md"
