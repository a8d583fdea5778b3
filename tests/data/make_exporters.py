#!/usr/bin/env python3
"""Writes tests/data/exporters/*.babylon (and the crate.png one names):
small scenes in the layouts that Babylon.js's exporters write (the keys
each writes, in its order, and its habits), made here so that nothing
third-party is committed. Each holds a few boxes or planes;
tests/test_exporters.c loads each, checks the exact warnings it gives
and draws it.

    python3 tests/data/make_exporters.py tests/data/exporters

max.babylon      3ds Max (older Max2Babylon): [r,g,b,a] colours, the
                 "Default camera" framing an empty box with "Infinity"
                 strings, a PBRMetallicRoughnessMaterial (baseColor,
                 metallic, roughness), a multi-material, a mesh kept in a
                 delayLoadingFile, a light's includedOnlyMeshesIds, "" for
                 no parent or material.
blender.babylon  Blender exporter: producer block, StandardMaterial keys
                 (ambient, diffuse, specular, emissive, specularPower,
                 alpha, backFaceCulling, checkReadyOnlyOnce,
                 maxSimultaneousLights), an embedded hasAlpha texture
                 (cut-out), a half-transparent box, a sun and a point
                 light with specular colours.
maya.babylon     Maya exporter: a PBRMaterial (albedo, metallic,
                 roughness, emissive) beside a StandardMaterial with an
                 emissiveTexture, a transform-node parent, a camera with a
                 target, a hemispheric light.
serializer.babylon  Babylon.js's SceneSerializer (the Editor and
                 playground exports): geometries.vertexData shared by
                 geometryId, uniqueIds, materialUniqueId,
                 materialsUniqueIds, a parentId that is a uniqueId, a
                 localMatrix as a Float32Array's object, an instance, a
                 texture in base64String.
gltf.babylon     a glTF file loaded into Babylon.js (the Sandbox) and
                 saved by the SceneSerializer: the glTF loader's
                 "__root__" node (turned half about y, z scaled by -1)
                 over its meshes, each with overrideMaterialSideOrientation
                 0 and a PBRMaterial with sideOrientation 0.
c4d.babylon      Cinema 4D's exporter (its Scene_Control object): keys
                 sorted, four-space indents with each innermost [...]
                 pressed onto one line, the old "activeCamera" by name,
                 "geometries": [], "materials": [] and every mesh's
                 materialId "" (its material tag is not exported), meshes
                 with their position alone and parentId "" or the parent
                 polygon object's name, each quad's shared points split
                 a,d,c / a,c,b with no normals, a UniversalCamera with a
                 target and numbers where Babylon.js keeps booleans and
                 vectors (applyGravity, ellipsoid, checkCollisions),
                 lights with null for the keys their type has not, one
                 under a polygon object (its position the local one).
babylonexport.babylon  Babylon.js 1.x's C# converter (BabylonExport.exe) from
                 an OBJ and its MTL: DataContractJsonSerializer's output
                 (keys sorted, null written for what is unset, "/"
                 escaped), GUIDs for ids, interleaved "vertices" (position,
                 normal, uv) with uvCount 1 and subMeshes as its first
                 versions wrote them (later ones split them), the OBJ's
                 winding and z kept, an invisible proxy mesh without
                 vertices over one part per material (named " / group"),
                 MTL materials with backFaceCulling false and ambient
                 [1,1,1], a texture named by its file name (crate.png,
                 written beside it), and the "Default camera" and
                 "Default light" it makes when the source has none.
righthanded.babylon  a glTF file loaded into a Babylon.js scene with
                 useRightHandedSystem true and saved by the
                 SceneSerializer: the loader's "__root__" is then the
                 identity, each mesh keeps glTF's winding with
                 sideOrientation 1 (as do its PBRMaterials), one node is
                 turned (a quaternion) and one mirrored (scaling x -1),
                 and the camera looks down -z.
righthanded_lh.babylon  the same scene written left-handed: z negated on
                 every point, normal, position, target and direction,
                 quaternions (x, y, z, w) as (-x, -y, z, w); what
                 Babylon.js shows of both is one picture.
"""
import base64, contextlib, io, json, os, re, sys, uuid

sys.dont_write_bytecode = True

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
with contextlib.redirect_stdout(io.StringIO()):   # it prints its scene when imported
    from make_transparency import png_rgba


def data_url(w, h, px):
    return "data:image/png;base64," + base64.b64encode(png_rgba(w, h, px)).decode()


def cutout_texture():
    """8x8 green leaf: opaque inside a disc, alpha 0 at the corners"""
    px = []
    for y in range(8):
        for x in range(8):
            inside = (x - 3.5) ** 2 + (y - 3.5) ** 2 < 12
            px += [40, 200, 60, 255 if inside else 0]
    return data_url(8, 8, px)


def glow_texture():
    """4x4 all-red emissive map"""
    return data_url(4, 4, [255, 0, 0, 255] * 16)


