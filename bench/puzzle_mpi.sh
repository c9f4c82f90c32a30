#!/usr/bin/env bash
# puzzle solve --mpi against one process (docs/puzzles.md, "On many
# machines"; bench/RESULTS.md "Batch and MPI"): medians of RUNS runs of
# `puzzle solve LEVEL --all` (the whole search) on one process with 1 and 2
# threads, and on 2 MPI ranks. Two times each: the whole command (wall, from
# bash's clock, MPI start included) and the search alone (the "seconds" that
# --json reports, measured by rank 0). Prints a markdown table on stdout.
#
#   bench/puzzle_mpi.sh [BUILD_DIR] [RUNS] [LEVEL...]
set -euo pipefail
build=${1:-build}
runs=${2:-5}
shift $(( $# >= 2 ? 2 : $# ))
levels=("$@")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ ${#levels[@]} -eq 0 ]; then
    # The slowest committed levels take a tenth of a second, less than
    # mpirun's start; reflect-10x10 with only its first 6 points keeps 8
    # blocks and a wide search (~1.6 10^5 nodes, 2.3 10^8 solutions).
    sed '/^P /d' instances/puzzles/reflect-10x10.bff > "$work/reflect-10x10-6-points.bff"
    grep '^P ' instances/puzzles/reflect-10x10.bff | head -6 >> "$work/reflect-10x10-6-points.bff"
    levels=(instances/puzzles/reflect-10x10.bff instances/puzzles/reflect-9x9.bff
            instances/puzzles/refract-7x7.bff "$work/reflect-10x10-6-points.bff")
fi
bin="$build/orthoray"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }

# "WALL SEARCH" seconds of one run.
one_run() {
    local begin end json
    begin=$(date +%s.%N)
    json=$("$@" 2>/dev/null || true)
    end=$(date +%s.%N)
    awk -v a="$begin" -v b="$end" -v s="$(sed -n 's/.*"seconds": *\([0-9.e+-]*\).*/\1/p' <<<"$json")" \
        'BEGIN {print b - a, s}'
}

echo "| level | nodes (--all) | run | median wall s | median search s |"
echo "|---|---|---|---|---|"
for level in "${levels[@]}"; do
    nodes=$("$bin" puzzle solve "$level" --all --json --jobs 1 | sed -n 's/.*"nodes": *\([0-9]*\).*/\1/p')
    for mode in "1 thread" "2 threads" "MPI 2 ranks"; do
        case $mode in
        "1 thread") cmd=("$bin" puzzle solve "$level" --all --json --quiet --jobs 1) ;;
        "2 threads") cmd=("$bin" puzzle solve "$level" --all --json --quiet --jobs 2) ;;
        "MPI 2 ranks")
            command -v mpirun >/dev/null || continue
            "$bin" puzzle solve --help | grep -q -- --mpi || continue
            cmd=(mpirun -n 2 --oversubscribe "$bin" puzzle solve "$level" --all --json --quiet --mpi) ;;
        esac
        samples=$(for _ in $(seq "$runs"); do one_run "${cmd[@]}"; done)
        wall=$(awk '{print $1}' <<<"$samples" | median)
        search=$(awk '{print $2}' <<<"$samples" | median)
        printf '| %s | %s | %s | %.3f | %.3f |\n' "$(basename "$level")" "$nodes" "$mode" "$wall" "$search"
    done
done
