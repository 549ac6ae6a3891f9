"""Mitsuba 3 "twins" of pbrlab scenes: `mitsuba_scene(path, spp)` reads a pbrlab YAML scene
and returns the same scene as a Mitsuba scene dict (for `mi.load_dict`), or raises
`NoTwin(reason)` naming everything in it that has no exact Mitsuba counterpart. Callers pick
the variant (`mi.set_variant`) first: the dict holds transforms of the active variant.
Used by tools/mitsuba_compare.py (images) and tools/bench_mitsuba.py (speed).

Mapped: quads, spheres, boxes, OBJ meshes with transforms; diffuse (cosine sampling),
mirror, dielectric (exact Fresnel), GGX conductors given by `eta` and `k` (both renderers
use the exact conductor Fresnel equations) or with `reflectance: 1` (Schlick with f0 = 1 is
exactly F = 1, which Mitsuba's `material: none` matches), isotropic, or anisotropic on
quads and spheres (pbrlab's alpha_x runs along edge1, or along the parallels around y;
Mitsuba's alpha_u along its dp/du, placed to match); area, point and constant environment
lights; homogeneous and density-grid media (grid files and pbrlab's procedural cloud,
whose lattice values and permutation are reproduced exactly). pbrlab's conventions
(two-sided opaque materials, box filter, vertical field of view, max_depth counting
segments, media boundaries that are not segments, density grid points on the corners of
the shape's box) are mapped onto Mitsuba's.

No twin: Phong and Kajiya-Kay (Mitsuba 3 has neither), hair fibres (ray-facing ribbons),
Schlick conductors with f0 other than 1 (Mitsuba's conductors have only the exact
equations or F = 1), anisotropic conductors on meshes (Mitsuba's tangent there depends on
nothing pbrlab's does), Schlick dielectrics, uniform hemisphere sampling, density grids in
meshes.

Not mapped, as they change weights but hardly the work: pbrlab's `strategy` and
`heuristic` (Mitsuba's path and volpath always combine light and BSDF sampling by MIS with
the power heuristic; pbrlab traces the same rays whichever it uses) and `transmittance`
(Mitsuba's volpath uses ratio tracking, pbrlab's default).

Checked against pbrlab's reference renders at 256-512 spp (tools/mitsuba_compare.py, and
16 × 16-pixel block means): cornell, furnace, glass, knot and smoke agree within noise; so
does a test scene with anisotropic copper on a sphere and a quad (with alpha_x and alpha_y
swapped, blocks differ by up to 80 %).
"""
import functools
import math
import os
import struct

import drjit as dr
import mitsuba as mi
import yaml


class NoTwin(Exception):
    """The scene uses a feature that has no exact Mitsuba counterpart (the reason)."""

    def __init__(self, reason, names=()):
        super().__init__(reason + (": " + ", ".join(names) if names else ""))
        self.reason, self.names = reason, list(names)


def quad_matrix(o, e1, e2):
    o, e1, e2 = map(mi.ScalarVector3f, (o, e1, e2))
    n = dr.normalize(dr.cross(e1, e2))
    c = o + (e1 + e2) / 2
    # Mitsuba's rectangle is [-1, 1]² in z = 0 with dp/du along x: mapping x to edge1
    # keeps the tangent (for anisotropy) on edge1, as pbrlab's quad has it.
    rows = [[e1[i] / 2, e2[i] / 2, n[i], c[i]] for i in range(3)]
    return mi.ScalarTransform4f(rows + [[0, 0, 0, 1]])


def rgb(v):
    return {"type": "rgb", "value": [v] * 3 if isinstance(v, (int, float)) else v}


