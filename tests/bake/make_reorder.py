#!/usr/bin/env python3
"""Writes tests/bake/reorder.babylon, the scene test_bake.c checks
mote-bake's vertex cache order on: grids whose triangles are in a shuffled
order (a direct-mapped cache transforms nearly every vertex of each), with
a colour per vertex.

  "grid"   12 x 12 vertices, coloured, and an instance of it: the two
           share one reordered vertex, colour and index array;
  "split"  10 x 10 vertices, coloured, in two sub-meshes (two index arrays
           on one vertex array): their triangles are reordered, their
           vertices and colours stay as in the file, shared.

  python3 tests/bake/make_reorder.py > tests/bake/reorder.babylon
"""
import json


def grid(n, size, seed):
    """Positions, colours and shuffled triangles of an n x n grid."""
    pos, col, tris = [], [], []
    for y in range(n):
        for x in range(n):
            u, v = x / (n - 1), y / (n - 1)
            # a bump, so that the normals and shading vary
            pos += [round((u - 0.5) * size, 4), round((v - 0.5) * size, 4),
                    round(0.3 * (u - 0.5) * (v - 0.5), 4)]
            col += [round(u, 3), round(v, 3), round(1 - u * v, 3)]
    for y in range(n - 1):
        for x in range(n - 1):
            a, b, c, d = y * n + x, y * n + x + 1, (y + 1) * n + x + 1, (y + 1) * n + x
            tris += [[a, b, c], [a, c, d]]
    state = seed
    for i in range(len(tris) - 1, 0, -1):   # Fisher-Yates, a fixed LCG
        state = (state * 1103515245 + 12345) % 2**31
        j = state % (i + 1)
        tris[i], tris[j] = tris[j], tris[i]
    return pos, col, tris


gpos, gcol, gtris = grid(12, 2.5, 1)
spos, scol, stris = grid(10, 2.5, 2)
half = len(stris) // 2
scene = {
    "materials": [{"id": "white", "diffuse": [1, 1, 1], "backFaceCulling": False},
                  {"id": "grey", "diffuse": [0.6, 0.6, 0.6], "backFaceCulling": False}],
    "multiMaterials": [{"id": "two", "materials": ["white", "grey"]}],
    "meshes": [
        {"id": "grid", "materialId": "white", "position": [-3, 1.4, 0],
         "positions": gpos, "colors": gcol, "indices": [i for t in gtris for i in t],
         "instances": [{"name": "grid2", "position": [0.2, 1.4, 0]}]},
        {"id": "split", "materialId": "two", "position": [3, -1.4, 0],
         "positions": spos, "colors": scol, "indices": [i for t in stris for i in t],
         "subMeshes": [
             {"materialIndex": 0, "verticesStart": 0, "verticesCount": 100,
              "indexStart": 0, "indexCount": 3 * half},
             {"materialIndex": 1, "verticesStart": 0, "verticesCount": 100,
              "indexStart": 3 * half, "indexCount": 3 * (len(stris) - half)}]},
    ],
    "cameras": [{"id": "c", "position": [0, 0, -9], "target": [0, 0, 0], "fov": 0.9}],
    "lights": [{"type": 0, "position": [2, 3, -6]}],
}
print(json.dumps(scene, separators=(",", ":")))
