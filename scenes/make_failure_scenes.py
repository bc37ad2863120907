#!/usr/bin/env python3
"""Writes the scenes where one light-transport method fails on purpose (issue: materials and
light transport). Each stays a small, self-contained glTF; run `python3 make_failure_scenes.py`.

- tiny_light.gltf: a 10 cm, very bright square light 2 m over a white floor. BSDF sampling almost
  never hits it; next-event estimation finds it every time.
- veach_mis.gltf: Veach's MIS scene: four metal plates from nearly mirror to rough, lit by four
  sphere lights from tiny to large, of equal power. Light sampling fails on the sharp plates
  with large lights, BSDF sampling on the rough plates with small lights; MIS does well on all.
- sphere_near_floor.gltf: a sphere light 2 cm above a floor. Sampling the sphere's area wastes
  the samples on its far side and weights the near ones badly; sampling its cone of directions
  does not.
- glass_caustic.gltf: a glass ball on a floor under a small sphere light. The caustic is found
  only by paths that bounce through the glass: shadow rays cannot pass a Dirac interface.
- mirror_caustic.gltf: the glass caustic seen only in a mirror (camera, mirror, floor, glass,
  glass, light: E S D S S L). The floor vertex cannot be joined to anything: shadow rays cannot
  pass the glass, the light's vertices there lie on the same floor, and the camera sees that
  floor only through the mirror. Only merging (--integrator vcm) samples it well; the path
  tracer must hit the small light through the ball by chance.
- many_lamps.gltf: 1,024 small lamps (6 cm octahedra shaded on top, lit below, 0.3-0.7 m above
  a floor, emission over 400:1) among a few blocks. Choosing a light by power sends most shadow rays to bright lamps
  metres away; the light tree picks the lamps near and facing each point.
- narrow_gap.gltf: a closed dark room (albedo 0.2) lit only through a 12 cm opening low in one
  wall by a small lamp outside, whose beam lights a spot on the ceiling; the camera looks at the
  floor below it. Shadow rays from almost every point in the room hit the wall; the light
  arrives by way of the spot, which BSDF sampling finds rarely: path guiding learns where it
  is (issue 30's failure scene for unguided MIS). Dark, so that most light comes straight
  from the spot rather than after several bounces, which only the camera's vertex would guide.
"""

import math
import os
import struct

from make_cornell_box import GltfWriter, quad, sub


def normalized(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v)


def material(g, name, color, metallic=0.0, roughness=1.0, lambert=False, emission=None,
             transmission=0.0, ior=None):
    index = g.material(name, color, emission or (0.0, 0.0, 0.0))
    mat = g.doc["materials"][index]
    mat["pbrMetallicRoughness"]["metallicFactor"] = metallic
    mat["pbrMetallicRoughness"]["roughnessFactor"] = roughness
    if not lambert:
        del mat["extensions"]["KHR_materials_specular"]
    if transmission > 0:
        mat["extensions"]["KHR_materials_transmission"] = {"transmissionFactor": transmission}
        mat["extensions"]["KHR_materials_ior"] = {"ior": ior or 1.5}
        for ext in ("KHR_materials_transmission", "KHR_materials_ior"):
            if ext not in g.doc["extensionsUsed"]:
                g.doc["extensionsUsed"].append(ext)
    if not mat["extensions"]:
        del mat["extensions"]
    return index


def floor(size, y=0.0):
    s = size / 2
    return [quad((-s, y, -s), (-s, y, s), (s, y, s), (s, y, -s), (0, 1, 0))]


def sphere_light(g, name, center, radius, intensity, color=(1.0, 1.0, 1.0)):
    ext = g.doc.setdefault("extensions", {}).setdefault("KHR_lights_punctual", {"lights": []})
    if "KHR_lights_punctual" not in g.doc["extensionsUsed"]:
        g.doc["extensionsUsed"].append("KHR_lights_punctual")
    ext["lights"].append({"name": name, "type": "point", "color": list(color),
                          "intensity": intensity, "extras": {"radius": radius}})
    g.node(name=name, translation=list(center),
           extensions={"KHR_lights_punctual": {"light": len(ext["lights"]) - 1}})