def bsdf(name, spec, shape_kind):
    (kind, p), = spec.items()
    if kind == "diffuse":
        if p.get("sampling", "cosine") != "cosine":
            raise NoTwin("uniform diffuse sampling (Mitsuba's is cosine)", [name])
        return {"type": "twosided", "b": {"type": "diffuse", "reflectance": rgb(p["albedo"])}}
    if kind == "mirror":
        return {"type": "twosided", "b": {"type": "conductor", "material": "none",
                                          "specular_reflectance": rgb(p.get("reflectance", 1))}}
    if kind == "conductor":
        if "roughness" in p:
            twin = {"type": "roughconductor", "distribution": "ggx", "alpha": p["roughness"]}
        elif shape_kind in ("quad", "sphere"):
            # pbrlab's alpha_x runs along the shading tangent, as Mitsuba's alpha_u does.
            twin = {"type": "roughconductor", "distribution": "ggx",
                    "alpha_u": p["alpha_x"], "alpha_v": p["alpha_y"]}
        else:
            raise NoTwin(f"anisotropic conductor on a {shape_kind} (whose tangent Mitsuba "
                         "picks arbitrarily)", [name])
        if "eta" in p:
            twin.update(eta=rgb(p["eta"]), k=rgb(p["k"]))
        elif p.get("reflectance") == 1:
            twin.update(material="none", specular_reflectance=rgb(1))
        else:
            raise NoTwin(f"Schlick conductor of reflectance {p.get('reflectance')} (Mitsuba's "
                         "conductors have exact Fresnel or F = 1 only)", [name])
        return {"type": "twosided", "b": twin}
    if kind == "dielectric":
        if p.get("fresnel", "exact") != "exact":
            raise NoTwin("Schlick dielectric", [name])
        return {"type": "dielectric", "int_ior": p["ior"], "ext_ior": p.get("ext_ior", 1.0)}
    raise NoTwin(f"{kind} material (Mitsuba 3 has none)", [name])


def f32(x):
    """x rounded to single precision, as pbrlab computes it."""
    return struct.unpack("f", struct.pack("f", x))[0]


class Pcg32:
    """rand_pcg's Lcg64Xsh32 (PCG32), as pbrlab's Sampler seeds and draws it."""
    MASK = (1 << 64) - 1
    MUL = 6364136223846793005

    def __init__(self, seed, stream):
        self.inc = ((stream << 1) | 1) & self.MASK
        self.state = ((seed + self.inc) * self.MUL + self.inc) & self.MASK

    def next_u32(self):
        s = self.state
        self.state = (s * self.MUL + self.inc) & self.MASK
        x = (((s >> 18) ^ s) >> 27) & 0xFFFFFFFF
        r = s >> 59
        return ((x >> r) | (x << (32 - r))) & 0xFFFFFFFF

    def next_1d(self):
        return (self.next_u32() >> 8) / (1 << 24)


@functools.lru_cache
def cloud(res, seed, frequency, octaves):
    """pbrlab's procedural cloud (src/renderer/scene/density.rs): fractal value noise under
    a spherical falloff; a flat list, x fastest. Same lattice values and permutation; the
    arithmetic is in double precision (the noise is continuous, so this moves values by
    about 1e-7)."""
    rng = Pcg32(seed ^ 0x853C49E6748FEA9B, 0x6E6F697365)
    table = [rng.next_1d() for _ in range(256)]
    perm = list(range(256))
    for i in range(255, 0, -1):
        # In single precision, as in pbrlab: a rounded product picks a different j.
        j = min(int(f32(rng.next_1d() * (i + 1))), i)
        perm[i], perm[j] = perm[j], perm[i]

    def lattice(x, y, z):
        return table[perm[(perm[(perm[x % 256] + y) % 256] + z) % 256]]

    coord = [i / (res - 1) for i in range(res)]
    value = [0.0] * res ** 3
    amplitude, f = 0.5, frequency
    for _ in range(octaves):
        # The smoothstep weights and lattice cell depend on one axis each.
        cells = []
        for u in coord:
            p = u * f
            b = math.floor(p)
            t = p - b
            cells.append((b, t * t * (3 - 2 * t)))
        k = 0
        for bz, sz in cells:
            for by, sy in cells:
                for bx, sx in cells:
                    c = [[[lattice(bx + dx, by + dy, bz + dz) for dx in (0, 1)]
                          for dy in (0, 1)] for dz in (0, 1)]
                    x = [[a + (b - a) * sx for a, b in row] for row in c]
                    y = [a + (b - a) * sy for a, b in x]
                    value[k] += amplitude * (y[0] + (y[1] - y[0]) * sz)
                    k += 1
        amplitude *= 0.5
        f *= 2
    total = 1 - 0.5 ** octaves
    out = []
    k = 0
    for z in coord:
        for y in coord:
            for x in coord:
                r = math.sqrt((2 * x - 1) ** 2 + (2 * y - 1) ** 2 + (2 * z - 1) ** 2)
                v = value[k] / total
                out.append(min(max(2 * (1 - r) - 0.6 + 1.2 * (v - 0.5), 0.0), 1.0))
                k += 1
    return out


