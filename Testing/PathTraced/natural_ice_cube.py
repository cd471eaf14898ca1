# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""A natural ice cube path traced by Mitsuba 3, the target for ice-render's default picture.

The scene is ice-render's default (the `cube` model on the ground in blender-data's `forest`
panorama, its camera, filmic tone mapping), with the ice as nature makes it:
- the rounded cube itself, index of refraction 1.31, a faint blue absorption (the ice-cube
  preset's attenuation colour 0.8, 0.92, 0.98 at 0.6);
- standing in its melt water: the faces of its base (vtkIceMapper::WetBase's band: wet up to 6 %
  of its height, dry above 10 %; up to the middle of its fade) meet water (1.33) instead of air;
- a core of a few hundred small air bubbles (mixed sizes, small ones most, thickest at the
  centre) and a few vertical streams of them;
- two thin planar air cracks with irregular outlines;
- the ground a diffuse plane lit by the panorama, of the colour the panorama shows its own ground
  in (as ice-render's, without its grain), fading into it as ice-render's does.

Three steps, each in the interpreter that has what it needs:
    /usr/bin/python3 natural_ice_cube.py mesh DIR    # the model (vtk and vtkice: the build's)
    VENV/bin/python natural_ice_cube.py render DIR    # mitsuba (scalar_rgb), numpy, Pillow
    VENV/bin/python natural_ice_cube.py compare DIR ICE.png  # flip-evaluator, numpy, Pillow
`render` writes DIR/mitsuba.png (tone mapped as ice-render's filmic curve), `compare` the FLIP
difference of ICE.png (ice-render's picture of the same size) against it, and a side-by-side
picture DIR/natural-ice-cube.png (target, VTK Ice, FLIP error map)."""
import argparse
import math
import os
import sys

import numpy

WIDTH, HEIGHT = 512, 384
CAMERA = ((3.2, 1.4, 5.6), (0.0, -0.2, 0.0))  # ice-render's with a ground (IceScene.cxx)
VIEW_ANGLE = 32.0
IOR = 1.31
ATTENUATION = ((0.8, 0.92, 0.98), 0.6)  # the ice-cube preset's colour at its distance
WATER_IOR = 1.33
WET_BAND = (0.06, 0.1)  # vtkIceMapper::WetBase: wet up to 6 % of the ice's height, dry above 10 %
GROUND_HALF_SIZE = 12.0  # IceGround: 6 model extents
# IceGround's melt water: the ice's footprint blurred by this fraction of its extent, wet where
# that exceeds the first number, fully over the second more (without IceGround's uneven edge).
POOL = (0.18, 0.08, 0.05)
PANORAMA = "/usr/share/blender/datafiles/studiolights/world/forest.exr"


def make_mesh(folder):
    """ice-render's `cube` model (IceScene::LoadModel): centred, its largest extent 2."""
    import vtk
    import vtkice
    from vtk.util import numpy_support

    cube = vtkice.vtkIceBlockSource()
    cube.SetResolution(48)
    cube.SetRoundness(0.22)
    cube.SetDisplacement(0.03)
    cube.SetSeed(3)
    cube.Update()
    model = cube.GetOutput()
    bounds = model.GetBounds()
    extent = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
    transform = vtk.vtkTransform()
    transform.Scale(2.0 / extent, 2.0 / extent, 2.0 / extent)
    transform.Translate(-0.5 * (bounds[0] + bounds[1]), -0.5 * (bounds[2] + bounds[3]),
                        -0.5 * (bounds[4] + bounds[5]))
    apply = vtk.vtkTransformPolyDataFilter()
    apply.SetInputData(model)
    apply.SetTransform(transform)
    triangles = vtk.vtkTriangleFilter()
    triangles.SetInputConnection(apply.GetOutputPort())
    normals = vtk.vtkPolyDataNormals()
    normals.SetInputConnection(triangles.GetOutputPort())
    normals.SplittingOff()
    normals.Update()
    surface = normals.GetOutput()
    polys = surface.GetPolys()
    numpy.savez(os.path.join(folder, "ice-cube.npz"),
                points=numpy_support.vtk_to_numpy(surface.GetPoints().GetData()),
                normals=numpy_support.vtk_to_numpy(surface.GetPointData().GetNormals()),
                triangles=numpy_support.vtk_to_numpy(polys.GetConnectivityArray()).reshape(-1, 3))


def write_ply(path, points, triangles, normals=None):
    """A binary PLY Mitsuba reads: points, optional point normals, triangles."""
    columns = [points] if normals is None else [points, normals]
    header = "ply\nformat binary_little_endian 1.0\nelement vertex %d\n" % len(points)
    header += "property float x\nproperty float y\nproperty float z\n"
    if normals is not None:
        header += "property float nx\nproperty float ny\nproperty float nz\n"
    header += "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % len(
        triangles)
    faces = numpy.zeros(len(triangles), dtype=[("n", "u1"), ("v", "<i4", 3)])
    faces["n"] = 3
    faces["v"] = triangles
    with open(path, "wb") as ply:
        ply.write(header.encode("ascii"))
        ply.write(numpy.hstack(columns).astype("<f4").tobytes())
        ply.write(faces.tobytes())


def crack_mesh(centre, normal, radius, thickness, rng):
    """A thin slab of air: a flat polygon with an irregular outline, `thickness` thick."""
    normal = numpy.asarray(normal, float) / numpy.linalg.norm(normal)
    u = numpy.cross(normal, (0.3, 1.0, 0.2))
    u /= numpy.linalg.norm(u)
    v = numpy.cross(normal, u)
    count = 48
    angles = numpy.linspace(0.0, 2.0 * math.pi, count, endpoint=False)
    # Two octaves of random harmonics: a jagged, uneven outline.
    wobble = numpy.ones(count)
    for k, amplitude in ((2, 0.25), (3, 0.15), (5, 0.08), (9, 0.05), (17, 0.03)):
        wobble += amplitude * numpy.cos(k * angles + rng.uniform(0.0, 2.0 * math.pi))
    ring = radius * wobble[:, None] * (numpy.cos(angles)[:, None] * u +
                                       numpy.sin(angles)[:, None] * v)
    centre = numpy.asarray(centre, float)
    top = centre + ring + 0.5 * thickness * normal
    bottom = centre + ring - 0.5 * thickness * normal
    points = numpy.vstack([top, bottom, centre + 0.5 * thickness * normal,
                           centre - 0.5 * thickness * normal])
    triangles = []
    for i in range(count):
        j = (i + 1) % count
        triangles += [(2 * count, i, j), (2 * count + 1, count + j, count + i),
                      (i, count + i, count + j), (i, count + j, j)]
    return points, numpy.array(triangles)


def bubbles(rng, cracks):
    """(centre, radius) of the core's bubbles and the vertical streams'."""
    found = []

    def free(centre, radius):
        # Inside the cube's core (|coordinate| < 0.8) and clear of the cracks' slabs.
        if numpy.abs(centre).max() + radius > 0.8:
            return False
        for crack_centre, normal, crack_radius in cracks:
            offset = centre - crack_centre
            near = numpy.linalg.norm(offset) < 1.6 * crack_radius
            if near and abs(offset @ normal) < radius + 0.01:
                return False
        return all(numpy.linalg.norm(centre - c) > radius + r + 0.004 for c, r in found)

    # The cloudy core: thickest at the centre, a rounded-cube profile fading outwards.
    while len(found) < 420:
        centre = rng.normal(0.0, 0.28, 3) * (1.0, 1.15, 1.0)
        radius = 0.006 * (1.0 - rng.uniform()) ** -0.45  # small ones most
        radius = min(radius, 0.035)
        if free(centre, radius):
            found.append((centre, radius))
    # Vertical streams: beads of nearly equal size, a little apart.
    for _ in range(4):
        x, z = rng.uniform(-0.45, 0.45, 2)
        y = rng.uniform(-0.7, -0.3)
        size = rng.uniform(0.008, 0.014)
        while y < rng.uniform(0.3, 0.65):
            centre = numpy.array((x + rng.normal(0.0, 0.004), y, z + rng.normal(0.0, 0.004)))
            if free(centre, size):
                found.append((centre, size))
            y += rng.uniform(2.6, 4.0) * size
    return found


def tone_map(linear):
    """ice-render's `filmic` (VTK's vtkToneMappingPass GenericFilmic with its default curve,
    without ACES, exposure 1) of linear values as the ice's framebuffer holds them."""
    a, d, mid_in, mid_out, hdr_max = 1.6773, 0.9714, 0.18, 0.18, 11.0785
    b = -((mid_in ** (-a * d)) * (-(mid_in ** a) + (mid_out * (
        (mid_in ** (a * d)) * mid_out * hdr_max ** a - mid_in ** a * hdr_max ** (a * d))) / (
        (mid_in ** (a * d)) * mid_out - mid_out * hdr_max ** (a * d)))) / mid_out
    c = max(((mid_in ** (a * d)) * mid_out * hdr_max ** a - mid_in ** a * hdr_max ** (a * d)) /
            ((mid_in ** (a * d)) * mid_out - mid_out * hdr_max ** (a * d)), 0.0)
    x = numpy.maximum(linear, 0.0)
    toned = numpy.clip(x ** a / (x ** (a * d) * b + c), 0.0, 1.0)
    return toned ** (1.0 / 2.2)


def ground_albedo(panorama):
    """The ground's diffuse reflectance that makes the panorama's light give the colour ice-render
    shows its ground in (IceGround: the mean of the cube map's -Y face texels, linear light):
    pi times that radiance over the irradiance the sky above gives a level surface."""
    rows, columns = panorama.shape[:2]
    polar = math.pi * (numpy.arange(rows) + 0.5) / rows
    azimuth = 2.0 * math.pi * (numpy.arange(columns) + 0.5) / columns
    y = numpy.cos(polar)[:, None] * numpy.ones((1, columns))
    sine = numpy.sin(polar)[:, None]
    horizontal = numpy.maximum(numpy.abs(sine * numpy.sin(azimuth)[None, :]),
                               numpy.abs(sine * numpy.cos(azimuth)[None, :]))
    solid_angle = sine * (2.0 * math.pi / columns) * (math.pi / rows)
    up = numpy.maximum(y, 0.0) * solid_angle
    irradiance = (panorama * up[..., None]).sum(axis=(0, 1))
    # The -Y face's texels: directions where -y is the largest component, a texel's solid angle
    # proportional to |y|^3, so each direction weighs 1 / |y|^3 in their plain mean.
    face = (-y >= horizontal) & (y < 0.0)
    weight = numpy.where(face, solid_angle / numpy.maximum(numpy.abs(y), 1.0e-6) ** 3, 0.0)
    radiance = (panorama * weight[..., None]).sum(axis=(0, 1)) / weight.sum()
    return numpy.clip(math.pi * radiance / numpy.maximum(irradiance, 1.0e-9), 0.0, 1.0).tolist()


def melt_pool(points, texels):
    """IceGround's melt water on the ground's texture (texels across 2 GROUND_HALF_SIZE): the
    footprint, the ice's base as a square, blurred (a product of erf steps), wet above a level."""
    bottom = points[:, 1].min()
    extent = max(numpy.ptp(points[:, 0]), numpy.ptp(points[:, 2]))
    foot = points[points[:, 1] < bottom + 0.05 * numpy.ptp(points[:, 1])]
    half = 0.5 * (numpy.ptp(foot[:, 0]) + numpy.ptp(foot[:, 2])) / 2.0
    sigma = POOL[0] * extent
    x = ((numpy.arange(texels) + 0.5) / texels - 0.5) * 2.0 * GROUND_HALF_SIZE
    erf = numpy.vectorize(math.erf)
    step = 0.5 * (erf((half - x) / (sigma * math.sqrt(2.0))) +
                  erf((half + x) / (sigma * math.sqrt(2.0))))
    pool = step[None, :] * step[:, None]
    return (numpy.clip((pool - POOL[1]) / POOL[2], 0.0, 1.0) *
            numpy.minimum(1.0, 20.0 * pool)).astype(numpy.float32)


def render(folder, spp, seed):
    import mitsuba

    mitsuba.set_variant("scalar_rgb")  # llvm_ad_rgb needs an LLVM that Debian 12's crashes
    rng = numpy.random.default_rng(seed)
    mesh = numpy.load(os.path.join(folder, "ice-cube.npz"))
    bottom = float(mesh["points"][:, 1].min())
    # The base in water: the triangles whose centre lies below the middle of the wet band's fade,
    # as one mesh whose outside is water.
    height = float(mesh["points"][:, 1].max()) - bottom
    centres = mesh["points"][mesh["triangles"]][:, :, 1].mean(axis=1)
    wet = centres < bottom + 0.5 * (WET_BAND[0] + WET_BAND[1]) * height
    write_ply(os.path.join(folder, "ice-cube.ply"), mesh["points"], mesh["triangles"][~wet],
              mesh["normals"])
    write_ply(os.path.join(folder, "ice-base.ply"), mesh["points"], mesh["triangles"][wet],
              mesh["normals"])

    # VTK Ice reads a panorama with u = 1/2 + atan2(x, -z) / 2 pi, Mitsuba with atan2(x, -z) /
    # 2 pi: half a turn apart.
    panorama = numpy.maximum(numpy.array(mitsuba.Bitmap(PANORAMA))[..., :3], 0.0)
    panorama = numpy.roll(panorama, panorama.shape[1] // 2, axis=1)
    sigma = [-math.log(c) / ATTENUATION[1] for c in ATTENUATION[0]]
    scene = {
        "type": "scene",
        "integrator": {"type": "volpath", "max_depth": 96, "rr_depth": 24},
        "sensor": {
            "type": "perspective", "fov": VIEW_ANGLE, "fov_axis": "y",
            "to_world": mitsuba.ScalarTransform4f().look_at(
                origin=list(CAMERA[0]), target=list(CAMERA[1]), up=[0, 1, 0]),
            "film": {"type": "hdrfilm", "width": WIDTH, "height": HEIGHT,
                     "rfilter": {"type": "gaussian"}},
            "sampler": {"type": "independent", "sample_count": spp, "seed": seed},
        },
        "environment": {"type": "envmap",
                        "bitmap": mitsuba.Bitmap(panorama.astype(numpy.float32))},
        "ice_medium": {"type": "homogeneous", "albedo": 0.0,
                       "sigma_t": {"type": "rgb", "value": sigma}},
        "ice": {"type": "ply", "filename": os.path.join(folder, "ice-cube.ply"),
                "bsdf": {"type": "dielectric", "int_ior": IOR, "ext_ior": 1.0},
                "interior": {"type": "ref", "id": "ice_medium"}},
        "ice_base": {"type": "ply", "filename": os.path.join(folder, "ice-base.ply"),
                     "bsdf": {"type": "dielectric", "int_ior": IOR, "ext_ior": WATER_IOR},
                     "interior": {"type": "ref", "id": "ice_medium"}},
    }
    # The ground: of the colour the panorama shows its own ground in (ground_albedo), lit by the
    # panorama, fading into it from 0.35 to 0.95 of its half size
    # as IceGround's does (smoothstep), slightly below the ice's foot; where the melt water lies,
    # the same stone under a film of water (a dielectric coat of index 1.33 on it).
    texels = 512
    x = ((numpy.arange(texels) + 0.5) / texels - 0.5) * 2.0
    r = numpy.hypot(x[None, :], x[:, None])
    t = numpy.clip((r - 0.35) / 0.6, 0.0, 1.0)
    fade = (1.0 - t * t * (3.0 - 2.0 * t)).astype(numpy.float32)
    albedo = ground_albedo(panorama)
    scene["ground"] = {
        "type": "rectangle",
        "to_world": mitsuba.ScalarTransform4f().translate([0.0, bottom - 1.0e-3, 0.0]) @
        mitsuba.ScalarTransform4f().rotate([1, 0, 0], -90.0) @
        mitsuba.ScalarTransform4f().scale([GROUND_HALF_SIZE, GROUND_HALF_SIZE, 1.0]),
        "bsdf": {"type": "mask",
                 "opacity": {"type": "bitmap", "bitmap": mitsuba.Bitmap(fade[..., None]),
                             "raw": True},
                 "bsdf": {"type": "blendbsdf",
                          "weight": {"type": "bitmap", "raw": True, "bitmap": mitsuba.Bitmap(
                              melt_pool(mesh["points"], 2048)[..., None])},
                          "bsdf_0": {"type": "diffuse", "reflectance": {"type": "rgb",
                                                                        "value": albedo}},
                          "bsdf_1": {"type": "plastic", "int_ior": WATER_IOR, "nonlinear": True,
                                     "diffuse_reflectance": {"type": "rgb",
                                                             "value": albedo}}}},
    }
    air = {"type": "dielectric", "int_ior": 1.0, "ext_ior": IOR}
    cracks = [(numpy.array((0.12, 0.05, -0.1)), numpy.array((0.9, 0.35, 0.25)), 0.42),
              (numpy.array((-0.2, -0.25, 0.15)), numpy.array((-0.2, 0.5, 0.85)), 0.33)]
    for i, (centre, normal, radius) in enumerate(cracks):
        normal = normal / numpy.linalg.norm(normal)
        cracks[i] = (centre, normal, radius)
        points, triangles = crack_mesh(centre, normal, radius, 0.004, rng)
        path = os.path.join(folder, "crack%d.ply" % i)
        write_ply(path, points, triangles)
        scene["crack%d" % i] = {"type": "ply", "filename": path, "face_normals": True,
                                "bsdf": air, "exterior": {"type": "ref", "id": "ice_medium"}}
    for i, (centre, radius) in enumerate(bubbles(rng, cracks)):
        scene["bubble%d" % i] = {"type": "sphere", "center": centre.tolist(), "radius": radius,
                                 "bsdf": air, "exterior": {"type": "ref", "id": "ice_medium"}}
    image = numpy.array(mitsuba.render(mitsuba.load_dict(scene)))[..., :3].astype(float)
    numpy.save(os.path.join(folder, "mitsuba-linear.npy"), image.astype(numpy.float32))
    write_png(tone_map(image), os.path.join(folder, "mitsuba.png"))


def write_png(srgb, path):
    from PIL import Image

    Image.fromarray((numpy.clip(srgb, 0.0, 1.0) * 255.0 + 0.5).astype(numpy.uint8)).save(path)


def compare(folder, picture):
    import flip_evaluator
    from PIL import Image

    reference = numpy.asarray(Image.open(os.path.join(folder, "mitsuba.png")).convert("RGB"))
    test = numpy.asarray(Image.open(picture).convert("RGB"))
    if test.shape != reference.shape:
        sys.exit("%s is %dx%d, the target %dx%d" % (picture, test.shape[1], test.shape[0],
                                                     reference.shape[1], reference.shape[0]))
    error_map, mean, _ = flip_evaluator.evaluate(reference / 255.0, test / 255.0, "LDR")
    side = numpy.concatenate([reference / 255.0, test / 255.0, error_map], axis=1)
    write_png(side, os.path.join(folder, "natural-ice-cube.png"))
    print("FLIP mean %.3f" % mean)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("step", choices=["mesh", "render", "compare"])
    parser.add_argument("folder")
    parser.add_argument("picture", nargs="?", help="compare: ice-render's picture")
    parser.add_argument("--spp", type=int, default=256)
    parser.add_argument("--seed", type=int, default=7)
    arguments = parser.parse_args()
    os.makedirs(arguments.folder, exist_ok=True)
    if arguments.step == "mesh":
        make_mesh(arguments.folder)
    elif arguments.step == "render":
        render(arguments.folder, arguments.spp, arguments.seed)
    else:
        if not arguments.picture:
            parser.error("compare needs ice-render's picture")
        compare(arguments.folder, arguments.picture)


if __name__ == "__main__":
    main()