def look_at_rotation(eye, target):
    """Quaternion (x, y, z, w) turning the glTF camera (looking down -Z, +Y up) towards target."""
    f = [t - e for t, e in zip(target, eye)]
    n = math.sqrt(sum(c * c for c in f))
    f = [c / n for c in f]
    # Right = f x up, true up = right x f; the camera's -Z is f.
    r = [f[1] * 0 - f[2] * 1, f[2] * 0 - f[0] * 0, f[0] * 1 - f[1] * 0]
    rn = math.sqrt(sum(c * c for c in r))
    r = [c / rn for c in r]
    u = [r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]]
    z = [-c for c in f]
    m = [[r[0], u[0], z[0]], [r[1], u[1], z[1]], [r[2], u[2], z[2]]]  # columns r, u, z
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0:
        s = 0.5 / math.sqrt(trace + 1.0)
        q = [(m[2][1] - m[1][2]) * s, (m[0][2] - m[2][0]) * s, (m[1][0] - m[0][1]) * s, 0.25 / s]
    else:
        i = max(range(3), key=lambda k: m[k][k])
        j, k = (i + 1) % 3, (i + 2) % 3
        s = 2.0 * math.sqrt(1.0 + m[i][i] - m[j][j] - m[k][k])
        q = [0.0, 0.0, 0.0, (m[k][j] - m[j][k]) / s]
        q[i] = 0.25 * s
        q[j] = (m[j][i] + m[i][j]) / s
        q[k] = (m[k][i] + m[i][k]) / s
    return [round(c, 12) for c in q]


def camera(g, eye, target, yfov, aspect=1.0):
    g.doc["cameras"].append({"type": "perspective", "name": "camera", "perspective": {
        "yfov": yfov, "aspectRatio": aspect, "znear": 0.01, "zfar": 100.0}})
    g.node(name="camera", camera=len(g.doc["cameras"]) - 1, translation=list(eye),
           rotation=look_at_rotation(eye, target))


def uv_sphere(center, radius, rings=24, segments=48):
    """Triangles of a UV sphere, counter-clockwise seen from outside, none degenerate."""
    cx, cy, cz = center
    def point(i, j):
        theta = math.pi * i / rings
        phi = 2 * math.pi * j / segments
        return (cx + radius * math.sin(theta) * math.cos(phi), cy + radius * math.cos(theta),
                cz + radius * math.sin(theta) * math.sin(phi))
    tris = []
    for i in range(rings):
        for j in range(segments):
            a, b = point(i, j), point(i + 1, j)
            c, d = point(i + 1, j + 1), point(i, j + 1)
            # Outward winding: counter-clockwise seen from outside.
            if i > 0:
                tris.append((a, d, b))
            if i < rings - 1:
                tris.append((b, d, c))
    return tris


def triangle_primitive(g, tris, material_index):
    """GltfWriter.primitive takes quads: pass each triangle as a quad whose fourth point
    repeats the third, then index only the triangles."""
    prim = g.primitive([[t[0], t[1], t[2], t[2]] for t in tris], material_index)
    # Replace the index accessor with a plain triangle list over the same points.
    indices = [4 * i + k for i in range(len(tris)) for k in (0, 1, 2)]
    view = g._view(struct.pack("<%dI" % len(indices), *indices), 34963)
    prim["indices"] = g._accessor(bufferView=view, componentType=5125, count=len(indices),
                                  type="SCALAR")
    return prim


