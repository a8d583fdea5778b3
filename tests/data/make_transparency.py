#!/usr/bin/env python3
"""Writes tests/data/transparency.babylon (or, with --fog,
tests/data/fog.babylon): a scene in the layout Babylon.js's
exporters write (positions, normals, uvs, indices; materials with alpha,
hasAlpha textures, transparencyMode, backFaceCulling false), made here so
that nothing third-party is committed. A lit ground, a fence cut out of an
embedded PNG's alpha (alpha test), and two overlapping glass boxes (alpha
blending) drawn from back to front.

    python3 tests/data/make_transparency.py > tests/data/transparency.babylon
    python3 tests/data/make_transparency.py --fog > tests/data/fog.babylon
    python3 tests/data/make_transparency.py --floor > tests/data/floor.babylon
    python3 tests/data/make_transparency.py --shiny > tests/data/shiny.babylon

The fog scene: a long checkered floor (in strips, as fog is worked out
per vertex) receding into linear fog, shiny
boxes along it (specular highlights), a light that lights only the
floor (includedOnlyMeshesIds) and a hemispheric one the floor excludes.

The shiny scene: three red spheres under a white point light, their
specularPower 8, 32 and 128 (Blinn-Phong highlights, per vertex).
"""
import math
import base64, json, struct, sys, zlib


def png_rgba(w, h, px):
    raw = b"".join(b"\0" + bytes(px[y * w * 4:(y + 1) * w * 4]) for y in range(h))
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def fence_texture():
    """16x16 planks with gaps: alpha 0 between the boards and in a knot hole"""
    px = []
    for y in range(16):
        for x in range(16):
            board = (x % 8) < 6 and not (4 <= y < 6)
            knot = (x - 3) ** 2 + (y - 11) ** 2 < 3
            shade = 150 + 8 * ((x * 7 + y * 3) % 5)
            px += [shade, int(shade * 0.7), int(shade * 0.4), 255 if board and not knot else 0]
    return "data:image/png;base64," + base64.b64encode(png_rgba(16, 16, px)).decode()


def quad(p0, p1, p2, p3, n, uv_scale=(1, 1)):
    su, sv = uv_scale
    return ([c for p in (p0, p1, p2, p3) for c in p], n * 4,
            [0, 0, su, 0, su, sv, 0, sv], [0, 2, 1, 0, 3, 2])


def merge(parts):
    pos, nrm, uvs, idx = [], [], [], []
    for p, n, u, i in parts:
        base = len(pos) // 3
        pos += p
        nrm += n
        uvs += u
        idx += [base + k for k in i]
    return pos, nrm, uvs, idx


def box(s):
    h = s / 2
    faces = []
    for axis in range(3):
        for sign in (-1, 1):
            n = [0, 0, 0]
            n[axis] = sign
            u = [0, 0, 0]
            v = [0, 0, 0]
            u[(axis + 1) % 3] = h
            v[(axis + 2) % 3] = h
            c = [sign * h * (k == axis) for k in range(3)]
            corner = lambda a, b: [round(c[k] + a * u[k] + b * v[k], 4) for k in range(3)]
            q = quad(corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1), n)
            if sign < 0:   # keep every face's outside its front
                q = (q[0], q[1], q[2], [0, 1, 2, 0, 2, 3])
            faces.append(q)
    return merge(faces)


def mesh(mid, material, position, geometry):
    pos, nrm, uvs, idx = geometry
    return {"name": mid, "id": mid, "materialId": material, "position": position,
            "rotation": [0, 0, 0], "scaling": [1, 1, 1], "isVisible": True, "isEnabled": True,
            "checkCollisions": False, "billboardMode": 0, "receiveShadows": False,
            "positions": pos, "normals": nrm, "uvs": uvs, "indices": idx}


def material(mid, diffuse, **extra):
    m = {"name": mid, "id": mid, "ambient": [0, 0, 0], "diffuse": diffuse,
         "specular": [0.2, 0.2, 0.2], "specularPower": 64, "emissive": [0, 0, 0],
         "alpha": 1, "backFaceCulling": True, "wireframe": False}
    m.update(extra)
    return m