def box(s):
    """a box of side s: 24 vertices, outward normals, each face's outside
    its front (as make_transparency.py's box)"""
    h = s / 2
    faces = [((0, 0, -1), (1, 0, 0), (0, 1, 0)), ((0, 0, 1), (-1, 0, 0), (0, 1, 0)),
             ((1, 0, 0), (0, 0, 1), (0, 1, 0)), ((-1, 0, 0), (0, 0, -1), (0, 1, 0)),
             ((0, 1, 0), (1, 0, 0), (0, 0, 1)), ((0, -1, 0), (1, 0, 0), (0, 0, -1))]
    pos, nrm, uvs, idx = [], [], [], []
    for n, u, v in faces:
        base = len(pos) // 3
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            pos += [h * (n[k] + su * u[k] + sv * v[k]) for k in range(3)]
            nrm += list(n)
        uvs += [0, 0, 1, 0, 1, 1, 0, 1]
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return pos, nrm, uvs, idx


def plane(s):
    """an upright s x s plane facing -z (towards a camera at -z)"""
    h = s / 2
    return ([-h, -h, 0, h, -h, 0, h, h, 0, -h, h, 0], [0, 0, -1] * 4,
            [0, 0, 1, 0, 1, 1, 0, 1], [0, 1, 2, 0, 2, 3])


def r(v):
    return [round(x, 4) for x in v]


def shared_box(s):
    """box(s) as a modeller keeps it: 8 points, each face a quad over
    them (a, b, c, d), outward when split into (a, d, c) and (a, c, b)"""
    pos, _, _, idx = box(s)
    points, quads = [], []
    for f in range(6):
        corners = []
        for k in range(4):
            p = tuple(pos[3 * (4 * f + k):3 * (4 * f + k) + 3])
            if p not in points:
                points.append(p)
            corners.append(points.index(p))
        p0, p1, p2, p3 = corners
        quads.append((p0, p3, p2, p1))
    return [x for p in points for x in p], quads


def max_scene():
    pos, nrm, uvs, idx = box(1)
    def mesh(mid, mat, at, sub=None):
        m = {"name": mid, "id": mid, "parentId": "", "materialId": mat,
             "isEnabled": True, "isVisible": True, "pickable": True,
             "position": at, "rotation": [0, 0, 0], "scaling": [1, 1, 1],
             "infiniteDistance": False, "billboardMode": 0, "visibility": 1,
             "positions": r(pos), "normals": nrm, "uvs": uvs, "indices": idx,
             "checkCollisions": False, "receiveShadows": False,
             "subMeshes": sub or [{"materialIndex": 0, "verticesStart": 0,
                                   "verticesCount": 24, "indexStart": 0, "indexCount": 36}]}
        return m
    two = [{"materialIndex": 0, "verticesStart": 0, "verticesCount": 24, "indexStart": 0, "indexCount": 18},
           {"materialIndex": 1, "verticesStart": 0, "verticesCount": 24, "indexStart": 18, "indexCount": 18}]
    delayed = {"name": "Proxy", "id": "proxy", "parentId": "", "materialId": "", "isEnabled": True,
               "isVisible": True, "position": [0, 3, 0], "rotation": [0, 0, 0], "scaling": [1, 1, 1],
               "delayLoadingFile": "max.proxy.babylonbinarymeshdata", "geometryId": "proxyGeometry",
               "boundingBoxMinimum": [-1, -1, -1], "boundingBoxMaximum": [1, 1, 1]}
    std = lambda mid, d, e: {"name": mid, "id": mid, "backFaceCulling": True, "wireframe": False,
                             "alpha": 1, "alphaCutOff": 0.4, "ambient": [0, 0, 0, 1],
                             "diffuse": d + [1], "specular": [0, 0, 0, 1], "emissive": e + [1],
                             "specularPower": 64, "useEmissiveAsIllumination": False,
                             "maxSimultaneousLights": 4, "diffuseTexture": None}
    return {
        "producer": {"name": "3dsmax", "version": "2017", "exporter_version": "1.2", "file": "max.babylon"},
        "autoClear": True, "clearColor": [0.2, 0.2, 0.3, 1], "ambientColor": [0, 0, 0, 1],
        "fogMode": 0, "fogColor": None, "fogStart": 0, "fogEnd": 0, "fogDensity": 0,
        "gravity": [0, -0.9, 0], "physicsEngine": None, "physicsEnabled": False,
        "physicsGravity": None, "workerCollisions": False,
        "meshes": [mesh("RedBox", "Red", [-1.5, 0, 0]),
                   mesh("MetalBox", "Metal", [0, 0, 0]),
                   mesh("TwoTone", "TwoTone", [1.5, 0, 0], two),
                   delayed],
        "materials": [std("Red", [0.8, 0, 0], [0, 0, 0]),
                      std("Glow", [0, 0, 0], [0, 0, 1]),
                      {"customType": "BABYLON.PBRMetallicRoughnessMaterial", "name": "Metal",
                       "id": "Metal", "backFaceCulling": True, "wireframe": False, "alpha": 1,
                       "baseColor": [0.9, 0.9, 0.2], "metallic": 0.0, "roughness": 0.5,
                       "emissive": [0, 0, 0], "maxSimultaneousLights": 4,
                       "transparencyMode": 0, "baseTexture": None,
                       "metallicRoughnessTexture": None, "normalTexture": None}],
        "multiMaterials": [{"name": "TwoTone", "id": "TwoTone", "materials": ["Red", "Glow"]}],
        "cameras": [{"name": "Default camera", "id": "defaultCamera", "parentId": "",
                     "position": ["-Infinity", "-Infinity", "-Infinity"],
                     "target": ["-Infinity", "-Infinity", "-Infinity"],
                     "fov": 0.8, "minZ": 0.1, "maxZ": "Infinity", "speed": 1, "inertia": 0.9,
                     "checkCollisions": False, "applyGravity": False,
                     "ellipsoid": [0.5, 1, 0.5], "type": "FreeCamera", "mode": 0}],
        "activeCameraID": "defaultCamera",
        "lights": [{"name": "Key", "id": "key", "parentId": "", "position": [0, 5, -5],
                    "direction": [0, -1, 1], "type": 1, "intensity": 1,
                    "diffuse": [1, 1, 1, 1], "specular": [1, 1, 1, 1],
                    "range": 3.4028234663852886e38, "excludedMeshesIds": [],
                    "includedOnlyMeshesIds": ["MetalBox", "TwoTone"]}],
        "shadowGenerators": [], "skeletons": [], "actions": None, "sounds": None,
    }


