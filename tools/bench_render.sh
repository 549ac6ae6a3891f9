#!/usr/bin/env bash
# Renderer throughput, timed (a bench script, not a test): renders every shipped scene with
# the reference for a fixed wall time on one thread and prints paths and rays per
# CPU-second, then the same on two threads and the speed-up of the second thread (paths per
# wall-second, two threads over one) beside the CPUs the two threads kept busy. For scenes with meshes it adds the ray-casting test of
# `--stats` (src/renderer/render/raycast.rs): closest-hit rays per second through the scene,
# and that over obvhs' CWBVH traversing the mesh alone. Run it twice, before and after a
# change, in one session: these machines are shared, so only ratios measured side by side
# mean anything.
#
# Where Mitsuba 3 is installed (`pip install mitsuba`; its llvm_ad_rgb variant also needs
# `apt-get install libllvm19`), it then times Mitsuba on the twins of the same scenes
# (tools/bench_mitsuba.py: one thread, the same seconds per render, after a warm-up that
# compiles its kernels) and prints pbrlab's paths per CPU-second beside Mitsuba's
# llvm_ad_rgb and scalar_rgb, with the ratios. Scenes without a twin (tools/mitsuba_twin.py
# says why) show "no twin". Without Mitsuba it says so and stops after pbrlab's table.
#
#   tools/bench_render.sh [SECONDS per render, default 5] [SCENE.yaml ...]
#
# Without scenes it times the shipped ones and knot_115k, the knot scene with a finer mesh.
#
# PBRLAB=path/to/pbrlab times another build (say, a worktree of the commit before).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-5}"
shift || true
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then
    # The shipped scenes, and the knot scene with a 115,200-triangle tube (not shipped:
    # 5 MB that no lesson needs), written here by the mesh's own script.
    mkdir -p "$work/knot_115k/meshes"
    python3 scenes/meshes/make_knot.py 2400 24 >"$work/knot_115k/meshes/knot.obj"
    cp scenes/knot.yaml "$work/knot_115k/knot_115k.yaml"
    scenes=(scenes/*.yaml "$work/knot_115k/knot_115k.yaml")
fi
if [ -z "${PBRLAB:-}" ]; then
    cargo build --release --quiet --bin pbrlab
fi
pbrlab="${PBRLAB:-target/release/pbrlab}"

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

printf '%-16s %14s %14s %12s %10s   %s\n' scene "M paths/CPU-s" "M rays/CPU-s" "2 threads ×" \
    "CPUs busy" "ray casts, M/s (÷ CWBVH)"
for scene in "${scenes[@]}"; do
    render "$scene" 1
    paths=$(field "$work/stats.json" paths_per_cpu_second)
    echo "$(basename "$scene" .yaml) $paths" >>"$work/pbrlab.txt"
    rays=$(field "$work/stats.json" rays_per_cpu_second)
    one=$(field "$work/stats.json" paths_per_second)
    # Scenes with meshes: the --stats ray-casting test (`render::raycast`), one thread.
    casts=$(python3 -c 'import json, sys
r = json.load(open(sys.argv[1]))["raycast_vs_obvhs"]
print("%.2f (%.2f)" % (r["scene_rays_per_second"] / 1e6, r["ratio"]) if r else "")' \
        "$work/stats.json")
    render "$scene" 2
    two=$(field "$work/stats.json" paths_per_second)
    # CPU-seconds per wall-second of the two-thread render: below 2, its threads waited
    # (or the machine gave them less); the speed-up cannot exceed it.
    busy=$(python3 -c 'import json, sys
s = json.load(open(sys.argv[1]))["stats"]
print(s["cpu_seconds"] / s["wall_seconds"])' "$work/stats.json")
    python3 -c 'import sys
name, paths, rays, one, two, busy = sys.argv[1], *map(float, sys.argv[2:7])
print(f"{name:<16} {paths / 1e6:14.3f} {rays / 1e6:14.3f} {two / one:12.2f} {busy:10.2f}   {sys.argv[7]}")' \
        "$(basename "$scene" .yaml)" "$paths" "$rays" "$one" "$two" "$busy" "$casts"
done

echo
if ! python3 -c "import mitsuba" 2>/dev/null; then
    echo "Mitsuba 3 is not installed (pip install mitsuba): no comparison with it"
    exit 0
fi
if ! python3 tools/bench_mitsuba.py --seconds "$seconds" --json "$work/mitsuba.json" "${scenes[@]}"; then
    echo "tools/bench_mitsuba.py failed: no comparison with Mitsuba"
    exit 0
fi
echo
python3 - "$work/pbrlab.txt" "$work/mitsuba.json" <<'EOF'
import json, sys
ours = {name: float(rate) for name, rate in map(str.split, open(sys.argv[1]))}
theirs = json.load(open(sys.argv[2]))
print("M paths per CPU-second, one thread: pbrlab, Mitsuba (mi) and their ratios")
print("%-16s %12s %12s %12s %12s %12s" % ("scene", "pbrlab", "mi llvm", "mi scalar",
                                          "pbrlab/llvm", "pbrlab/scalar"))
for name, rate in ours.items():
    if name not in theirs:
        print("%-16s %12.3f %12s" % (name, rate / 1e6, "no twin"))
        continue
    llvm, scalar = (theirs[name].get(v) for v in ("llvm_ad_rgb", "scalar_rgb"))
    cells = ["%12.3f" % (x / 1e6) if x else "%12s" % "-" for x in (llvm, scalar)]
    cells += ["%12.2f" % (rate / x) if x else "%12s" % "-" for x in (llvm, scalar)]
    print("%-16s %12.3f %s" % (name, rate / 1e6, " ".join(cells)))
EOF