scene = {
    "autoClear": True, "clearColor": [0.55, 0.7, 0.85], "ambientColor": [0, 0, 0],
    "gravity": [0, -9.81, 0],
    "cameras": [{"name": "camera", "id": "camera", "type": "FreeCamera",
                 "position": [2.5, 3.2, -7.5], "target": [0, 0.7, 0], "fov": 0.8,
                 "minZ": 0.1, "maxZ": 100}],
    "activeCameraID": "camera",
    "lights": [{"name": "sky", "id": "sky", "type": 3, "direction": [0, 1, 0],
                "diffuse": [0.75, 0.75, 0.75], "groundColor": [0.2, 0.2, 0.25], "intensity": 1},
               {"name": "sun", "id": "sun", "type": 1, "direction": [-0.4, -1, 0.6],
                "diffuse": [0.6, 0.6, 0.5], "intensity": 1}],
    "materials": [
        material("ground", [0.35, 0.55, 0.3]),
        material("fence", [1, 1, 1], backFaceCulling=False,
                 diffuseTexture={"name": "fence.png", "base64String": fence_texture(),
                                 "hasAlpha": True, "uScale": 3, "vScale": 1, "level": 1,
                                 "coordinatesMode": 0, "wrapU": 1, "wrapV": 1}),
        material("red glass", [0.9, 0.15, 0.1], alpha=0.5, backFaceCulling=False),
        material("blue glass", [0.1, 0.3, 0.95], alpha=0.4, backFaceCulling=False),
    ],
    "meshes": [
        mesh("ground", "ground", [0, 0, 0],
             merge([quad([-6, 0, 6], [6, 0, 6], [6, 0, -6], [-6, 0, -6], [0, 1, 0])])),
        mesh("fence", "fence", [0, 0, 2.5],
             merge([quad([-4.5, 2, 0], [4.5, 2, 0], [4.5, 0, 0], [-4.5, 0, 0], [0, 0, -1], (3, 1))])),
        # the nearer box first: drawn back to front, the blend reorders them
        mesh("blue box", "blue glass", [0.6, 0.7, -1.2], box(1.4)),
        mesh("red box", "red glass", [-0.7, 0.9, 0], box(1.8)),
    ],
}