def density(spec, scene_dir):
    """A density grid as (values x fastest, (nx, ny, nz))."""
    (kind, p), = spec.items()
    if kind == "file":
        text = open(os.path.join(scene_dir, p)).read()
        words = [w for line in text.splitlines() for w in line.split("#")[0].split()]
        return [float(w) for w in words[3:]], tuple(map(int, words[:3]))
    if kind == "cloud":
        n = p["resolution"]
        return cloud(n, p.get("seed", 0), p.get("frequency", 4.0), p.get("octaves", 4)), (n, n, n)
    raise NoTwin("density " + kind)


def medium(name, spec, bounds, scene_dir):
    (kind, p), = spec.items()
    st = p["sigma_a"] + p["sigma_s"]
    phase = {"type": "hg", "g": p.get("g", 0.0)}
    if kind == "homogeneous":
        return {"type": "homogeneous", "sigma_t": st, "albedo": p["sigma_s"] / st, "phase": phase}
    if kind != "grid":
        raise NoTwin(f"{kind} medium", [name])
    if bounds is None:
        raise NoTwin("density grid inside a mesh", [name])
    values, res = density(p["density"], scene_dir)
    # pbrlab's grid points sit on the corners of the shape's bounding box (point i at
    # i / (n - 1)); Mitsuba's texels are cell-centred (at (i + 0.5) / n of its unit cube).
    # Widening the cube by half a cell on every side puts the texel centres on pbrlab's
    # points, so the trilinear interpolation inside the box is the same.
    lo, hi = bounds
    cell = [(h - l) / (n - 1) for l, h, n in zip(lo, hi, res)]
    T = mi.ScalarTransform4f()
    to_world = (T.translate([l - c / 2 for l, c in zip(lo, cell)])
                @ T.scale([c * n for c, n in zip(cell, res)]))
    grid = mi.VolumeGrid(dr.scalar.TensorXf(values, shape=(res[2], res[1], res[0], 1)))
    # The majorant is then the grid's largest value times sigma_t, as pbrlab's is.
    return {"type": "heterogeneous", "albedo": p["sigma_s"] / st, "scale": st, "phase": phase,
            "sigma_t": {"type": "gridvolume", "grid": grid,
                        "filter_type": "trilinear", "to_world": to_world}}


MEDIUM_INSET = 1e-3  # see shape()


def record(missing, build, *args):
    """build(*args), or None after adding its NoTwin to `missing` (reason -> names)."""
    try:
        return build(*args)
    except NoTwin as e:
        names = missing.setdefault(e.reason, [])
        names += [n for n in e.names if n not in names]


