#!/usr/bin/env python3
"""Where a render's instructions go, by part of the renderer, from callgrind profiles.

    valgrind --tool=callgrind --callgrind-out-file=cornell.cg \
        target/release/pbrlab render scenes/cornell.yaml --spp 8 --threads 1 \
        --impl reference --quiet -o /tmp/cornell.exr
    tools/profile_parts.py cornell.cg [more.cg ...]

Prints a Markdown table: per part, billions of instructions (self cost, inlined functions
counted as their caller) and the share of the whole run, one column per profile. Parts are
told apart by function name (PARTS below, first match wins); src/renderer/PROFILE.md holds
the tables made with it.
"""
import re
import subprocess
import sys

PARTS = [
    ("scene loading and BVH build",
     r"obvhs::(ploc|bvh2|cwbvh::builder|cwbvh::bvh2_to_cwbvh|splits|aabb)|Bvh::build|"
     r"Bvh::collapse|tobj|saphyr|scene::load|scene::obj|TriangleSet::new|FibreSet::new|"
     r"radsort|rdst|Bvh2Converter|ReinsertionOptimizer|PlocBuilder|strands|SplitWhitespace|"
     r"dec2flt|hash|memchr|Utf8Chunks|CharSearcher|append_to_string|from_utf8"),
    ("traversal and intersection",
     r"Geometry::(intersect|occluded)|Scene::(intersect|occluded)|CwBvh::ray_traverse|"
     r"bvh::Bvh::|WatertightRay|TriangleSet::(intersect|occluded|hit)|"
     r"FibreSet::(intersect|occluded|hit)|FibreSegment|Sphere::hit|Quad::hit|packs::|LocalKey"),
    ("integrator (path_trace, mis, volpath)",
     r"pbrlab_solutions::(path_trace|mis|delta_tracking)|integrator::|Hit::spawn|volpath"),
    ("BSDF evaluation and sampling (tasks included)",
     r"bsdf::|cook_torrance|ndf|smith_g1|fresnel|cosine_|reflect|refract|phong|kajiya|"
     r"beckmann|optics::"),
    ("light sampling", r"light::|Lights::|Patch::"),
    ("render loop, camera, film and output",
     r"call_mut|render::|png::|exr::|image::|Film|PixelSums|checkpoint|zune|miniz|fdeflate|"
     r"flate|crc32|adler|Camera"),
    ("calls through the task table", r"FnOnce::call_once|TaskFns"),
    ("libm (powf, trigonometry)", r"libm\.so|sincosf|powf|expf|logf|atan|acos|hypot"),
    ("memory and runtime", r"libc\.so|malloc|free|memcpy|memset|memmove|rayon|ld-linux|_dl_"),
]


def parts(path):
    """The whole run's instructions and each part's, from one callgrind file."""
    out = subprocess.run(["callgrind_annotate", "--threshold=100", path],
                         capture_output=True, text=True, check=True).stdout
    total, counts = 0, {name: 0 for name, _ in PARTS + [("other", "")]}
    for line in out.splitlines():
        m = re.match(r"\s*([\d,]+) \(\s*[\d.]+%\)\s+(.*)", line)
        if not m:
            continue
        n, function = int(m.group(1).replace(",", "")), m.group(2)
        if "PROGRAM TOTALS" in function:
            total = n
            continue
        part = next((name for name, rx in PARTS if re.search(rx, function)), "other")
        counts[part] += n
    return total, counts


def main():
    columns = [parts(p) for p in sys.argv[1:]]
    heads = ["%s (%.2f G)" % (p, t / 1e9) for p, (t, _) in zip(sys.argv[1:], columns)]
    print("| part | " + " | ".join(heads) + " |")
    print("|---" * (len(columns) + 1) + "|")
    for name in [n for n, _ in PARTS] + ["other"]:
        cells = ["%.2f (%.0f %%)" % (c[name] / 1e9, 100 * c[name] / t) for t, c in columns]
        print("| %s | %s |" % (name, " | ".join(cells)))


if __name__ == "__main__":
    main()