def tiny_light():
    g = GltfWriter()
    white = material(g, "white", (0.8, 0.8, 0.8), lambert=True)
    light = material(g, "tiny light", (0.0, 0.0, 0.0), lambert=True,
                     emission=(1200.0, 1200.0, 1200.0))
    g.node(name="floor", mesh=g.mesh("floor", [g.primitive(floor(8.0), white)]))
    s, y = 0.05, 2.0
    g.node(name="light", mesh=g.mesh("light", [g.primitive(
        [quad((-s, y, -s), (s, y, -s), (s, y, s), (-s, y, s), (0, -1, 0))], light)]))
    camera(g, (0.0, 3.0, 5.0), (0.0, 0.0, 0.0), 0.8)
    return g


def veach_mis():
    g = GltfWriter()
    backdrop = material(g, "backdrop", (0.1, 0.1, 0.1), lambert=True)
    g.node(name="floor", mesh=g.mesh("floor", [g.primitive(floor(40.0, -3.0), backdrop)]))
    # Plates: strips tilted so that each mirrors the row of lights towards the camera.
    eye, lights_center = (0.0, 2.0, 9.0), (0.0, 2.5, -4.0)
    for k, roughness in enumerate((0.05, 0.12, 0.25, 0.45)):
        plate = material(g, "plate %d" % k, (0.9, 0.9, 0.9), metallic=1.0, roughness=roughness)
        center = (0.0, -1.0 + 0.45 * k, 0.8 - 1.2 * k)
        to_eye = normalized(sub(eye, center))
        to_light = normalized(sub(lights_center, center))
        n = normalized(tuple(a + b for a, b in zip(to_eye, to_light)))
        along = normalized((0.0, n[2], -n[1]))  # in the yz plane, perpendicular to n
        h = tuple(0.5 * c for c in along)
        q = quad((-4, center[1] - h[1], center[2] - h[2]), (4, center[1] - h[1], center[2] - h[2]),
                 (4, center[1] + h[1], center[2] + h[2]), (-4, center[1] + h[1], center[2] + h[2]),
                 n)
        g.node(name="plate %d" % k, mesh=g.mesh("plate %d" % k, [g.primitive([q], plate)]))
    for k, radius in enumerate((0.03, 0.1, 0.3, 0.9)):
        sphere_light(g, "light %d" % k, (-3.75 + 2.5 * k, 2.5, -4.0), radius, 3.0)
    camera(g, (0.0, 2.0, 9.0), (0.0, -0.8, -0.5), 0.7, aspect=1.5)
    return g


def sphere_near_floor():
    g = GltfWriter()
    white = material(g, "white", (0.8, 0.8, 0.8), lambert=True)
    g.node(name="floor", mesh=g.mesh("floor", [g.primitive(floor(6.0), white)]))
    sphere_light(g, "sphere", (0.0, 0.52, 0.0), 0.5, 10.0)
    camera(g, (0.0, 1.6, 3.2), (0.0, 0.1, 0.0), 0.8)
    return g


def glass_caustic():
    g = GltfWriter()
    white = material(g, "white", (0.8, 0.8, 0.8), lambert=True)
    glass = material(g, "glass", (1.0, 1.0, 1.0), roughness=0.0, transmission=1.0, ior=1.5)
    g.node(name="floor", mesh=g.mesh("floor", [g.primitive(floor(6.0), white)]))
    g.node(name="ball", mesh=g.mesh("ball", [triangle_primitive(
        g, uv_sphere((0.0, 0.6, 0.0), 0.5), glass)]))
    sphere_light(g, "light", (0.6, 3.0, -0.4), 0.15, 30.0)
    camera(g, (0.0, 2.2, 3.0), (0.0, 0.3, 0.0), 0.75)
    return g