def checker_texture():
    px = []
    for y in range(32):
        for x in range(32):
            c = 230 if ((x // 4) ^ (y // 4)) & 1 else 40
            px += [c, c, c, 255]
    return "data:image/png;base64," + base64.b64encode(png_rgba(32, 32, px)).decode()


fog_scene = {
    "autoClear": True, "clearColor": [0.7, 0.72, 0.75], "ambientColor": [0, 0, 0],
    "fogMode": 3, "fogColor": [0.7, 0.72, 0.75], "fogStart": 6, "fogEnd": 40, "fogDensity": 0.05,
    "cameras": [{"name": "camera", "id": "camera", "type": "FreeCamera",
                 "position": [0, 2.2, -6], "target": [0, 0.8, 10], "fov": 0.9,
                 "minZ": 0.1, "maxZ": 200}],
    "activeCameraID": "camera",
    "lights": [{"name": "sky", "id": "sky", "type": 3, "direction": [0, 1, 0],
                "diffuse": [0.6, 0.6, 0.65], "groundColor": [0.25, 0.2, 0.2], "intensity": 1,
                "excludedMeshesIds": ["floor"]},
               {"name": "sun", "id": "sun", "type": 1, "direction": [0.3, -1, 0.5],
                "diffuse": [0.9, 0.85, 0.7], "specular": [1, 1, 1], "intensity": 1},
               {"name": "floor lamp", "id": "floor lamp", "type": 3, "direction": [0, 1, 0],
                "diffuse": [0.35, 0.35, 0.35], "groundColor": [0, 0, 0], "intensity": 1,
                "includedOnlyMeshesIds": ["floor"]}],
    "materials": [
        material("floor", [1, 1, 1], specular=[0, 0, 0],
                 diffuseTexture={"name": "checker.png", "base64String": checker_texture(),
                                 "hasAlpha": False}),
        material("shiny red", [0.8, 0.15, 0.1], specular=[1, 1, 1], specularPower=24),
        material("shiny blue", [0.1, 0.25, 0.8], specular=[1, 1, 1], specularPower=48),
    ],
    # the floor in strips: fog is worked out per vertex
    "meshes": [mesh("floor", "floor", [0, 0, 0],
                    merge([quad([-6, 0, z + 6], [6, 0, z + 6], [6, 0, z], [-6, 0, z], [0, 1, 0], (12, 6))
                           for z in range(-6, 120, 6)]))]
    + [mesh("box %d" % k, "shiny red" if k % 2 == 0 else "shiny blue",
            [(-2.5 if k % 2 == 0 else 2.5), 0.8, 2 + 6 * k], box(1.6)) for k in range(6)],
}

# --floor: the fog scene's floor and boxes without fog, seen lower, for
# the mipmap pictures (a receding checkerboard), the boxes glowing with an
# emissive map (emissiveTexture, level 0.6) as exporters write one
floor_scene = dict(fog_scene, fogMode=0, clearColor=[0.55, 0.65, 0.8])
floor_scene["cameras"] = [dict(fog_scene["cameras"][0], position=[0, 1.2, -6], target=[0, 0.9, 10])]
floor_scene["materials"] = [dict(m) for m in fog_scene["materials"]]
for m in floor_scene["materials"][1:]:
    m["emissiveTexture"] = {"name": "checker.png", "base64String": checker_texture(), "level": 0.6,
                            "uScale": 2, "vScale": 2, "hasAlpha": False, "coordinatesIndex": 0}



def sphere(r, rings=18, segments=30):
    pos, nrm, uvs, idx = [], [], [], []
    for i in range(rings + 1):
        th = math.pi * i / rings
        for j in range(segments + 1):
            ph = 2 * math.pi * j / segments
            n = [math.sin(th) * math.cos(ph), math.cos(th), math.sin(th) * math.sin(ph)]
            nrm += [round(c, 4) for c in n]
            pos += [round(r * c, 4) for c in n]
            uvs += [round(j / segments, 4), round(i / rings, 4)]
    for i in range(rings):
        for j in range(segments):
            a, b = i * (segments + 1) + j, (i + 1) * (segments + 1) + j
            idx += [a, b, a + 1, a + 1, b, b + 1]   # the outside is the front
    return pos, nrm, uvs, idx


shiny_scene = {
    "autoClear": True, "clearColor": [0.08, 0.09, 0.12], "ambientColor": [0.15, 0.15, 0.15],
    "cameras": [{"name": "camera", "id": "camera", "type": "FreeCamera",
                 "position": [0, 0.6, -6], "target": [0, 0, 0], "fov": 0.7,
                 "minZ": 0.1, "maxZ": 100}],
    "activeCameraID": "camera",
    "lights": [{"name": "lamp", "id": "lamp", "type": 0, "position": [-2, 3, -4],
                "diffuse": [1, 1, 1], "specular": [1, 1, 1], "intensity": 1}],
    "materials": [material("shiny %d" % p, [0.75, 0.1, 0.08], ambient=[1, 1, 1],
                           specular=[1, 1, 1], specularPower=p) for p in (8, 32, 128)],
    # one geometry, three meshes (geometryId, as the exporters share one)
    "geometries": {"vertexData": [dict(zip(("id", "positions", "normals", "uvs", "indices"),
                                           ("ball",) + sphere(0.8)))]},
    "meshes": [{"name": "sphere %d" % p, "id": "sphere %d" % p, "materialId": "shiny %d" % p,
                "position": [x, 0, 0], "rotation": [0, 0, 0], "scaling": [1, 1, 1],
                "isVisible": True, "isEnabled": True, "geometryId": "ball"}
               for x, p in ((-1.9, 8), (0, 32), (1.9, 128))],
}

out = (shiny_scene if "--shiny" in sys.argv[1:] else floor_scene if "--floor" in sys.argv[1:]
       else fog_scene if "--fog" in sys.argv[1:] else scene)
print(json.dumps(out, separators=(",", ":")))