def blender_scene():
    bpos, bnrm, buvs, bidx = box(1)
    ppos, pnrm, puvs, pidx = plane(1.5)
    def mesh(mid, mat, at, geo):
        p, n, u, i = geo
        return {"name": mid, "id": mid, "materialId": mat, "billboardMode": 0,
                "position": at, "rotation": [0, 0, 0], "scaling": [1, 1, 1],
                "isVisible": True, "freezeWorldMatrix": False, "isEnabled": True,
                "checkCollisions": False, "receiveShadows": False, "tags": "",
                "positions": r(p), "normals": n, "uvs": u, "indices": i,
                "subMeshes": [{"materialIndex": 0, "verticesStart": 0,
                               "verticesCount": len(p) // 3, "indexStart": 0, "indexCount": len(i)}]}
    def mat(mid, diffuse, **extra):
        m = {"name": mid, "id": mid, "ambient": [0, 0, 0], "diffuse": diffuse,
             "specular": [0.5, 0.5, 0.5], "emissive": [0, 0, 0], "specularPower": 50,
             "alpha": 1, "backFaceCulling": True, "checkReadyOnlyOnce": False,
             "maxSimultaneousLights": 4}
        m.update(extra)
        return m
    return {
        "producer": {"name": "Blender", "version": "2.79", "exporter_version": "5.6.4", "file": "blender.babylon"},
        "autoClear": True, "clearColor": [0.05, 0.05, 0.05], "ambientColor": [0, 0, 0],
        "gravity": [0, -9.81, 0],
        "materials": [mat("blender.Ground", [0.3, 0.3, 0.8]),
                      mat("blender.Leaf", [1, 1, 1], backFaceCulling=False,
                          diffuseTexture={"name": cutout_texture(), "level": 1, "hasAlpha": True,
                                          "coordinatesMode": 0, "uOffset": 0, "vOffset": 0,
                                          "uScale": 1, "vScale": 1, "uAng": 0, "vAng": 0,
                                          "wAng": 0, "wrapU": 1, "wrapV": 1, "coordinatesIndex": 0}),
                      mat("blender.Glass", [0.9, 0.9, 0.9], alpha=0.5)],
        "multiMaterials": [],
        "skeletons": [],
        "meshes": [mesh("Ground", "blender.Ground", [0, -0.6, 0], box(1)),
                   mesh("Leaf", "blender.Leaf", [-0.9, 0, -0.6], (ppos, pnrm, puvs, pidx)),
                   mesh("Glass", "blender.Glass", [0.9, 0, -0.6], (bpos, bnrm, buvs, bidx))],
        "cameras": [{"name": "Camera", "id": "Camera", "position": [0, 0.5, -5],
                     "rotation": [0.0997, 0, 0], "fov": 0.8576, "minZ": 0.1, "maxZ": 100,
                     "speed": 1, "inertia": 0.9, "checkCollisions": False, "applyGravity": False,
                     "ellipsoid": [0.2, 0.9, 0.2], "cameraRigMode": 0, "interaxial_distance": 0.0637,
                     "type": "FreeCamera"}],
        "activeCamera": "Camera",
        "lights": [{"name": "Sun", "id": "Sun", "type": 1, "direction": [0.3, -1, 0.6],
                    "intensity": 1, "diffuse": [1, 1, 1], "specular": [1, 1, 1]},
                   {"name": "Lamp", "id": "Lamp", "type": 0, "position": [2, 2, -3],
                    "intensity": 0.5, "diffuse": [1, 0.9, 0.8], "specular": [1, 1, 1],
                    "range": 30}],
        "shadowGenerators": [],
    }


def maya_scene():
    pos, nrm, uvs, idx = box(1)
    def mesh(mid, mat, at, parent):
        m = {"name": mid, "id": mid, "parentId": parent, "materialId": mat,
             "isEnabled": True, "isVisible": True, "pickable": True,
             "position": at, "rotationQuaternion": [0, 0, 0, 1], "scaling": [1, 1, 1],
             "positions": r(pos), "normals": nrm, "uvs": uvs, "indices": idx,
             "subMeshes": [{"materialIndex": 0, "verticesStart": 0, "verticesCount": 24,
                            "indexStart": 0, "indexCount": 36}],
             "billboardMode": 0, "visibility": 1, "checkCollisions": False, "receiveShadows": True}
        return m
    return {
        "producer": {"name": "Maya", "version": "2018", "exporter_version": "1.3", "file": "maya.babylon"},
        "autoClear": True, "clearColor": [0.2, 0.2, 0.3, 1], "ambientColor": [0, 0, 0],
        "fogMode": 0, "fogColor": None, "fogStart": 0, "fogEnd": 0, "fogDensity": 0,
        "gravity": [0, -0.9, 0],
        "meshes": [mesh("pCube1", "lambert2", [-0.8, 0, 0], "group1"),
                   mesh("pCube2", "aiStandardSurface1", [0.8, 0, 0], "group1")],
        "transformNodes": [{"name": "group1", "id": "group1", "parentId": None,
                            "position": [0, 0, 0], "rotationQuaternion": [0, 0, 0, 1],
                            "scaling": [1, 1, 1], "isEnabled": True}],
        "materials": [{"customType": "BABYLON.StandardMaterial", "name": "lambert2", "id": "lambert2",
                       "backFaceCulling": True, "alpha": 1, "ambient": [0, 0, 0],
                       "diffuse": [0.2, 0.2, 0.2], "specular": [0, 0, 0], "emissive": [0, 0, 0],
                       "specularPower": 64, "maxSimultaneousLights": 4,
                       "emissiveTexture": {"name": glow_texture(), "level": 1, "hasAlpha": False,
                                           "coordinatesMode": 0, "uOffset": 0, "vOffset": 0,
                                           "uScale": 1, "vScale": 1, "uAng": 0, "vAng": 0,
                                           "wAng": 0, "wrapU": 1, "wrapV": 1,
                                           "coordinatesIndex": 0, "isCube": False}},
                      {"customType": "BABYLON.PBRMaterial", "name": "aiStandardSurface1",
                       "id": "aiStandardSurface1", "backFaceCulling": True, "alpha": 1,
                       "albedo": [0.1, 0.8, 0.1], "reflectivity": [1, 1, 1], "metallic": 0,
                       "roughness": 0.4, "emissive": [0, 0, 0], "maxSimultaneousLights": 4,
                       "transparencyMode": 0, "environmentIntensity": 1,
                       "useRoughnessFromMetallicTextureAlpha": False,
                       "useRoughnessFromMetallicTextureGreen": True,
                       "useMetallnessFromMetallicTextureBlue": True}],
        "multiMaterials": [],
        "cameras": [{"name": "persp", "id": "persp", "parentId": None, "position": [0, 0, -4],
                     "target": [0, 0, 0], "fov": 0.6, "minZ": 0.1, "maxZ": 1000,
                     "type": "FreeCamera", "mode": 0}],
        "activeCameraID": "persp",
        "lights": [{"name": "ambientLight1", "id": "ambientLight1", "type": 3,
                    "direction": [0, 1, 0], "intensity": 1, "diffuse": [1, 1, 1],
                    "specular": [0, 0, 0], "groundColor": [0.2, 0.2, 0.2]}],
    }


def serializer_scene():
    pos, nrm, uvs, idx = box(1)
    ident = {str(k): float(k % 5 == 0) for k in range(16)}   # a Float32Array, serialized
    sub = [{"materialIndex": 0, "verticesStart": 0, "verticesCount": 24, "indexStart": 0, "indexCount": 18},
           {"materialIndex": 1, "verticesStart": 0, "verticesCount": 24, "indexStart": 18, "indexCount": 18}]
    def mesh(mid, uid, at, parent, mat_uid, submeshes, **extra):
        m = {"name": mid, "id": mid, "uniqueId": uid, "type": "Mesh", "geometryId": "shared",
             "position": at, "rotation": [0, 0, 0], "scaling": [1, 1, 1],
             "localMatrix": ident, "isEnabled": True, "isVisible": True,
             "infiniteDistance": False, "pickable": True, "receiveShadows": False,
             "billboardMode": 0, "visibility": 1, "checkCollisions": False, "isBlocker": False,
             "parentId": parent, "materialUniqueId": mat_uid, "subMeshes": submeshes,
             "instances": [], "animations": [], "ranges": []}
        m.update(extra)
        return m
    def std(mid, uid, diffuse, **extra):
        m = {"tags": None, "ambient": [0, 0, 0], "diffuse": diffuse, "specular": [0, 0, 0],
             "emissive": [0, 0, 0], "specularPower": 64, "useAlphaFromDiffuseTexture": False,
             "useEmissiveAsIllumination": False, "linkEmissiveWithDiffuse": False,
             "useSpecularOverAlpha": False, "disableLighting": False, "maxSimultaneousLights": 4,
             "id": mid, "uniqueId": uid, "name": mid, "checkReadyOnlyOnce": False,
             "state": "", "alpha": 1, "backFaceCulling": True, "sideOrientation": 1,
             "alphaMode": 2, "disableDepthWrite": False, "fogEnabled": True,
             "customType": "BABYLON.StandardMaterial"}
        m.update(extra)
        return m
    stripes = []
    for y in range(4):
        for x in range(4):
            stripes += [255, 255, 255, 255] if x < 2 else [255, 128, 0, 255]
    tex = {"tags": None, "url": "stripes", "uOffset": 0, "vOffset": 0, "uScale": 1, "vScale": 1,
           "uAng": 0, "vAng": 0, "wAng": 0, "uRotationCenter": 0.5, "vRotationCenter": 0.5,
           "wRotationCenter": 0.5, "homogeneousRotationInUVTransform": False, "isBlocking": True,
           "name": "stripes", "hasAlpha": False, "getAlphaFromRGB": False, "level": 1,
           "coordinatesIndex": 0, "coordinatesMode": 0, "wrapU": 1, "wrapV": 1, "wrapR": 1,
           "anisotropicFilteringLevel": 4, "isCube": False, "is3D": False, "is2DArray": False,
           "gammaSpace": True, "invertZ": False, "lodLevelInAlpha": False, "isRenderTarget": False,
           "samplingMode": 3, "invertY": True, "base64String": data_url(4, 4, stripes)}
    return {
        "useDelayedTextureLoading": False, "autoClear": True, "clearColor": [0.2, 0.2, 0.3, 1],
        "ambientColor": [0, 0, 0], "gravity": [0, -9.807, 0], "collisionsEnabled": True,
        "useRightHandedSystem": False,
        "lights": [{"tags": None, "direction": [0, 1, 0], "diffuse": [1, 1, 1], "specular": [0, 0, 0],
                    "groundColor": [0.3, 0.3, 0.3], "id": "light", "name": "light", "uniqueId": 1,
                    "intensity": 1, "range": 3.4028234663852886e38, "falloffType": 0,
                    "intensityMode": 0, "radius": 0.00001, "shadowEnabled": True,
                    "excludeWithLayerMask": 0, "includeOnlyWithLayerMask": 0, "lightmapMode": 0,
                    "type": 3, "excludedMeshesIds": [], "includedOnlyMeshesIds": [],
                    "isEnabled": True, "animations": [], "ranges": []}],
        "cameras": [{"tags": None, "position": [0, 1, -5], "rotation": [0.2, 0, 0],
                     "speed": 2, "id": "camera", "name": "camera", "uniqueId": 2,
                     "fov": 0.8, "minZ": 1, "maxZ": 10000, "inertia": 0.9, "mode": 0,
                     "isIntermediate": False, "fovMode": 0, "type": "UniversalCamera",
                     "isEnabled": True, "animations": [], "ranges": []}],
        "activeCameraID": "camera",
        "materials": [std("white", 10, [1, 1, 1], diffuseTexture=tex),
                      std("blue", 11, [0.1, 0.2, 1])],
        "multiMaterials": [{"name": "both", "id": "both", "uniqueId": 12, "tags": None,
                            "materials": ["white", "blue"], "materialsUniqueIds": [10, 11]}],
        "skeletons": [], "transformNodes": [],
        "geometries": {"boxes": [], "spheres": [], "cylinders": [], "toruses": [], "grounds": [],
                       "planes": [], "torusKnots": [],
                       "vertexData": [{"id": "shared", "updatable": False, "positions": r(pos),
                                       "normals": nrm, "uvs": uvs, "indices": idx}]},
        "meshes": [mesh("box", 20, [-1, 0, 0], None, 12, sub,
                        instances=[{"name": "box copy", "id": "box copy", "uniqueId": 22,
                                    "position": [0, -1.2, 0], "rotation": [0, 0, 0],
                                    "scaling": [1, 1, 1], "pickable": True, "checkCollisions": False}]),
                   mesh("child", 21, [2, 0, 0], 20, 11,
                        [{"materialIndex": 0, "verticesStart": 0, "verticesCount": 24,
                          "indexStart": 0, "indexCount": 36}])],
        "particleSystems": [], "postProcesses": [], "animations": [], "sounds": [],
    }


def gltf_pbr(mid, uid, albedo, side):
    """a PBRMaterial as the glTF loader makes it, saved"""
    return {
        "customType": "BABYLON.PBRMaterial", "id": mid, "uniqueId": uid, "name": mid,
        "albedoColor": albedo, "reflectivityColor": [1, 1, 1], "metallic": 0, "roughness": 0.5,
        "emissiveColor": [0, 0, 0], "alpha": 1, "backFaceCulling": True, "sideOrientation": side,
        "transparencyMode": 0, "maxSimultaneousLights": 4, "environmentIntensity": 1,
        "useRoughnessFromMetallicTextureAlpha": False, "useRoughnessFromMetallicTextureGreen": True,
        "useMetallnessFromMetallicTextureBlue": True, "useRadianceOverAlpha": True}


def gltf_saved(right_handed, light, eye, root, vertex_data, meshes):
    """a glTF file's red and green boxes as the Sandbox saves them, around
    its "__root__" (root: its rotationQuaternion and scaling)"""
    side = 1 if right_handed else 0
    return {
        "autoClear": True, "clearColor": [0.2, 0.2, 0.3, 1], "ambientColor": [0, 0, 0],
        "gravity": [0, -9.807, 0], "useRightHandedSystem": right_handed,
        "lights": [{"direction": light, "diffuse": [1, 1, 1], "specular": [0, 0, 0],
                    "id": "sun", "name": "sun", "uniqueId": 5, "intensity": 1, "type": 1,
                    "excludedMeshesIds": [], "includedOnlyMeshesIds": [], "isEnabled": True}],
        "cameras": [{"position": eye, "target": [0, 0, 0], "id": "camera", "name": "camera",
                     "uniqueId": 6, "fov": 0.8, "minZ": 0.1, "maxZ": 100, "mode": 0,
                     "type": "FreeCamera", "isEnabled": True}],
        "activeCameraID": "camera",
        "materials": [gltf_pbr("Red", 10, [0.8, 0.1, 0.1], side),
                      gltf_pbr("Green", 11, [0.1, 0.8, 0.1], side)],
        "multiMaterials": [],
        "transformNodes": [{"name": "__root__", "id": "__root__", "uniqueId": 1,
                            "position": [0, 0, 0], "rotationQuaternion": root[0],
                            "scaling": root[1], "isEnabled": True}],
        "geometries": {"boxes": [], "spheres": [], "cylinders": [], "toruses": [], "grounds": [],
                       "planes": [], "torusKnots": [], "vertexData": vertex_data},
        "meshes": meshes,
    }


def gltf_mesh(mid, uid, at, mat_uid, **extra):
    """a mesh the glTF loader makes, under "__root__", saved"""
    m = {"name": mid, "id": mid, "uniqueId": uid, "type": "Mesh", "geometryId": mid + "_geo",
         "position": at, "rotationQuaternion": [0, 0, 0, 1], "scaling": [1, 1, 1],
         "isEnabled": True, "isVisible": True, "parentId": 1, "materialUniqueId": mat_uid}
    m.update(extra)
    m.update({"subMeshes": [{"materialIndex": 0, "verticesStart": 0, "verticesCount": 24,
                             "indexStart": 0, "indexCount": 36}], "instances": []})
    return m


def gltf_box():
    """box(1) in glTF's winding: its front faces wind the other way"""
    pos, nrm, uvs, idx = box(1)
    return pos, nrm, uvs, [idx[k + d] for k in range(0, len(idx), 3) for d in (0, 2, 1)]


def gltf_scene():
    # the loader keeps glTF's triangles and says so with side orientation 0
    pos, nrm, uvs, idx = gltf_box()
    geo = lambda gid: {"id": gid, "updatable": False, "positions": r(pos), "normals": nrm,
                       "uvs": uvs, "indices": idx}
    side0 = {"materialId": "", "overrideMaterialSideOrientation": 0}
    return gltf_saved(False, [0.2, -0.5, 1], [0, 1, -4], ([0, 1, 0, 0], [1, 1, -1]),
                      [geo("Cube_geo"), geo("Cube.001_geo")],
                      [gltf_mesh("Cube", 2, [0.8, 0, 0], 10, **side0),
                       gltf_mesh("Cube.001", 3, [-0.8, 0, 0], 11, **side0)])


def righthanded_scene(left_handed=False):
    """see the module's docstring; left_handed writes its mirror in z"""
    flip = -1 if left_handed else 1
    z = lambda v: [v[0], v[1], flip * v[2]] if v[2] else list(v[:2]) + [0]
    def zs(flat):
        return [x for k in range(0, len(flat), 3) for x in z(flat[k:k + 3])]
    quat = lambda q: [flip * q[0], flip * q[1], q[2], q[3]]
    pos, nrm, uvs, idx = gltf_box()
    shifted = [pos[k] + (0.3 if k % 3 == 0 else 0) for k in range(len(pos))]
    geo = lambda gid, p: {"id": gid, "updatable": False, "positions": r(zs(p)), "normals": zs(nrm),
                          "uvs": uvs, "indices": idx}
    turn = [0, 0.258819, 0, 0.965926]          # 30 degrees about y
    return gltf_saved(not left_handed, z([0.2, -0.5, -1]), z([0, 1, 5]),
                      ([0, 0, 0, 1], [1, 1, 1]),
                      [geo("Cube_geo", pos), geo("Cube.mirror_geo", shifted)],
                      [gltf_mesh("Cube", 2, z([0.8, 0, 0]), 10, rotationQuaternion=quat(turn),
                                 sideOrientation=1),
                       gltf_mesh("Cube.mirror", 3, z([-0.5, 0, 0]), 11, scaling=[-1, 1, 1],
                                 sideOrientation=1)])


def guid(name):
    """a GUID as the converter writes ids, made the same each run"""
    return str(uuid.uuid5(uuid.NAMESPACE_URL, "mote-exporters/" + name))


def stripes_png():
    """4x4: the left half white, the right half orange, the same down
    each column (so which row v = 0 names does not matter)"""
    px = []
    for y in range(4):
        for x in range(4):
            px += [255, 255, 255, 255] if x < 2 else [255, 128, 0, 255]
    return png_rgba(4, 4, px)


def babylonexport_scene():
    """an OBJ of two groups, "crate" (textured) and "slab" (red), each a
    unit box, converted as the OBJ path does: positions, normals and v as
    written, each quad 1-2-3 / 1-3-4 in the OBJ's (right-handed) order"""
    pos, nrm, uvs, _ = box(1)
    idx = []
    for f in range(6):
        b = 4 * f
        idx += [b, b + 3, b + 2, b, b + 2, b + 1]
    def part(name, dx, mat):
        verts = []
        for k in range(24):
            verts += [round(pos[3 * k] + dx, 4), pos[3 * k + 1], pos[3 * k + 2]]
            verts += nrm[3 * k:3 * k + 3] + uvs[2 * k:2 * k + 2]
        return {"animations": None, "autoAnimate": False, "autoAnimateFrom": 0,
                "autoAnimateLoop": False, "autoAnimateTo": 0, "billboardMode": 0,
                "checkCollisions": False, "id": guid("mesh " + name), "indices": idx,
                "isEnabled": True, "isVisible": True, "localMatrix": None,
                "materialId": guid("material " + mat), "name": " / " + name,
                "parentId": guid("proxy"), "position": [0, 0, 0], "receiveShadows": False,
                "rotation": [0, 0, 0], "scaling": [1, 1, 1], "skeletonId": -1,
                "subMeshes": [{"indexCount": 36, "indexStart": 0, "materialIndex": 0,
                               "verticesCount": 24, "verticesStart": 0}],
                "uvCount": 1, "vertices": verts, "visibility": 1}
    proxy = dict(part("slab", 0, "x"), id=guid("proxy"), name="slab", parentId="", materialId="",
                 isVisible=False, indices=None, vertices=None, uvCount=0, subMeshes=None)
    tex = {"animations": None, "coordinatesIndex": 0, "coordinatesMode": 0, "hasAlpha": False,
           "isCube": False, "isRenderTarget": False, "level": 1, "mirrorPlane": None,
           "name": "crate.png", "renderList": None, "renderTargetSize": 0, "uAng": 0,
           "uOffset": 0, "uScale": 1, "vAng": 0, "vOffset": 0, "vScale": 1, "wAng": 0,
           "wrapU": 1, "wrapV": 1}
    def mat(name, diffuse, specular, texture):
        return {"alpha": 1, "ambient": [1, 1, 1], "ambientTexture": None, "backFaceCulling": False,
                "bumpTexture": None, "diffuse": diffuse, "diffuseTexture": texture,
                "emissive": [0, 0, 0], "emissiveTexture": None, "id": guid("material " + name),
                "name": name, "opacityTexture": None, "reflectionTexture": None,
                "specular": specular, "specularPower": 96.0784, "specularTexture": None}
    # the bounds of both parts: (-1.25, -0.5, -0.5) to (1.25, 0.5, 0.5);
    # the camera and the light stand at the middle plus the extent
    extent = (2.5 ** 2 + 1 + 1) ** 0.5
    return {
        "activeCameraID": guid("camera"), "ambientColor": [0, 0, 0], "autoClear": True,
        "cameras": [{"applyGravity": False, "checkCollisions": False, "ellipsoid": None,
                     "fov": 0.8, "id": guid("camera"), "inertia": 0.9,
                     "maxZ": round(extent * 4, 5), "minZ": 0.1, "name": "Default camera",
                     "position": [2.5, 1, 1], "rotation": [0, 0, 0],
                     "speed": round(extent / 50, 7), "target": [0, 0, 0]}],
        "clearColor": [0.2, 0.2, 0.3], "fogColor": None, "fogDensity": 0, "fogEnd": 0,
        "fogMode": 0, "fogStart": 0, "gravity": [0, 0, -0.9],
        "lights": [{"diffuse": [1, 1, 1], "direction": None, "id": guid("light"), "intensity": 1,
                    "name": "Default light", "position": [2.5, 1, 1], "specular": [1, 1, 1],
                    "type": 0}],
        "materials": [mat("crate", [1, 1, 1], [0, 0, 0], tex), mat("red", [0.8, 0, 0], [0.5, 0.5, 0.5], None)],
        "meshes": [proxy, part("crate", -0.75, "crate"), part("slab", 0.75, "red")],
        "multiMaterials": [], "particleSystems": None, "shadowGenerators": [], "skeletons": []}


def datacontract_text(scene):
    """DataContractJsonSerializer: members sorted, no blanks, "/" as "\\/" """
    return json.dumps(scene, sort_keys=True, separators=(",", ":")).replace("/", "\\/")


def c4d_scene():
    """what Scene_Control writes: position alone for a node (rotation and
    scale are not exported), the scene's units 200 to one"""
    cube_pos, cube_quads = shared_box(1)
    # the plane is a polygon object of one quad facing -z
    plane_pos, plane_quads = [-0.6, -0.6, 0, 0.6, -0.6, 0, 0.6, 0.6, 0, -0.6, 0.6, 0], [(0, 3, 2, 1)]
    def polygon(name, parent, at, points, quads):
        idx, uvs = [], []
        for a, b, c, d in quads:
            idx += [a, d, c, a, c, b]
        # each point takes its uv from the first polygon that uses it
        for p in range(len(points) // 3):
            q = next(q for q in quads if p in q)
            k = q.index(p)
            uvs += [(0, 1, 1, 0)[k], (0, 0, 1, 1)[k]]
        return {"name": name, "id": name, "tags": "", "parentId": parent, "materialId": "",
                "position": at, "positions": r(points), "indices": idx, "uvs": uvs}
    anim = {"animations": [], "autoAnimate": False, "autoAnimateFrom": 0,
            "autoAnimateLoop": False, "autoAnimateSpeed": 1, "autoAnimateTo": 0}
    def light(name, kind, at, direction, diffuse, intensity, specular, parent=""):
        l = {"name": name, "id": name, "type": kind, "tags": "", "parentId": parent, "position": at,
             "direction": direction, "diffuse": diffuse, "specular": specular,
             "groundColor": None, "intensity": intensity, "angle": None, "exponent": None}
        l.update(anim)
        return l
    cam = {"name": "Camera", "id": "Camera", "type": "UniversalCamera", "tags": "", "parentId": "",
           "position": [0.0, 0.0, -4.0], "target": [0.0, 0.0, 6.0], "fov": 0.8, "minZ": 1.0,
           "maxZ": 10000.0, "speed": 2.0, "inertia": 0.9, "checkCollisions": 0,
           "applyGravity": 0.8, "ellipsoid": 0.8, "attachControls": 0, "inputmgr": []}
    cam.update(anim)
    cam["autoAnimateSpeed"] = 1.0
    scene = {
        "autoClear": True, "clearColor": [0.2, 0.2, 0.5, 1.0], "ambientColor": [0.0, 0.0, 0.0],
        "gravity": [0.0, -9.81, 0.0], "cameras": [cam], "activeCamera": "Camera",
        # the point light sits under the plane, at its own position there
        "lights": [light("D_Light", 1, [0.0, 2.0, -3.0], [0.0, 0.0, 1.0], [1.0, 1.0, 1.0], 0.5,
                         [0.0, 0.0, 0.0]),
                   light("P_Light", 0, [0.0, 0.0, -1.0], None, [1.0, 0.0, 0.0], 0.5,
                         [0.0, 0.0, 0.0], parent="Plane")],
        "reflectionProbes": [], "materials": [], "geometries": [],
        "meshes": [polygon("Cube", "", [-0.8, 0.0, 0.0], cube_pos, cube_quads),
                   polygon("Plane", "Cube", [1.6, 0.0, 0.0], plane_pos, plane_quads)],
        "multiMaterials": [], "shadowGenerators": [], "skeletons": [], "particleSystems": [],
        "lensFlareSystems": [], "actions": [], "sounds": [], "collisionsEnabled": False,
        "physicsEnabled": False, "physicsGravity": [0.0, -9.81, 0.0], "physicsEngine": "oimo"}
    scene.update({k: v for k, v in anim.items()})
    scene["autoAnimateSpeed"] = 1.0
    return scene


def c4d_text(scene):
    """sorted and indented by four, then each [...] that holds no ']'
    pressed onto one line, blanks and all, as the exporter writes it"""
    text = json.dumps(scene, sort_keys=True, indent=4, separators=(",", ": "))
    return re.sub(r"\[[^\]]+\]", lambda m: re.sub(r"[ \r\n]", "", m.group(0)), text)


def compact(scene):
    return json.dumps(scene, separators=(",", ":")) + "\n"


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "exporters")
    os.makedirs(out, exist_ok=True)
    for name, text in (("max", compact(max_scene())), ("blender", compact(blender_scene())),
                       ("maya", compact(maya_scene())), ("serializer", compact(serializer_scene())),
                       ("gltf", compact(gltf_scene())), ("c4d", c4d_text(c4d_scene())),
                       ("babylonexport", datacontract_text(babylonexport_scene())),
                       ("righthanded", compact(righthanded_scene())),
                       ("righthanded_lh", compact(righthanded_scene(left_handed=True)))):
        with open(os.path.join(out, name + ".babylon"), "w") as f:
            f.write(text)
    with open(os.path.join(out, "crate.png"), "wb") as f:
        f.write(stripes_png())
