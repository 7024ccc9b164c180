#!/usr/bin/env python3
"""Generate the low-poly OBJ models in models/ (one per kind and damage state) and their shared
material file models/materials.mtl.

Convention (src/world/model.hpp): metres, z up, +y forward (the heading direction), x right,
origin at the centre of the ground contact (ships: at the waterline centre). Every model is a set of
closed parts; each part is oriented so its faces wind counter-clockwise seen from outside (checked
by the signed volume), non-planar faces are split into triangles, and degenerate faces are
rejected. Wrecks are the intact parts moved, tilted, squashed, jittered and blackened.

Usage: python3 tools/make_models.py [OUT_DIR]   (default: models/ next to this tools/ folder)
"""
import math
import os
import random
import sys

# ---------------------------------------------------------------- materials (Kd diffuse colour)
MATERIALS = {
    "bark": (0.40, 0.26, 0.13),
    "leaves": (0.13, 0.42, 0.12),
    "leaves_dark": (0.10, 0.33, 0.10),
    "leaves_dry": (0.42, 0.40, 0.14),
    "bush": (0.20, 0.38, 0.11),
    "bush_dry": (0.36, 0.36, 0.15),
    "wood_cut": (0.78, 0.62, 0.40),
    "pole": (0.33, 0.24, 0.15),
    "insulator": (0.80, 0.85, 0.80),
    "wall": (0.80, 0.74, 0.60),
    "wall_dirty": (0.55, 0.50, 0.42),
    "roof": (0.58, 0.20, 0.13),
    "window": (0.18, 0.24, 0.34),
    "door": (0.36, 0.22, 0.12),
    "rubble": (0.50, 0.46, 0.40),
    "concrete": (0.60, 0.60, 0.56),
    "slit": (0.06, 0.06, 0.06),
    "steel": (0.42, 0.45, 0.48),
    "tank_white": (0.80, 0.85, 0.90),
    "tank_roof": (0.52, 0.58, 0.64),
    "rust": (0.45, 0.22, 0.10),
    "rock": (0.50, 0.48, 0.45),
    "rock_dark": (0.40, 0.38, 0.36),
    "m1_sand": (0.66, 0.58, 0.40),
    "m1_dark": (0.52, 0.45, 0.30),
    "track": (0.13, 0.13, 0.12),
    "gun": (0.30, 0.30, 0.28),
    "hmmwv": (0.46, 0.46, 0.30),
    "tyre": (0.07, 0.07, 0.07),
    "glass": (0.16, 0.22, 0.30),
    "bmp": (0.28, 0.36, 0.18),
    "bmp_dark": (0.22, 0.28, 0.14),
    "hull_grey": (0.56, 0.59, 0.63),
    "deck": (0.36, 0.38, 0.40),
    "antifoul": (0.52, 0.14, 0.11),
    "jet_grey": (0.58, 0.61, 0.65),
    "jet_dark": (0.40, 0.43, 0.47),
    "heli": (0.25, 0.29, 0.19),
    "rotor": (0.10, 0.10, 0.10),
    "shell": (0.36, 0.39, 0.20),
    "brass": (0.76, 0.60, 0.22),
    "missile": (0.85, 0.85, 0.80),
    "missile_dark": (0.25, 0.27, 0.20),
    "generic_ground": (0.55, 0.50, 0.42),
    "generic_air": (0.70, 0.70, 0.72),
    "generic_sea": (0.62, 0.64, 0.68),
    "marker": (0.95, 0.55, 0.05),
    "charred": (0.11, 0.10, 0.09),
    "charred2": (0.19, 0.16, 0.13),
    "ash": (0.30, 0.29, 0.27),
}


# ---------------------------------------------------------------- vector helpers
def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def add(a, b): return (a[0] + b[0], a[1] + b[1], a[2] + b[2])
def mul(a, s): return (a[0] * s, a[1] * s, a[2] * s)
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def norm(a): return math.sqrt(dot(a, a))
def unit(a):
    n = norm(a)
    return mul(a, 1.0 / n)