def shape(kind, p, s, scene_dir, missing):
    """The Mitsuba shape of one pbrlab shape `kind: p` of the scene `s`; what has no
    counterpart goes into `missing` instead (the shape is then incomplete)."""
    T = mi.ScalarTransform4f()
    bounds = None  # the box a density grid inside spans
    # Where a medium's boundary and a surface coincide (smoke's fog box stands on the
    # floor), pbrlab's surface wins (boundaries are searched only up to the nearest surface
    # hit) and the path stays in the medium; Mitsuba picks either and then loses track of
    # the medium (the floor under the fog came out 5 % dark, with a sharp edge). Insetting
    # media by 1e-3 separates the two (1e-4 was not enough: 20 % dark) and moves every
    # other pixel by less than the noise.
    inset = MEDIUM_INSET if "medium" in p else 0
    if kind == "quad":
        d = {"type": "rectangle", "to_world": quad_matrix(p["origin"], p["edge1"], p["edge2"])}
    elif kind == "sphere":
        ctr, rad = p["center"], p["radius"]
        # Pole along y: Mitsuba's sphere tangent runs along the parallels around its local
        # z, pbrlab's around world y.
        d = {"type": "sphere",
             "to_world": T.translate(ctr) @ T.rotate([1, 0, 0], -90) @ T.scale(rad - inset)}
        bounds = ([x - rad for x in ctr], [x + rad for x in ctr])
    elif kind == "box":
        lo, hi = p["min"], p["max"]
        d = {"type": "cube", "to_world": T.translate([(l + h) / 2 for l, h in zip(lo, hi)])
             @ T.scale([(h - l) / 2 - inset for l, h in zip(lo, hi)])}
        bounds = (lo, hi)
    elif kind == "mesh":
        t = p.get("transform", {})
        sc = t.get("scale", 1)
        sc = [sc] * 3 if isinstance(sc, (int, float)) else sc
        rx, ry, rz = t.get("rotate", [0, 0, 0])
        to_world = (T.translate(t.get("translate", [0, 0, 0])) @ T.rotate([0, 0, 1], rz)
                    @ T.rotate([0, 1, 0], ry) @ T.rotate([1, 0, 0], rx) @ T.scale(sc))
        d = {"type": "obj", "filename": os.path.join(scene_dir, p["file"]),
             "to_world": to_world, "face_normals": True}
    else:
        missing[f"{kind} (ray-facing ribbons; Mitsuba's curves are round)"] = []
        d = {}
    if "material" in p:  # checked for fibres too, to name every reason
        d["bsdf"] = record(missing, bsdf, p["material"], s["materials"][p["material"]], kind)
    elif "medium" in p:
        d["bsdf"] = {"type": "null"}  # an index-matched boundary
        d["interior"] = record(missing, medium, p["medium"], s["media"][p["medium"]], bounds,
                               scene_dir)
    else:
        d["bsdf"] = {"type": "diffuse", "reflectance": rgb(0)}  # pbrlab's Black
    if "emission" in p:
        d["emitter"] = {"type": "area", "radiance": rgb(p["emission"])}
    return d


def mitsuba_scene(path, spp):
    """The Mitsuba scene dict of the pbrlab scene at `path`, at `spp` samples per pixel;
    raises NoTwin listing everything that has no Mitsuba counterpart."""
    s = yaml.safe_load(open(path))
    scene_dir = os.path.dirname(path)
    c, r = s["camera"], s.get("render") or {}
    md = r.get("max_depth")
    shapes = s.get("shapes") or []
    scene = {
        "type": "scene",
        # Mitsuba's max_depth counts segments as pbrlab's does (1: emitters seen directly,
        # 2: direct lighting; -1 unbounded), and both start Russian roulette at rr_depth
        # with survival min(max(throughput), 0.95).
        "integrator": {"type": "volpath" if any("medium" in next(iter(sh.values()))
                                                for sh in shapes) else "path",
                       "max_depth": -1 if md is None else md, "rr_depth": r.get("rr_depth", 5)},
        "sensor": {"type": "perspective", "fov_axis": "y", "fov": c["fov"],
                   "to_world": mi.ScalarTransform4f().look_at(
                       origin=c["eye"], target=c["target"], up=c.get("up", [0, 1, 0])),
                   "film": {"type": "hdrfilm", "width": c["width"], "height": c["height"],
                            "rfilter": {"type": "box"}, "pixel_format": "rgb"},
                   "sampler": {"type": "independent", "sample_count": spp}},
    }
    missing = {}  # every reason (and what it is about), not just the first
    for i, sh in enumerate(shapes):
        (kind, p), = sh.items()
        scene["shape%d" % i] = shape(kind, p, s, scene_dir, missing)
    for i, light in enumerate(s.get("lights") or []):
        (kind, p), = light.items()
        if kind == "environment":
            scene["env"] = {"type": "constant", "radiance": rgb(p["radiance"])}
        elif kind == "point":
            scene["point%d" % i] = {"type": "point", "position": p["position"],
                                    "intensity": rgb(p["intensity"])}
        else:
            missing[kind + " light"] = []
    if missing:
        raise NoTwin("; ".join(str(NoTwin(r, n)) for r, n in missing.items()))
    return scene
