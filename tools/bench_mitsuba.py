"""Mitsuba 3's render throughput on twins of pbrlab's scenes, on one thread.

A bench, not a test: for each scene with a twin (tools/mitsuba_twin.py), renders it with
the variants llvm_ad_rgb (Dr.Jit compiles the whole path tracer into one vectorised LLVM
kernel) and scalar_rgb (C++, one path at a time), and prints million paths (pixels × spp)
per CPU-second, the figure tools/bench_render.sh prints for pbrlab.

    python3 tools/bench_mitsuba.py [--seconds 5] [--json FILE] [SCENE.yaml ...]

How: Dr.Jit's thread pool is set to one thread (`dr.set_thread_count(1)`: the calling
thread does all the work), and every render is timed with `time.process_time()`, the CPU
time of all the process's threads. The `caller` column, the share of it spent on the
calling thread (`time.thread_time()`), checks that no other thread worked: 100 %, where
two threads give 50 %. (CPU over wall time would not tell: on a shared machine, two
threads that get one core between them look like one.) Warm-up renders come first (see
`warm_up`), so no timing includes compiling kernels; calibration renders, doubling spp,
then pick the spp at which the timed render takes about SECONDS of CPU time.

Installing: `pip install mitsuba` (brings Dr.Jit). llvm_ad_rgb also needs a shared
libLLVM (`apt-get install libllvm19`), which Dr.Jit finds in /usr/lib/<arch> by itself
(DRJIT_LIBLLVM_PATH picks another); without one it is skipped.
"""
import argparse
import glob
import json
import os
import sys
import time

import drjit as dr
import mitsuba as mi

from mitsuba_twin import NoTwin, mitsuba_scene

VARIANTS = ("llvm_ad_rgb", "scalar_rgb")


def render(scene, spp, passes=1):
    """(process CPU seconds, calling thread's CPU seconds) of `passes` renders at `spp`,
    evaluated to the last pixel."""
    c, t = time.process_time(), time.thread_time()
    for seed in range(passes):
        image = mi.render(scene, spp=spp, seed=seed)
        # JIT variants evaluate lazily: the time must include running the kernels.
        dr.eval(image)
        dr.sync_thread()
    return time.process_time() - c, time.thread_time() - t


def cache_misses():
    """Kernels compiled (not found in Dr.Jit's cache) since the last call."""
    return sum(1 for k in dr.kernel_history()
               if k.get("type") == dr.KernelType.JIT and not k.get("cache_hit"))


def warm_up(scene):
    # The first render of a JIT variant compiles its kernel (about 0.1 s, and the LLVM
    # setup on top); later ones find it in the cache. mi.render builds a different kernel
    # for a power-of-two spp (a shift) than for any other (a division), so both are
    # rendered here, and whatever spp the calibration then picks is already compiled.
    for spp in (1, 3):
        render(scene, spp)


def bench(path, variant, seconds):
    """(spp, paths per CPU-second, share of the CPU time on the calling thread) of
    `variant` on the twin of `path`."""
    mi.set_variant(variant)
    scene = mi.load_dict(mitsuba_scene(path, 1))
    width, height = scene.sensors()[0].film().size()
    jit = variant.startswith(("llvm", "cuda"))
    dr.set_flag(dr.JitFlag.KernelHistory, jit)
    warm_up(scene)
    # Calibrate: double spp until a render takes a tenth of the budget (0.2 s at least).
    target, spp = min(seconds, max(0.2, seconds / 10)), 1
    while True:
        cpu, _ = render(scene, spp)
        if cpu >= target or spp >= 1 << 20:
            break
        spp *= 2
    spp = max(1, round(spp * seconds / cpu))
    # Mitsuba renders at most 2^32 paths at once: split longer renders into passes.
    passes = -(-width * height * spp // 2**31)
    spp = -(-spp // passes)
    cache_misses()
    cpu, own = render(scene, spp, passes)
    if jit and cache_misses():
        cpu, own = render(scene, spp, passes)  # a kernel was compiled in the timing: again
    return spp * passes, width * height * spp * passes / cpu, own / cpu


def llvm_library():
    """The libLLVM Dr.Jit loaded (Linux), for the header."""
    try:
        with open("/proc/self/maps") as maps:
            names = {line.split()[-1] for line in maps if "libLLVM" in line}
        return ", ".join(sorted(names)) or "?"
    except OSError:
        return "?"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scenes", nargs="*", help="pbrlab scenes (default scenes/*.yaml)")
    ap.add_argument("--seconds", type=float, default=5, help="CPU seconds per timed render")
    ap.add_argument("--json", help="also write {scene: {variant: paths_per_cpu_second}} here")
    a = ap.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    scenes = a.scenes or sorted(glob.glob(os.path.join(root, "scenes", "*.yaml")))

    # One thread: the caller's. Dr.Jit's pool (nanothread) runs the LLVM kernels and
    # Mitsuba's scalar render blocks alike.
    dr.set_thread_count(1)
    variants = []
    for v in VARIANTS:
        if v not in mi.variants():
            print(f"{v}: not in this Mitsuba build, skipped")
            continue
        try:
            mi.set_variant(v)  # an ImportError for llvm_* when libLLVM cannot be loaded
        except ImportError as e:
            print(f"{v}: skipped: {e}")
            continue
        variants.append(v)
    extra = f", {llvm_library()}" if any(v.startswith("llvm") for v in variants) else ""
    print(f"Mitsuba {mi.__version__}, Dr.Jit {dr.__version__}{extra}; one thread, "
          f"{a.seconds:g} CPU-s per render")

    results = {}
    print("%-16s %-12s %7s %14s %7s" % ("scene", "variant", "spp", "M paths/CPU-s", "caller"))
    for path in scenes:
        name = os.path.splitext(os.path.basename(path))[0]
        for variant in variants:
            try:
                spp, rate, caller = bench(path, variant, a.seconds)
            except NoTwin as e:
                print("%-16s no twin: %s" % (name, e))
                break
            results.setdefault(name, {})[variant] = rate
            print("%-16s %-12s %7d %14.3f %6.0f%%" % (name, variant, spp, rate / 1e6,
                                                      100 * caller))
            sys.stdout.flush()
    if a.json:
        with open(a.json, "w") as f:
            json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