def mirror_caustic():
    g = GltfWriter()
    white = material(g, "white", (0.8, 0.8, 0.8), lambert=True)
    glass = material(g, "glass", (1.0, 1.0, 1.0), roughness=0.0, transmission=1.0, ior=1.5)
    mirror = material(g, "mirror", (0.95, 0.95, 0.95), metallic=1.0, roughness=0.0)
    g.node(name="floor", mesh=g.mesh("floor", [g.primitive(floor(6.0), white)]))
    g.node(name="ball", mesh=g.mesh("ball", [triangle_primitive(
        g, uv_sphere((0.0, 0.6, 0.0), 0.5), glass)]))
    g.node(name="mirror", mesh=g.mesh("mirror", [g.primitive(
        [rect((-1.5, 0.0, -1.6), (1.5, 0.0, -1.6), (1.5, 2.2, -1.6), (-1.5, 2.2, -1.6),
              (0, 0, 1))], mirror)]))
    sphere_light(g, "light", (0.6, 3.0, -0.4), 0.15, 30.0)
    # Between the ball and the mirror, facing the mirror: the ball and its caustic (near
    # (-0.15, 0, 0.1)) are behind the camera, in view only by way of the mirror.
    camera(g, (0.3, 1.2, -0.7), (0.12, 0.8, -1.6), 0.8)
    return g


def octahedron(center, radius):
    """Eight triangles, counter-clockwise seen from outside: the upper four, then the lower."""
    cx, cy, cz = center
    px, nx = (cx + radius, cy, cz), (cx - radius, cy, cz)
    py, ny = (cx, cy + radius, cz), (cx, cy - radius, cz)
    pz, nz = (cx, cy, cz + radius), (cx, cy, cz - radius)
    return [(px, py, pz), (pz, py, nx), (nx, py, nz), (nz, py, px),
            (pz, ny, px), (nx, ny, pz), (nz, ny, nx), (px, ny, nz)]


