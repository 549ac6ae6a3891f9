#!/usr/bin/env bash
# Renderer throughput, timed (a bench script, not a test): renders every shipped scene with
# the reference for a fixed wall time on one thread and prints paths and rays per
# CPU-second, then the same on two threads and the speed-up of the second thread (paths per
# wall-second, two threads over one). Run it twice, before and after a change, in one
# session: these machines are shared, so only ratios measured side by side mean anything.
#
# It does not time Mitsuba 3: these machines have no network to install it from, so a
# twin's timing could not be written and checked here (tools/mitsuba_compare.py compares
# images where Mitsuba is installed).
#
#   tools/bench_render.sh [SECONDS per render, default 5] [SCENE.yaml ...]
#
# PBRLAB=path/to/pbrlab times another build (say, a worktree of the commit before).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-5}"
shift || true
scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then
    scenes=(scenes/*.yaml)
fi
if [ -z "${PBRLAB:-}" ]; then
    cargo build --release --quiet --bin pbrlab
fi
pbrlab="${PBRLAB:-target/release/pbrlab}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# `field FILE NAME`: one number of a render's --stats JSON.
field() {
    python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["stats"][sys.argv[2]])' "$1" "$2"
}

# `render SCENE THREADS`: renders for $seconds (far more samples asked for than fit) and
# leaves the statistics in $work/stats.json.
render() {
    "$pbrlab" render "$1" --impl reference --threads "$2" --spp 1048576 \
        --time "$seconds" --quiet -o "$work/image.exr" --stats "$work/stats.json" >/dev/null
}

printf '%-16s %14s %14s %12s\n' scene "M paths/CPU-s" "M rays/CPU-s" "2 threads ×"
for scene in "${scenes[@]}"; do
    render "$scene" 1
    paths=$(field "$work/stats.json" paths_per_cpu_second)
    rays=$(field "$work/stats.json" rays_per_cpu_second)
    one=$(field "$work/stats.json" paths_per_second)
    render "$scene" 2
    two=$(field "$work/stats.json" paths_per_second)
    python3 -c 'import sys
name, paths, rays, one, two = sys.argv[1], *map(float, sys.argv[2:])
print(f"{name:<16} {paths / 1e6:14.3f} {rays / 1e6:14.3f} {two / one:12.2f}")' \
        "$(basename "$scene" .yaml)" "$paths" "$rays" "$one" "$two"
done