def rot_x(deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return ((1, 0, 0), (0, c, -s), (0, s, c))
def rot_y(deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return ((c, 0, s), (0, 1, 0), (-s, 0, c))
def rot_z(deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return ((c, -s, 0), (s, c, 0), (0, 0, 1))
def mat_vec(m, v):
    return tuple(m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2] for r in range(3))


class Part:
    """A closed polyhedron: vertices and faces (vertex index lists with a material each)."""

    def __init__(self):
        self.v = []
        self.f = []  # (indices, material)

    def vert(self, p):
        self.v.append(tuple(float(c) for c in p))
        return len(self.v) - 1

    def face(self, idx, mat):
        self.f.append((list(idx), mat))

    # transforms return self so they chain
    def move(self, d):
        self.v = [add(p, d) for p in self.v]
        return self

    def rotate(self, m, about=(0, 0, 0)):
        self.v = [add(mat_vec(m, sub(p, about)), about) for p in self.v]
        return self

    def scale(self, s, about=(0, 0, 0)):
        self.v = [add((d[0] * s[0], d[1] * s[1], d[2] * s[2]), about) for d in (sub(p, about) for p in self.v)]
        return self

    def jitter(self, rng, amount):
        self.v = [add(p, (rng.uniform(-amount, amount), rng.uniform(-amount, amount),
                          rng.uniform(-amount, amount))) for p in self.v]
        return self

    def recolor(self, mapping):
        self.f = [(i, mapping.get(m, mapping.get("*", m))) for i, m in self.f]
        return self

    def copy(self):
        p = Part()
        p.v = list(self.v)
        p.f = [(list(i), m) for i, m in self.f]
        return p

    def signed_volume(self):
        vol = 0.0
        for idx, _ in self.f:
            a = self.v[idx[0]]
            for k in range(1, len(idx) - 1):
                vol += dot(a, cross(self.v[idx[k]], self.v[idx[k + 1]])) / 6.0
        return vol


def face_normal(pts):
    """Newell normal (not normalised)."""
    n = [0.0, 0.0, 0.0]
    for k in range(len(pts)):
        a, b = pts[k], pts[(k + 1) % len(pts)]
        n[0] += (a[1] - b[1]) * (a[2] + b[2])
        n[1] += (a[2] - b[2]) * (a[0] + b[0])
        n[2] += (a[0] - b[0]) * (a[1] + b[1])
    return tuple(n)


# ---------------------------------------------------------------- primitives
def box(c, s, mat, mats=None):
    """Axis-aligned box centred at c with sizes s. mats: optional per-face materials
    in order (-x, +x, -y, +y, -z, +z)."""
    p = Part()
    hx, hy, hz = s[0] / 2, s[1] / 2, s[2] / 2
    for z in (-hz, hz):
        for y in (-hy, hy):
            for x in (-hx, hx):
                p.vert((c[0] + x, c[1] + y, c[2] + z))
    # vertex index = xi + 2*yi + 4*zi
    quads = [(0, 4, 6, 2), (1, 3, 7, 5), (0, 1, 5, 4), (2, 6, 7, 3), (0, 2, 3, 1), (4, 5, 7, 6)]
    for k, q in enumerate(quads):
        p.face(q, mats[k] if mats else mat)
    return p


def frustum(n, r0, r1, z0, z1, mat, cap0=None, cap1=None, phase=0.0, c=(0, 0)):
    """Vertical n-sided frustum (r1 == 0: cone). Caps use the side material unless given."""
    p = Part()
    ang = [2 * math.pi * (k + phase) / n for k in range(n)]
    b = [p.vert((c[0] + r0 * math.cos(a), c[1] + r0 * math.sin(a), z0)) for a in ang]
    if r1 > 0:
        t = [p.vert((c[0] + r1 * math.cos(a), c[1] + r1 * math.sin(a), z1)) for a in ang]
        for k in range(n):
            p.face((b[k], b[(k + 1) % n], t[(k + 1) % n], t[k]), mat)
        p.face(t, cap1 or mat)
    else:
        apex = p.vert((c[0], c[1], z1))
        for k in range(n):
            p.face((b[k], b[(k + 1) % n], apex), mat)
    p.face(list(reversed(b)), cap0 or mat)
    return p


def cylinder_along(a, b, n, r0, r1, mat, cap_mat=None, phase=0.5):
    """Frustum from point a (radius r0) to point b (radius r1)."""
    a, b = tuple(a), tuple(b)
    L = norm(sub(b, a))
    p = frustum(n, r0, r1, 0.0, L, mat, cap_mat, cap_mat, phase)
    w = unit(sub(b, a))
    helper = (0, 0, 1) if abs(w[2]) < 0.9 else (1, 0, 0)
    u = unit(cross(helper, w))
    v = cross(w, u)
    m = ((u[0], v[0], w[0]), (u[1], v[1], w[1]), (u[2], v[2], w[2]))
    p.rotate(m)
    p.move(a)
    return p


def beam(a, b, w, h, mat):
    """Box of section w x h from a to b (square-ish strut)."""
    a, b = tuple(a), tuple(b)
    L = norm(sub(b, a))
    p = box((0, 0, L / 2), (w, h, L), mat)
    d = unit(sub(b, a))
    helper = (0, 0, 1) if abs(d[2]) < 0.9 else (1, 0, 0)
    u = unit(cross(helper, d))
    v = cross(d, u)
    m = ((u[0], v[0], d[0]), (u[1], v[1], d[1]), (u[2], v[2], d[2]))
    return p.rotate(m).move(a)


def extrude_yz(profile, x0, x1, mat, side_mats=None):
    """Side profile [(y, z), ...] (a convex polygon) extruded across x from x0 to x1.
    side_mats[k]: material of the band between profile points k and k+1."""
    p = Part()
    n = len(profile)
    l = [p.vert((x0, y, z)) for y, z in profile]
    r = [p.vert((x1, y, z)) for y, z in profile]
    for k in range(n):
        p.face((l[k], l[(k + 1) % n], r[(k + 1) % n], r[k]), side_mats[k] if side_mats else mat)
    p.face(l, mat)
    p.face(list(reversed(r)), mat)
    return p


def extrude_xy(outline, z0, z1, mat, top_scale=1.0, top_mat=None, c=(0, 0)):
    """Top-view outline [(x, y), ...] extruded up from z0 to z1; the top may be scaled about c."""
    p = Part()
    n = len(outline)
    b = [p.vert((x, y, z0)) for x, y in outline]
    t = [p.vert((c[0] + (x - c[0]) * top_scale, c[1] + (y - c[1]) * top_scale, z1)) for x, y in outline]
    for k in range(n):
        p.face((b[k], b[(k + 1) % n], t[(k + 1) % n], t[k]), mat)
    p.face(b, mat)
    p.face(t, top_mat or mat)
    return p


def extrude_xz(profile, y0, y1, mat):
    """Front profile [(x, z), ...] extruded along y (for fins, tails)."""
    p = Part()
    n = len(profile)
    a = [p.vert((x, y0, z)) for x, z in profile]
    b = [p.vert((x, y1, z)) for x, z in profile]
    for k in range(n):
        p.face((a[k], a[(k + 1) % n], b[(k + 1) % n], b[k]), mat)
    p.face(a, mat)
    p.face(list(reversed(b)), mat)
    return p


def loft_y(sections, mat, band_mats=None, cap_mats=(None, None)):
    """Sections along y: [(y, [(x, z), ...]), ...], each with the same vertex count. A section of a
    single point closes that end as an apex. band_mats[k]: material between ring points k, k+1."""
    p = Part()
    rings = []
    for y, pts in sections:
        rings.append([p.vert((x, y, z)) for x, z in pts])
    for s in range(len(rings) - 1):
        A, B = rings[s], rings[s + 1]
        if len(B) == 1:
            for k in range(len(A)):
                p.face((A[k], A[(k + 1) % len(A)], B[0]), band_mats[k] if band_mats else mat)
        elif len(A) == 1:
            for k in range(len(B)):
                p.face((A[0], B[(k + 1) % len(B)], B[k]), band_mats[k] if band_mats else mat)
        else:
            n = len(A)
            for k in range(n):
                p.face((A[k], A[(k + 1) % n], B[(k + 1) % n], B[k]), band_mats[k] if band_mats else mat)
    if len(rings[0]) > 2:
        p.face(rings[0], cap_mats[0] or mat)
    if len(rings[-1]) > 2:
        p.face(list(reversed(rings[-1])), cap_mats[1] or mat)
    return p


def ellipsoid(c, r, nlon, nlat, mat, mat_top=None):
    """UV ellipsoid with radii r = (rx, ry, rz)."""
    p = Part()
    south = p.vert((c[0], c[1], c[2] - r[2]))
    rings = []
    for j in range(1, nlat):
        th = -math.pi / 2 + math.pi * j / nlat
        ring = []
        for i in range(nlon):
            ph = 2 * math.pi * i / nlon
            ring.append(p.vert((c[0] + r[0] * math.cos(th) * math.cos(ph),
                                c[1] + r[1] * math.cos(th) * math.sin(ph),
                                c[2] + r[2] * math.sin(th))))
        rings.append(ring)
    north = p.vert((c[0], c[1], c[2] + r[2]))
    for i in range(nlon):
        p.face((south, rings[0][(i + 1) % nlon], rings[0][i]), mat)
    for j in range(len(rings) - 1):
        m = mat_top if (mat_top and j >= len(rings) // 2) else mat
        for i in range(nlon):
            a, b = rings[j], rings[j + 1]
            p.face((a[i], a[(i + 1) % nlon], b[(i + 1) % nlon], b[i]), m)
    for i in range(nlon):
        p.face((rings[-1][i], rings[-1][(i + 1) % nlon], north), mat_top or mat)
    return p


def jagged_stump(n, r0, r1, h, top_h, mat, top_mat, rng, c=(0, 0)):
    """Frustum with a broken (jagged) top: a triangle fan to a raised centre with uneven rim."""
    p = Part()
    ang = [2 * math.pi * k / n for k in range(n)]
    b = [p.vert((c[0] + r0 * math.cos(a), c[1] + r0 * math.sin(a), 0.0)) for a in ang]
    t = [p.vert((c[0] + r1 * math.cos(a), c[1] + r1 * math.sin(a), h + rng.uniform(-0.35, 0.35) * top_h))
         for a in ang]
    apex = p.vert((c[0] + 0.2 * r1, c[1], h + top_h))
    for k in range(n):
        p.face((b[k], b[(k + 1) % n], t[(k + 1) % n], t[k]), mat)
        p.face((t[k], t[(k + 1) % n], apex), top_mat)
    p.face(list(reversed(b)), mat)
    return p


# ---------------------------------------------------------------- model writer + checks
class Model:
    def __init__(self, name):
        self.name = name
        self.parts = []

    def add(self, *parts):
        for p in parts:
            self.parts.append(p)
        return self

    def transform_all(self, fn):
        for p in self.parts:
            fn(p)
        return self


def finalize(model):
    """Orient every part outward, split non-planar faces, reject degenerate ones.
    Returns (vertices, faces[(indices, mat)])."""
    verts, faces = [], []
    for p in model.parts:
        vol = p.signed_volume()
        if abs(vol) < 1e-9:
            raise SystemExit(f"{model.name}: a part has no volume")
        flip = vol < 0
        base = len(verts)
        verts.extend(p.v)
        for idx, mat in p.f:
            idx = list(reversed(idx)) if flip else list(idx)
            pts = [p.v[i] for i in idx]
            n = face_normal(pts)
            area2 = norm(n)
            if area2 < 1e-8:
                raise SystemExit(f"{model.name}: degenerate face {idx}")
            nu = mul(n, 1 / area2)
            planar = all(abs(dot(sub(q, pts[0]), nu)) < 1e-4 for q in pts)
            convex = True
            for k in range(len(pts)):
                e = cross(sub(pts[(k + 1) % len(pts)], pts[k]), sub(pts[(k + 2) % len(pts)], pts[(k + 1) % len(pts)]))
                if dot(e, nu) < -1e-9:
                    convex = False
            if len(idx) == 3 or (planar and convex):
                faces.append(([base + i for i in idx], mat))
            else:  # fan split into triangles
                for k in range(1, len(idx) - 1):
                    tri = [idx[0], idx[k], idx[k + 1]]
                    tn = face_normal([p.v[i] for i in tri])
                    if norm(tn) < 1e-8:
                        continue
                    faces.append(([base + i for i in tri], mat))
    return verts, faces


def write_model(out_dir, model, report):
    verts, faces = finalize(model)
    if not (20 <= len(faces) <= 300):
        raise SystemExit(f"{model.name}: {len(faces)} faces (want 20..300)")
    lo = [min(v[k] for v in verts) for k in range(3)]
    hi = [max(v[k] for v in verts) for k in range(3)]
    path = os.path.join(out_dir, model.name + ".obj")
    with open(path, "w") as f:
        f.write(f"# {model.name}: generated by tools/make_models.py. Metres, z up, +y forward,\n")
        f.write("# origin at the centre of the ground contact. Faces wind counter-clockwise from outside.\n")
        f.write(f"# {len(verts)} vertices, {len(faces)} faces; extent x {hi[0]-lo[0]:.2f} y {hi[1]-lo[1]:.2f} z {hi[2]-lo[2]:.2f} m\n")
        f.write("mtllib materials.mtl\n")
        f.write(f"o {model.name}\n")
        for v in verts:
            f.write(f"v {v[0]:.4f} {v[1]:.4f} {v[2]:.4f}\n")
        cur = None
        for idx, mat in faces:
            if mat not in MATERIALS:
                raise SystemExit(f"{model.name}: unknown material {mat}")
            if mat != cur:
                f.write(f"usemtl {mat}\n")
                cur = mat
            f.write("f " + " ".join(str(i + 1) for i in idx) + "\n")
    report.append((model.name, len(faces), [hi[k] - lo[k] for k in range(3)], lo[2], hi[2]))


def write_mtl(out_dir):
    with open(os.path.join(out_dir, "materials.mtl"), "w") as f:
        f.write("# Materials of the NPSNET models (diffuse colour Kd). Generated by tools/make_models.py.\n")
        for name, (r, g, b) in MATERIALS.items():
            f.write(f"newmtl {name}\nKa 0 0 0\nKd {r:.3f} {g:.3f} {b:.3f}\nKs 0 0 0\nd 1\nillum 1\n\n")


CHAR = {"*": "charred"}


def char_mix(rng, parts, frac=0.7):
    """Blacken most faces of the given parts (charred / dark char / ash / rust)."""
    for p in parts:
        new = []
        for idx, m in p.f:
            r = rng.random()
            if r < frac:
                m = "charred"
            elif r < frac + 0.15:
                m = "charred2"
            elif r < frac + 0.22:
                m = "rust"
            new.append((idx, m))
        p.f = new


# ---------------------------------------------------------------- the models
def tree(rng):
    return Model("tree").add(
        frustum(8, 0.28, 0.18, 0.0, 3.0, "bark"),
        frustum(12, 2.5, 0.0, 2.0, 6.2, "leaves"),
        frustum(10, 1.8, 0.0, 4.2, 8.0, "leaves_dark", phase=0.5),
    )


def tree_damaged(rng):
    trunk = frustum(8, 0.28, 0.18, 0.0, 3.0, "bark")
    crown = frustum(12, 2.2, 0.0, 2.0, 5.4, "leaves", phase=0.25).jitter(rng, 0.25)
    crown.recolor({"leaves": "leaves"})
    for i, (idx, m) in enumerate(crown.f):
        if i % 3 == 0:
            crown.f[i] = (idx, "leaves_dry")
    crown.rotate(rot_y(18), (0, 0, 2.5))
    broken_top = frustum(8, 1.3, 0.0, 0.0, 3.2, "leaves_dry").rotate(rot_x(-80)).move((1.5, 1.2, 0.9)).jitter(rng, 0.1)
    return Model("tree_damaged").add(trunk, crown, broken_top)


def tree_stump(rng):
    stump = jagged_stump(8, 0.34, 0.27, 0.55, 0.25, "bark", "wood_cut", rng)
    log = cylinder_along((0.6, 0.3, 0.22), (5.8, 2.4, 0.2), 6, 0.2, 0.14, "bark", "wood_cut")
    chip = box((-0.6, -0.5, 0.05), (0.5, 0.3, 0.1), "wood_cut").rotate(rot_z(30), (-0.6, -0.5, 0))
    return Model("tree_stump").add(stump, log, chip)


def bush(rng):
    return Model("bush").add(
        ellipsoid((0, 0, 0.7), (1.0, 1.0, 0.75), 8, 5, "bush", "leaves"),
        ellipsoid((0.55, -0.35, 0.5), (0.6, 0.6, 0.55), 6, 4, "bush"),
    )


def bush_flattened(rng):
    a = ellipsoid((0, 0.3, 0.15), (1.5, 1.1, 0.17), 8, 4, "bush_dry", "bush").jitter(rng, 0.05)
    b = ellipsoid((0.7, -0.6, 0.1), (0.7, 0.5, 0.11), 6, 3, "bush_dry").jitter(rng, 0.03)
    return Model("bush_flattened").add(a, b)


def pole_top(z, parts):
    parts.append(box((0, 0, z), (2.4, 0.14, 0.14), "pole"))
    for x in (-1.0, -0.35, 1.0):
        parts.append(frustum(6, 0.07, 0.05, z + 0.07, z + 0.32, "insulator", c=(x, 0)))


def telephone_pole(rng):
    parts = [frustum(8, 0.16, 0.12, 0.0, 9.0, "pole")]
    pole_top(8.4, parts)
    return Model("telephone_pole").add(*parts)


def telephone_pole_snapped(rng):
    stump = jagged_stump(8, 0.16, 0.155, 1.1, 0.3, "pole", "wood_cut", rng)
    fallen = [frustum(8, 0.155, 0.12, 1.3, 9.0, "pole")]
    pole_top(8.4, fallen)
    m = Model("telephone_pole_snapped").add(stump)
    # fallen section: rotated down to the ground, lying along +x, its cross-arm tipped
    for p in fallen:
        p.move((0, 0, -1.3)).rotate(rot_y(86)).move((0.45, 0.0, 0.16)).rotate(rot_z(25))
        m.add(p)
    return m


def building_parts(rng, level):
    """level 0 intact, 1 damaged_low, 2 damaged_med, 3 destroyed."""
    W, D, H, R = 12.0, 10.0, 4.4, 6.0
    parts = []
    if level <= 1:
        parts.append(box((0, 0, H / 2), (W, D, H), "wall"))
        # gabled roof, ridge along x
        prof = [(-D / 2 - 0.4, H), (D / 2 + 0.4, H), (0, R)]
        if level == 0:
            roof = extrude_yz(prof, -W / 2 - 0.2, W / 2 + 0.2, "wall")
            roof.f = [(i, "roof") if k < 3 else (i, "wall") for k, (i, m) in enumerate(roof.f)]
            parts.append(roof)
        else:
            # the roof's east half has caved in: it sags into the house, burnt
            left = extrude_yz(prof, -W / 2 - 0.2, -0.3, "wall")
            left.f = [(i, "roof") if k < 3 else (i, "wall") for k, (i, m) in enumerate(left.f)]
            right = extrude_yz(prof, 0.3, W / 2 + 0.2, "roof")
            right.rotate(rot_y(16), (0.3, 0, H)).move((0, 0, -0.4))
            char_mix(rng, [right], frac=0.55)
            parts += [left, right]
        win = "window" if level == 0 else "slit"
        for x in (-3.8, -0.5, 3.8):  # front (+y) and back windows
            parts.append(box((x, D / 2 + 0.04, 2.6), (1.4, 0.12, 1.2), win))
            parts.append(box((x, -D / 2 - 0.04, 2.6), (1.4, 0.12, 1.2), "window"))
        for y in (-2.5, 2.5):
            parts.append(box((W / 2 + 0.04, y, 2.6), (0.12, 1.4, 1.2), "window"))
            parts.append(box((-W / 2 - 0.04, y, 2.6), (0.12, 1.4, 1.2), "window"))
        parts.append(box((2.0, D / 2 + 0.05, 1.1), (1.2, 0.12, 2.2), "door"))
        if level == 1:
            for k in range(3):
                parts.append(box((-4 + 1.6 * k, D / 2 + 1.0 + 0.3 * k, 0.3), (1.0, 0.8, 0.6), "rubble")
                             .rotate(rot_z(20 * k), (-4 + 1.6 * k, D / 2 + 1, 0)).jitter(rng, 0.1))
            scorch = box((-3.8, D / 2 + 0.1, 3.3), (2.2, 0.1, 1.2), "charred")
            parts.append(scorch)
    elif level == 2:
        # walls as slabs; the front-right corner has fallen in, roof collapsed onto the floor
        t = 0.35
        parts.append(box((0, -D / 2 + t / 2, H / 2), (W, t, H), "wall"))                  # back
        parts.append(box((-W / 2 + t / 2, 0, H / 2), (t, D - 2 * t, H), "wall"))          # left
        parts.append(box((W / 2 - t / 2, -1.5, 1.6), (t, D - 3 - 2 * t, 3.2), "wall_dirty"))  # right, lower
        front = extrude_yz([(D / 2 - t, 0), (D / 2, 0), (D / 2, H), (D / 2 - t, H)], -W / 2, -1.0, "wall")
        parts.append(front)
        parts.append(box((1.5, D / 2 - t / 2, 0.8), (4.0, t, 1.6), "wall_dirty"))
        for x in (-3.8,):
            parts.append(box((x, D / 2 + 0.04, 2.6), (1.4, 0.12, 1.2), "slit"))
        roof = box((-1.0, 0.0, 1.4), (W * 0.8, D * 0.55, 0.3), "roof").rotate(rot_x(14), (0, 0, 1.4)).rotate(rot_y(-12), (0, 0, 1.4))
        roof2 = box((-2.0, -1.0, 2.4), (W * 0.5, D * 0.4, 0.3), "roof").rotate(rot_x(-22), (-2, -1, 2.4))
        parts += [roof, roof2]
        for k in range(4):
            c = (3.5 + rng.uniform(-1, 1), 3.0 + rng.uniform(-1.5, 1.5), 0.4)
            parts.append(box(c, (1.4, 1.1, 0.8), "rubble").rotate(rot_z(rng.uniform(0, 90)), c).jitter(rng, 0.15))
        char_mix(rng, [roof, roof2], frac=0.35)
    else:
        # rubble heap with wall stumps, charred
        t = 0.35
        parts.append(box((0, -D / 2 + t / 2, 0.8), (W, t, 1.6), "wall_dirty").jitter(rng, 0.1))
        parts.append(box((-W / 2 + t / 2, -1.5, 1.2), (t, D - 3, 2.4), "wall_dirty").jitter(rng, 0.1))
        parts.append(box((W / 2 - t / 2, 2.0, 0.5), (t, 3.0, 1.0), "wall_dirty").jitter(rng, 0.08))
        heap = ellipsoid((0, 0, 0.0), (5.0, 4.0, 1.9), 8, 4, "rubble", "ash").jitter(rng, 0.3)
        parts.append(heap)
        for k in range(6):
            c = (rng.uniform(-5, 5), rng.uniform(-4, 4), 0.35)
            parts.append(box(c, (rng.uniform(0.8, 2.0), rng.uniform(0.6, 1.4), 0.6), "rubble")
                         .rotate(rot_z(rng.uniform(0, 90)), c).rotate(rot_x(rng.uniform(-15, 15)), c).jitter(rng, 0.1))
        beamp = beam((-3, -2, 0.2), (2.5, 1.5, 1.8), 0.25, 0.25, "charred")
        parts.append(beamp)
        char_mix(rng, [heap] + parts[3:5], frac=0.5)
    return parts


def watertower_parts(rng, level):
    parts = []
    Zt = 22.0
    base, top = 4.2, 2.6
    corners = [(1, 1), (-1, 1), (-1, -1), (1, -1)]
    legs = []
    for sx, sy in corners:
        a = (sx * base, sy * base, 0.0)
        b = (sx * top, sy * top, Zt)
        legs.append((a, b))
    if level == 0:
        for a, b in legs:
            parts.append(beam(a, b, 0.45, 0.45, "steel"))
        for z in (7.0, 14.5):
            f = z / Zt
            r = base + (top - base) * f
            parts.append(beam((-r, -r, z), (r, -r, z), 0.18, 0.18, "steel"))
            parts.append(beam((r, r, z), (-r, r, z), 0.18, 0.18, "steel"))
            parts.append(beam((r, -r, z), (r, r, z), 0.18, 0.18, "steel"))
            parts.append(beam((-r, r, z), (-r, -r, z), 0.18, 0.18, "steel"))
        parts.append(frustum(14, 5.0, 5.0, Zt, Zt + 6.0, "tank_white", cap0="steel"))
        parts.append(frustum(14, 5.3, 0.0, Zt + 6.0, Zt + 8.2, "tank_roof"))
        parts.append(frustum(14, 2.5, 5.0, Zt - 1.6, Zt, "tank_white", phase=0.0))
    elif level == 1:
        # one leg buckled at mid height: tank tilted and dented, rust streaks
        for i, (a, b) in enumerate(legs):
            if i == 0:
                mid = (a[0] * 0.55 + 1.5, a[1] * 0.55 + 1.2, 10.0)
                parts.append(beam(a, mid, 0.45, 0.45, "rust"))
                parts.append(beam(mid, (b[0], b[1], b[2] - 1.4), 0.45, 0.45, "steel"))
            else:
                parts.append(beam(a, b, 0.45, 0.45, "steel"))
        for z in (7.0,):
            r = base + (top - base) * z / Zt
            parts.append(beam((-r, -r, z), (r, -r, z), 0.18, 0.18, "steel"))
            parts.append(beam((-r, r, z), (-r, -r, z), 0.18, 0.18, "steel"))
        tank = [frustum(14, 5.0, 5.0, Zt, Zt + 6.0, "tank_white", cap0="steel"),
                frustum(14, 5.3, 0.0, Zt + 6.0, Zt + 8.2, "tank_roof"),
                frustum(14, 2.5, 5.0, Zt - 1.6, Zt, "tank_white")]
        for p in tank:
            p.jitter(rng, 0.25)
            p.rotate(rot_x(-7), (0, 0, Zt)).rotate(rot_y(6), (0, 0, Zt)).move((0, 0, -0.8))
            p.f = [(i, "rust" if rng.random() < 0.3 else m) for i, m in p.f]
        parts += tank
    else:
        # crushed: legs collapsed on the ground, tank burst and flattened beside them
        for i, (a, b) in enumerate(legs):
            ang = 35 + 20 * i
            d = (math.cos(math.radians(ang)) * 18, math.sin(math.radians(ang)) * 18, 0.3)
            parts.append(beam((a[0], a[1], 0.25), (a[0] + d[0] * 0.6, a[1] + d[1] * 0.6, 0.5), 0.45, 0.45, "steel").jitter(rng, 0.1))
        parts.append(frustum(6, 0.4, 0.35, 0.0, 3.5, "rust", c=(base, base)).jitter(rng, 0.08))
        parts.append(frustum(6, 0.4, 0.35, 0.0, 2.0, "rust", c=(-base, -base)).jitter(rng, 0.08))
        tank = frustum(14, 5.0, 5.0, -3.0, 3.0, "tank_white", cap0="rust", cap1="tank_roof")
        tank.rotate(rot_y(90)).scale((1.05, 1.1, 0.5)).jitter(rng, 0.35).move((6.0, 7.0, 2.4))
        tank.f = [(i, "rust" if rng.random() < 0.35 else m) for i, m in tank.f]
        roof = frustum(10, 5.3, 0.0, 0.0, 1.6, "tank_roof").jitter(rng, 0.2).rotate(rot_x(70)).move((-6.0, 8.0, 2.8))
        parts += [tank, roof]
    return parts


def bunker(rng, destroyed):
    if not destroyed:
        parts = [frustum(8, 4.2, 3.5, 0.0, 2.3, "concrete", phase=0.5),
                 frustum(8, 3.7, 3.2, 2.3, 2.7, "concrete", phase=0.5)]
        for ang in (90, 30, 150):
            a = math.radians(ang)
            c = (3.55 * math.cos(a), 3.55 * math.sin(a), 1.6)
            parts.append(box(c, (1.6, 0.3, 0.28), "slit").rotate(rot_z(ang - 90), c))
        parts.append(box((0, -3.3, 0.9), (1.1, 1.3, 1.8), "concrete", mats=["concrete", "concrete", "concrete", "concrete", "concrete", "concrete"]))
        parts.append(box((0, -3.98, 0.85), (0.9, 0.08, 1.6), "slit"))
        return Model("bunker").add(*parts)
    parts = [frustum(8, 4.2, 3.6, 0.0, 1.4, "concrete", phase=0.5).jitter(rng, 0.12)]
    for k in range(5):
        a = 2 * math.pi * k / 5 + 0.3
        c = (2.8 * math.cos(a), 2.8 * math.sin(a), 1.6)
        slab = box(c, (2.8, 2.2, 0.4), "concrete").rotate(rot_z(math.degrees(a)), c)
        slab.rotate(rot_x(rng.uniform(-30, 30)), c).rotate(rot_y(rng.uniform(-25, 25)), c).jitter(rng, 0.1)
        parts.append(slab)
    crater = frustum(8, 2.5, 1.8, 1.35, 1.45, "charred")
    parts.append(crater)
    char_mix(rng, parts[1:4], frac=0.3)
    return Model("bunker_destroyed").add(*parts)


def rock(rng):
    r = ellipsoid((0, 0, 0.55), (2.4, 1.9, 1.5), 8, 5, "rock", "rock_dark").jitter(rng, 0.25)
    r2 = ellipsoid((1.6, 1.0, 0.3), (1.0, 0.9, 0.7), 6, 4, "rock_dark").jitter(rng, 0.12)
    return Model("rock").add(r, r2)


# ---- vehicles
def m1a1_parts():
    body, dark = "m1_sand", "m1_dark"
    parts = []
    track_prof = [(-3.95, 0.55), (-3.6, 0.05), (3.4, 0.05), (3.95, 0.6), (3.85, 1.05), (-3.95, 1.05)]
    for sx in (-1, 1):
        x0, x1 = (1.20, 1.85) if sx > 0 else (-1.85, -1.20)
        parts.append(extrude_yz(track_prof, x0, x1, "track"))
        parts.append(box((sx * 1.53, 0.0, 1.10), (0.66, 7.9, 0.12), dark))  # fender / skirt top
        parts.append(box((sx * 1.86, 0.0, 0.78), (0.06, 7.4, 0.56), body))   # side skirt
    hull = [(-3.9, 0.45), (3.2, 0.45), (3.95, 1.0), (3.3, 1.5), (-3.9, 1.5)]
    parts.append(extrude_yz(hull, -1.20, 1.20, body, side_mats=[dark, body, body, body, body]))
    turret = [(-1.6, -2.3), (1.6, -2.3), (1.75, 0.5), (0.85, 1.9), (-0.85, 1.9), (-1.75, 0.5)]
    tur = extrude_xy(turret, 1.5, 2.3, body, top_scale=0.93, c=(0, -0.2))
    parts.append(tur)
    parts.append(frustum(8, 0.38, 0.34, 2.3, 2.42, dark, c=(0.7, -0.9)))       # commander's cupola
    parts.append(box((0, -2.55, 1.95), (2.6, 0.5, 0.6), dark))               # bustle rack
    parts.append(cylinder_along((0, 1.8, 1.95), (0, 5.9, 1.95), 8, 0.14, 0.12, "gun"))
    parts.append(cylinder_along((0, 1.6, 1.95), (0, 2.4, 1.95), 8, 0.3, 0.22, dark))  # mantlet
    return parts


def m1a1(rng):
    return Model("m1a1").add(*m1a1_parts())


def wreck(name, parts, rng, sink=0.2, jit=0.07, frac=0.72):
    for p in parts:
        p.jitter(rng, jit)
        p.move((0, 0, -sink))
    char_mix(rng, parts, frac)
    return Model(name).add(*parts)


def m1a1_wreck(rng):
    parts = m1a1_parts()
    hull = parts[:7]
    turret = parts[7:]
    for p in hull:
        p.rotate(rot_x(-3)).rotate(rot_y(4))
    for p in turret:
        p.rotate(rot_z(35), (0, -0.2, 1.5)).rotate(rot_y(-14), (0, 0, 1.5)).move((0.6, -0.4, -0.25))
    turret[-2].rotate(rot_x(-12), (0, 1.8, 1.9))  # gun drooping
    return wreck("m1a1_wreck", parts, rng, sink=0.15)


def wheel(c, r, w, mat="tyre"):
    return cylinder_along((c[0] - w / 2, c[1], c[2]), (c[0] + w / 2, c[1], c[2]), 10, r, r, mat, "gun")


def hmmwv_parts():
    parts = []
    body = "hmmwv"
    lower = [(-2.3, 0.55), (2.15, 0.55), (2.3, 0.75), (2.25, 1.05), (1.0, 1.15), (-2.3, 1.15)]
    parts.append(extrude_yz(lower, -1.1, 1.1, body))
    cab = [(-0.95, 1.15), (0.75, 1.15), (0.45, 1.8), (-0.95, 1.8)]
    parts.append(extrude_yz(cab, -0.98, 0.98, body, side_mats=[body, "glass", body, "glass"]))
    parts.append(box((0, 0.62, 1.5), (1.9, 0.1, 0.5), "glass").rotate(rot_x(-25), (0, 0.62, 1.5)))
    for x in (-0.99, 0.99):
        parts.append(box((x, -0.1, 1.5), (0.05, 1.1, 0.4), "glass"))
    parts.append(box((0, 2.05, 0.85), (1.6, 0.25, 0.35), "tyre"))  # grille
    for sx in (-1, 1):
        for y in (-1.5, 1.5):
            parts.append(wheel((sx * 0.93, y, 0.45), 0.45, 0.34))
    return parts


def hmmwv(rng):
    return Model("hmmwv").add(*hmmwv_parts())


def hmmwv_wreck(rng):
    parts = hmmwv_parts()
    parts[1].scale((1, 1, 0.6), (0, 0, 1.15))            # cabin crushed
    parts[2].move((0, -0.2, -0.25))
    for p in parts[3:5]:
        p.scale((1, 1, 0.5), (0, 0, 1.15))
    del parts[-1]                                           # a wheel blown off
    for p in parts[:5]:
        p.rotate(rot_y(7), (0, 0, 0.4)).rotate(rot_x(-4))
    parts.append(wheel((2.1, -2.6, 0.2), 0.45, 0.34).rotate(rot_y(80), (2.1, -2.6, 0.2)).move((0, 0, 0.1)))
    return wreck("hmmwv_wreck", parts, rng, sink=0.1, jit=0.05)


def bmp_parts():
    body, dark = "bmp", "bmp_dark"
    parts = []
    track = [(-3.3, 0.5), (-3.0, 0.05), (2.6, 0.05), (3.2, 0.55), (3.1, 0.95), (-3.3, 0.95)]
    for sx in (-1, 1):
        x0, x1 = (1.1, 1.6) if sx > 0 else (-1.6, -1.1)
        parts.append(extrude_yz(track, x0, x1, "track"))
    hull = [(-3.35, 0.45), (2.4, 0.45), (3.35, 0.95), (1.0, 1.95), (-3.35, 1.95)]
    parts.append(extrude_yz(hull, -1.6, 1.6, body, side_mats=[dark, body, body, body, dark]))
    parts.append(box((0, -3.36, 1.25), (1.8, 0.06, 1.0), dark))  # rear doors
    parts.append(frustum(8, 0.95, 0.72, 1.95, 2.45, body, c=(0.1, 0.1)))
    parts.append(cylinder_along((0.1, 0.8, 2.2), (0.1, 3.3, 2.25), 8, 0.1, 0.08, "gun"))
    parts.append(cylinder_along((0.1, 0.2, 2.55), (0.1, 1.3, 2.55), 6, 0.1, 0.1, dark))  # missile rail
    return parts


def bmp(rng):
    return Model("bmp").add(*bmp_parts())


def bmp_wreck(rng):
    parts = bmp_parts()
    for p in parts[4:]:
        p.rotate(rot_z(-50), (0.1, 0.1, 2)).rotate(rot_x(20), (0.1, 0.1, 2)).move((-1.0, -0.5, -0.2))
    for p in parts[:4]:
        p.rotate(rot_y(-5))
    return wreck("bmp_wreck", parts, rng, sink=0.2)


def ship_parts():
    def sec(hw, deck, keel):
        return [(hw, deck), (-hw, deck), (-hw * 0.95, 0.6), (-hw * 0.45, keel), (hw * 0.45, keel), (hw * 0.95, 0.6)]
    hull = loft_y([(-15.0, sec(2.7, 2.4, -1.1)), (-8.0, sec(3.0, 2.4, -1.4)), (2.0, sec(3.0, 2.6, -1.4)),
                   (9.0, sec(2.3, 2.9, -1.2)), (13.0, sec(1.1, 3.2, -0.6)), (15.0, sec(0.12, 3.4, 0.4))],
                  "hull_grey", band_mats=["deck", "hull_grey", "antifoul", "antifoul", "antifoul", "hull_grey"],
                  cap_mats=("hull_grey", "hull_grey"))
    parts = [hull]
    parts.append(extrude_xy([(-2.2, -6.0), (2.2, -6.0), (2.2, 1.5), (1.4, 3.0), (-1.4, 3.0), (-2.2, 1.5)], 2.4, 4.6, "hull_grey", top_scale=0.95, c=(0, -1.5)))
    parts.append(extrude_xy([(-1.5, -3.0), (1.5, -3.0), (1.5, 1.0), (0.9, 2.0), (-0.9, 2.0), (-1.5, 1.0)], 4.6, 6.0, "glass", top_scale=0.92, top_mat="hull_grey", c=(0, -1)))
    parts.append(cylinder_along((0, -1.0, 6.0), (0, -1.0, 6.6), 6, 0.15, 0.1, "steel"))
    parts.append(box((0, -1.0, 6.4), (2.4, 0.18, 0.18), "steel"))
    parts.append(frustum(8, 0.9, 0.7, 2.7, 3.4, "hull_grey", c=(0, 7.5)))
    parts.append(cylinder_along((0, 8.0, 3.1), (0, 10.8, 3.2), 6, 0.09, 0.07, "gun"))
    return parts


def patrol_ship(rng):
    return Model("patrol_ship").add(*ship_parts())


def patrol_ship_wreck(rng):
    parts = ship_parts()
    del parts[3:5]  # mast gone
    parts[1].scale((1, 1, 0.75), (0, 0, 2.4))
    parts[2].scale((1, 0.8, 0.5), (0, 0, 4.6)).move((0.3, 0, -1.1))
    for p in parts:
        p.rotate(rot_y(14)).rotate(rot_x(-4)).move((0, 0, -1.6))
    parts.append(beam((1.5, -3.0, 2.0), (2.8, -10.0, 1.6), 0.2, 0.2, "steel"))  # fallen mast
    m = wreck("patrol_ship_wreck", parts, rng, sink=0.0, jit=0.06, frac=0.45)
    return m


def f16_parts():
    body, dark = "jet_grey", "jet_dark"
    zc = 2.0

    def ring(r, hz, dz=0.0):
        return [(r, zc + dz), (r * 0.7, zc + dz + hz * 0.75), (0, zc + dz + hz), (-r * 0.7, zc + dz + hz * 0.75),
                (-r, zc + dz), (-r * 0.7, zc + dz - hz * 0.8), (0, zc + dz - hz), (r * 0.7, zc + dz - hz * 0.8)]
    fus = loft_y([(-7.2, ring(0.45, 0.45)), (-5.5, ring(0.65, 0.62)), (1.0, ring(0.72, 0.7)), (4.0, ring(0.55, 0.55, -0.05)),
                  (6.3, ring(0.25, 0.25, -0.1)), (7.8, [(0, zc - 0.1)])], body, cap_mats=("gun", None))
    parts = [fus]
    parts.append(extrude_xy([(-5.0, -3.4), (-5.0, -2.5), (-0.6, 2.8), (0.6, 2.8), (5.0, -2.5), (5.0, -3.4)], zc - 0.12, zc + 0.02, body))
    parts.append(extrude_xy([(-2.8, -7.3), (-2.8, -6.7), (-0.4, -4.8), (0.4, -4.8), (2.8, -6.7), (2.8, -7.3)], zc - 0.05, zc + 0.05, dark))
    parts.append(extrude_yz([(-7.4, zc + 0.4), (-5.0, zc + 0.4), (-6.6, zc + 3.0), (-7.5, zc + 3.0)], -0.07, 0.07, dark))
    parts.append(ellipsoid((0, 3.3, zc + 0.62), (0.42, 1.5, 0.42), 8, 4, "glass"))
    parts.append(box((0, 1.8, zc - 0.8), (1.0, 2.6, 0.5), dark))  # intake
    for x, y in ((0, 4.5), (-1.2, -0.8), (1.2, -0.8)):
        parts.append(beam((x, y, 0.0), (x, y, zc - 0.5), 0.14, 0.14, "steel"))
    return parts


def f16(rng):
    return Model("f16").add(*f16_parts())


def f16_wreck(rng):
    parts = f16_parts()
    del parts[-3:]  # gear gone
    for p in parts:
        p.move((0, 0, -1.6))
    # fuselage broken behind the canopy: rotate the rear half, left wing tilted into the ground
    parts[0].rotate(rot_z(8)).rotate(rot_x(3))
    parts[1].rotate(rot_y(-9), (0, 0, 0.4)).rotate(rot_z(8))
    parts[2].rotate(rot_z(30), (0, -6, 0.4)).move((1.5, -1.0, 0))
    parts[3].rotate(rot_y(70), (0, -6, 0.6)).move((2.5, -0.5, -0.1))
    parts.append(box((-3.0, -9.0, 0.3), (1.2, 2.0, 0.6), "charred").rotate(rot_z(20), (-3, -9, 0)))
    return wreck("f16_wreck", parts, rng, sink=0.0, jit=0.06, frac=0.8)


def ah64_parts():
    body, dark = "heli", "heli"
    parts = []

    def sec(hw, zb, zt):
        return [(hw, zb + 0.25), (hw, zt - 0.2), (hw * 0.6, zt), (-hw * 0.6, zt), (-hw, zt - 0.2), (-hw, zb + 0.25),
                (-hw * 0.5, zb), (hw * 0.5, zb)]
    fus = loft_y([(-2.8, sec(0.9, 0.9, 3.1)), (0.5, sec(1.0, 0.8, 3.2)), (3.5, sec(0.75, 0.8, 2.9)),
                  (5.6, sec(0.45, 1.0, 2.1)), (6.6, sec(0.25, 1.2, 1.7))], body)
    parts.append(fus)
    boom = loft_y([(-2.8, sec(0.45, 1.6, 2.6)), (-9.2, sec(0.22, 2.0, 2.5))], body)
    parts.append(boom)
    parts.append(extrude_yz([(-9.5, 2.0), (-8.5, 2.1), (-9.0, 4.3), (-9.6, 4.3)], -0.08, 0.08, body))  # tail fin
    parts.append(box((0, -8.9, 2.35), (3.4, 0.8, 0.08), body))  # stabilator
    parts.append(box((0.18, -9.2, 3.8), (0.05, 0.25, 2.8), "rotor"))  # tail rotor blade
    parts.append(box((0.18, -9.2, 3.8), (0.05, 2.8, 0.25), "rotor"))
    parts.append(extrude_xy([(-0.6, 1.2), (0.6, 1.2), (0.55, 5.2), (0, 5.8), (-0.55, 5.2)], 2.9, 3.7, "glass", top_scale=0.8, c=(0, 3.2)))
    parts.append(frustum(8, 0.55, 0.4, 3.2, 3.9, body, c=(0, 0.3)))  # mast
    for ang in (45, 135, 225, 315):
        parts.append(box((3.65, 0, 4.0), (7.3, 0.55, 0.07), "rotor").rotate(rot_z(ang)).move((0, 0.3, 0)))
    parts.append(box((0, 0.4, 1.9), (4.8, 1.0, 0.12), body))  # stub wings
    for sx in (-1, 1):
        parts.append(box((sx * 2.0, 0.3, 1.55), (0.5, 1.5, 0.5), "missile_dark"))
        parts.append(beam((sx * 1.2, 1.8, 0.0), (sx * 0.9, 1.8, 1.1), 0.14, 0.14, "steel"))
        parts.append(wheel((sx * 1.2, 1.8, 0.3), 0.3, 0.2))
    parts.append(cylinder_along((0, 5.9, 1.1), (0, 7.2, 1.1), 6, 0.07, 0.06, "gun"))
    parts.append(ellipsoid((0, 6.7, 1.55), (0.35, 0.4, 0.35), 6, 3, "gun"))
    return parts


def ah64(rng):
    return Model("ah64").add(*ah64_parts())


def ah64_wreck(rng):
    parts = ah64_parts()
    # crashed: on its belly, tilted; tail boom broken off at an angle; blades bent down
    blades = parts[8:12]
    boom = parts[1:6]
    del parts[-4:-2]  # gear collapsed (keep only one wheel pair parts removed)
    for p in parts:
        p.move((0, 0, -0.75))
    for p in boom:
        p.rotate(rot_z(-25), (0, -2.8, 1.2)).rotate(rot_y(15), (0, -2.8, 1.2))
    for k, p in enumerate(blades):
        p.rotate(rot_x(-14 if k % 2 else 12), (0, 0.3, 3.2))
    return wreck("ah64_wreck", parts, rng, sink=0.0, jit=0.0, frac=0.55)


def he_round(rng):
    r = 0.077
    body = loft_y([(-0.3, circle(r * 0.92, 8, r)), (-0.27, circle(r, 8, r)), (0.05, circle(r, 8, r)),
                   (0.15, circle(r * 0.8, 8, r)), (0.25, circle(r * 0.45, 8, r)), (0.3, [(0, r)])], "shell",
                  band_mats=None)
    # colour: the ogive (last bands) brass, the body olive
    body.f = [(i, "brass" if k >= 24 and k < 40 else m) for k, (i, m) in enumerate(body.f)]
    band = cylinder_along((0, -0.22, r), (0, -0.18, r), 8, r * 1.04, r * 1.04, "brass")
    return Model("he_round").add(body, band)


def circle(r, n, zc, phase=0.5):
    return [(r * math.cos(2 * math.pi * (k + phase) / n), zc + r * math.sin(2 * math.pi * (k + phase) / n)) for k in range(n)]


def missile(rng):
    r = 0.09
    body = loft_y([(-0.8, circle(r, 8, r)), (0.55, circle(r, 8, r)), (0.72, circle(r * 0.6, 8, r)),
                   (0.8, [(0, r)])], "missile", cap_mats=("slit", None))
    body.f = [(i, "missile_dark" if k >= 8 and k < 16 else m) for k, (i, m) in enumerate(body.f)]
    parts = [body]
    for ang in (0, 90, 180, 270):
        fin = extrude_yz([(-0.8, 0.0), (-0.45, 0.0), (-0.55, 0.16), (-0.8, 0.16)], -0.01, 0.01, "missile_dark")
        fin.move((0, 0, r)).rotate(rot_y(ang))
        fin.move((0, 0, r))
        can = extrude_yz([(0.3, 0.0), (0.45, 0.0), (0.42, 0.08), (0.33, 0.08)], -0.008, 0.008, "missile_dark")
        can.move((0, 0, r)).rotate(rot_y(ang)).move((0, 0, r))
        parts += [fin, can]
    for p in parts:
        p.move((0, 0, 0.16))  # lowest fin tip on the ground plane
    return Model("missile").add(*parts)


def generic_ground(rng):
    c = "generic_ground"
    parts = [extrude_yz([(-2.3, 0.6), (2.3, 0.6), (2.3, 1.4), (-2.3, 1.4)], -1.1, 1.1, c),
             extrude_yz([(0.9, 1.4), (2.2, 1.4), (1.9, 2.2), (0.9, 2.2)], -1.05, 1.05, c, side_mats=[c, "glass", c, c]),
             box((0, -0.6, 1.8), (2.1, 2.8, 0.8), "marker")]
    for sx in (-1, 1):
        for y in (-1.6, 0.0, 1.6):
            parts.append(wheel((sx * 0.95, y, 0.45), 0.45, 0.3))
    return Model("generic_ground").add(*parts)


def generic_air(rng):
    c = "generic_air"
    zc = 1.8
    fus = loft_y([(-6.0, circle(0.4, 8, zc)), (-4.0, circle(0.7, 8, zc)), (3.5, circle(0.7, 8, zc)),
                  (5.5, circle(0.4, 8, zc)), (6.2, [(0, zc)])], c)
    parts = [fus,
             extrude_xy([(-6.0, -0.8), (6.0, -0.8), (6.0, 0.6), (-6.0, 0.6)], zc - 0.05, zc + 0.08, "marker"),
             extrude_xy([(-2.2, -6.0), (2.2, -6.0), (2.2, -5.2), (-2.2, -5.2)], zc, zc + 0.08, c),
             extrude_yz([(-6.0, zc + 0.3), (-4.8, zc + 0.3), (-5.6, zc + 2.2), (-6.1, zc + 2.2)], -0.06, 0.06, c),
             ellipsoid((0, 2.6, zc + 0.6), (0.35, 0.9, 0.3), 6, 3, "glass")]
    for x, y in ((0, 3.5), (-1.0, -0.5), (1.0, -0.5)):
        parts.append(beam((x, y, 0.0), (x, y, zc - 0.6), 0.12, 0.12, "steel"))
    return Model("generic_air").add(*parts)


def generic_sea(rng):
    def sec(hw, deck, keel):
        return [(hw, deck), (-hw, deck), (-hw * 0.9, 0.3), (0, keel), (hw * 0.9, 0.3)]
    hull = loft_y([(-6.0, sec(1.8, 1.4, -0.8)), (2.0, sec(2.0, 1.5, -1.0)), (5.0, sec(1.2, 1.7, -0.6)),
                   (6.2, sec(0.1, 1.9, 0.6))], "generic_sea",
                  band_mats=["deck", "generic_sea", "antifoul", "antifoul", "generic_sea"])
    cabin = extrude_xy([(-1.2, -3.0), (1.2, -3.0), (1.2, 0.5), (0.8, 1.5), (-0.8, 1.5), (-1.2, 0.5)], 1.4, 3.0, "generic_sea", top_scale=0.9, top_mat="marker", c=(0, -1))
    win = box((0, 1.05, 2.5), (1.4, 0.4, 0.4), "glass")
    return Model("generic_sea").add(hull, cabin, win)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "models")
    os.makedirs(out, exist_ok=True)
    rng = random.Random(1991)
    builders = [
        tree, tree_damaged, tree_stump, bush, bush_flattened, telephone_pole, telephone_pole_snapped,
        lambda r: Model("building").add(*building_parts(r, 0)),
        lambda r: Model("building_damaged_low").add(*building_parts(r, 1)),
        lambda r: Model("building_damaged_med").add(*building_parts(r, 2)),
        lambda r: Model("building_destroyed").add(*building_parts(r, 3)),
        lambda r: Model("watertower").add(*watertower_parts(r, 0)),
        lambda r: Model("watertower_damaged").add(*watertower_parts(r, 1)),
        lambda r: Model("watertower_crushed").add(*watertower_parts(r, 2)),
        lambda r: bunker(r, False), lambda r: bunker(r, True), rock,
        m1a1, m1a1_wreck, hmmwv, hmmwv_wreck, bmp, bmp_wreck, patrol_ship, patrol_ship_wreck,
        f16, f16_wreck, ah64, ah64_wreck, he_round, missile, generic_ground, generic_air, generic_sea,
    ]
    report = []
    for b in builders:
        m = b(rng)
        write_model(out, m, report)
    write_mtl(out)
    for name, nf, ext, zlo, zhi in report:
        print(f"{name:26s} {nf:4d} faces  {ext[0]:6.2f} x {ext[1]:6.2f} x {ext[2]:6.2f} m  z {zlo:6.2f}..{zhi:6.2f}")


if __name__ == "__main__":
    main()