def box(lo, hi):
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    return [quad((x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0), (0, 1, 0)),
            quad((x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1), (0, 0, 1)),
            quad((x1, y0, z0), (x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (0, 0, -1)),
            quad((x1, y0, z1), (x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (1, 0, 0)),
            quad((x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0), (-1, 0, 0))]


def many_lamps():
    g = GltfWriter()
    white = material(g, "white", (0.8, 0.8, 0.8), lambert=True)
    grey = material(g, "grey", (0.5, 0.5, 0.5), lambert=True)
    g.node(name="floor", mesh=g.mesh("floor", [g.primitive(floor(8.0), white)]))
    blocks = [((-1.6, 0.0, -0.9), (-0.8, 0.9, -0.1)), ((0.5, 0.0, 0.6), (1.3, 0.5, 1.4)),
              ((1.2, 0.0, -2.0), (2.0, 1.2, -1.2))]
    g.node(name="blocks", mesh=g.mesh("blocks", [g.primitive(
        [q for lo, hi in blocks for q in box(lo, hi)], grey)]))
    # Eight emission levels spread geometrically over 400:1, assigned by a fixed LCG.
    levels = [0.05 * 400.0 ** (k / 7.0) for k in range(8)]
    lamps, shades = [[] for _ in levels], []
    state = 12345
    def rand():
        nonlocal state
        state = (1103515245 * state + 12345) % 2 ** 31
        return state / 2 ** 31
    for i in range(32):
        for j in range(32):
            x, z = -3.1 + 0.2 * i, -3.1 + 0.2 * j
            height, level = 0.3 + 0.4 * rand(), int(rand() * len(levels))
            if any(lo[0] - 0.1 < x < hi[0] + 0.1 and lo[2] - 0.1 < z < hi[2] + 0.1
                   for lo, hi in blocks):
                height += 1.0  # over the block
            faces = octahedron((x, height, z), 0.03)
            shades += faces[:4]
            lamps[level].append(faces[4:])
    g.node(name="shades", mesh=g.mesh("shades", [triangle_primitive(g, shades, grey)]))
    for k, level in enumerate(levels):
        lamp = material(g, "lamp %d" % k, (0.0, 0.0, 0.0), lambert=True,
                        emission=(level, level * 0.9, level * 0.75))
        g.node(name="lamps %d" % k, mesh=g.mesh("lamps %d" % k, [triangle_primitive(
            g, [t for octa in lamps[k] for t in octa], lamp)]))
    camera(g, (0.0, 3.5, 5.0), (0.0, 0.0, -0.3), 0.8)
    return g


def rect(p0, p1, p2, p3, facing):
    """A quad facing `facing`, whichever way round its corners were given."""
    from make_cornell_box import cross, dot
    if dot(cross(sub(p1, p0), sub(p2, p0)), facing) < 0:
        p0, p1, p2, p3 = p3, p2, p1, p0
    return quad(p0, p1, p2, p3, facing)


def narrow_gap():
    g = GltfWriter()
    grey = material(g, "dark grey", (0.2, 0.2, 0.2), lambert=True)
    lamp = material(g, "lamp", (0.0, 0.0, 0.0), lambert=True,
                    emission=(8.0e6, 7.6e6, 6.8e6))
    # The room: x, z in [-2, 2], y in [0, 2.5]; the wall at x = 2 has a 12 cm square opening
    # around (2, wy, 0).
    x0, x1, h, wy, a = -2.0, 2.0, 2.5, 0.6, 0.06
    inward_x = (-1, 0, 0)
    quads = [
        rect((x0, 0, -2), (x1, 0, -2), (x1, 0, 2), (x0, 0, 2), (0, 1, 0)),      # floor
        rect((x0, h, -2), (x1, h, -2), (x1, h, 2), (x0, h, 2), (0, -1, 0)),     # ceiling
        rect((x0, 0, -2), (x0, h, -2), (x0, h, 2), (x0, 0, 2), (1, 0, 0)),      # far wall
        rect((x0, 0, -2), (x1, 0, -2), (x1, h, -2), (x0, h, -2), (0, 0, 1)),    # back
        rect((x0, 0, 2), (x1, 0, 2), (x1, h, 2), (x0, h, 2), (0, 0, -1)),       # front
        # The wall with the opening: below, above, and either side of it.
        rect((x1, 0, -2), (x1, 0, 2), (x1, wy - a, 2), (x1, wy - a, -2), inward_x),
        rect((x1, wy + a, -2), (x1, wy + a, 2), (x1, h, 2), (x1, h, -2), inward_x),
        rect((x1, wy - a, -2), (x1, wy - a, -a), (x1, wy + a, -a), (x1, wy + a, -2), inward_x),
        rect((x1, wy - a, a), (x1, wy - a, 2), (x1, wy + a, 2), (x1, wy + a, a), inward_x),
    ]
    g.node(name="room", mesh=g.mesh("room", [g.primitive(quads, grey)]))
    # The lamp outside, low: 20 cm square, 4 m from the opening, facing it; its beam rises
    # through the opening and lights a spot about 0.4 m across on the ceiling near
    # (0.5, 2.5, 0), which floor and walls see at a good angle.
    centre, s = (4.5, -2.5, 0.0), 0.1
    facing = normalized(sub((x1, wy, 0.0), centre))
    u = (0.0, 0.0, 1.0)
    v = normalized((facing[1] * u[2] - facing[2] * u[1], facing[2] * u[0] - facing[0] * u[2],
                    facing[0] * u[1] - facing[1] * u[0]))
    corner = lambda i, j: tuple(c + s * (i * uu + j * vv) for c, uu, vv in zip(centre, u, v))
    g.node(name="lamp", mesh=g.mesh("lamp", [g.primitive(
        [rect(corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1), facing)], lamp)]))
    # From the far corner down onto the floor below the spot, the opening in view.
    camera(g, (-1.8, 1.5, 1.5), (0.8, 0.0, -0.3), 0.6)
    return g


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    for name, build in (("tiny_light", tiny_light), ("veach_mis", veach_mis),
                        ("sphere_near_floor", sphere_near_floor),
                        ("glass_caustic", glass_caustic), ("mirror_caustic", mirror_caustic),
                        ("many_lamps", many_lamps),
                        ("narrow_gap", narrow_gap)):
        doc = build()
        doc.doc["asset"]["generator"] = "scenes/make_failure_scenes.py"
        doc.write(os.path.join(here, name + ".gltf"))
