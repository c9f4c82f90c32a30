#!/usr/bin/env bash
# batch throughput (docs/batch.md, bench/RESULTS.md "Batch"): medians of
# RUNS runs of `orthoray batch` on generated sweeps, with no file written
# but the results. Prints a markdown table on stdout.
#
#   bench/batch_scaling.sh [BUILD_DIR] [RUNS]
#
# Sweeps: "tiny" (10 mirrors, no box: most rays escape after a few
# reflections, so the time is batch's own overhead plus a small solve),
# "mixed" (100-mirror boxes: orbits from a few to 10^5 reflections, so
# instance costs differ by orders of magnitude). Each is run on 1 and 2
# threads, and with MPI (when the build has it) on 2 ranks of 1 thread.
set -euo pipefail
build=${1:-build}
runs=${2:-5}
bin="$build/orthoray"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# Wall seconds of one command, from bash's clock.
seconds() {
    local begin end
    begin=$(date +%s.%N)
    "$@" >/dev/null 2>&1 || true
    end=$(date +%s.%N)
    awk -v a="$begin" -v b="$end" 'BEGIN {print b - a}'
}

median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }

row() { # name words seeds
    local name=$1 words=$2 seeds=$3 count
    count=$(( ${seeds#*..} - ${seeds%..*} + 1 ))
    for mode in "1 thread" "2 threads" "MPI 2 ranks"; do
        local cmd
        case $mode in
        "1 thread") cmd=("$bin" batch --generate "$words" --seeds "$seeds" --jobs 1 -o "$work/r.jsonl" --quiet) ;;
        "2 threads") cmd=("$bin" batch --generate "$words" --seeds "$seeds" --jobs 2 -o "$work/r.jsonl" --quiet) ;;
        "MPI 2 ranks")
            command -v mpirun >/dev/null || continue
            "$bin" batch --help | grep -q -- --mpi || continue
            cmd=(mpirun -n 2 --oversubscribe "$bin" batch --generate "$words" --seeds "$seeds" --mpi -o "$work/r.jsonl" --quiet) ;;
        esac
        local t
        t=$(for _ in $(seq "$runs"); do seconds "${cmd[@]}"; done | median)
        printf '| %s | %s | %d | %.3f | %.0f |\n' "$name" "$mode" "$count" "$t" "$(awk -v n="$count" -v t="$t" 'BEGIN {print n / t}')"
    done
}

echo "| sweep | run | instances | median s | instances/s |"
echo "|---|---|---|---|---|"
row tiny "random --dim 2 --mirrors 10" 1..20000
row mixed "random --dim 2 --mirrors 100 --box" 1..400
# A rough cost of the MPI start: one rank, one instance.
if command -v mpirun >/dev/null && "$bin" batch --help | grep -q -- --mpi; then
    t=$(for _ in $(seq "$runs"); do seconds mpirun -n 1 "$bin" batch --generate "random --mirrors 10" --seeds 1 --mpi -o "$work/r.jsonl" --quiet; done | median)
    printf '\nmpirun start-up and shut-down (1 rank, 1 tiny instance): %.3f s median\n' "$t"
fi
