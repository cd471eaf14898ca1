# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Remakes references.npz: each scene of scenes.py path traced by Mitsuba 3 (full light
transport: Fresnel at every interface, total internal reflection, up to 64 bounces, Beer-Lambert
in the medium), stored as BLOCK x BLOCK block means in float16.

Needs a virtual environment with PyPI's mitsuba, vtk and numpy (Documentation/optics.md):
    python make_references.py [--spp N] [--scene NAME] [--pictures DIR]
It first checks that the panorama and camera agree with scenes.py's directions (the environment
alone, within 0.5/255), then renders. --pictures also writes each full image as a PNG (sRGB)."""
import argparse
import math
import os
import sys
import tempfile

import mitsuba
import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scenes  # noqa: E402

mitsuba.set_variant("scalar_rgb")  # llvm_ad_rgb needs an LLVM that Debian 12's crashes


def panorama(width=2048):
    """The environment as Mitsuba's envmap reads it: u = atan2(x, -z) / 2 pi, v = acos(y) / pi."""
    u = (numpy.arange(width) + 0.5) / width
    v = (numpy.arange(width // 2) + 0.5) / (width // 2)
    phi = 2.0 * math.pi * u[None, :]
    theta = math.pi * v[:, None]
    d = numpy.stack([numpy.sin(phi) * numpy.sin(theta), numpy.cos(theta) + 0.0 * phi,
                     -numpy.cos(phi) * numpy.sin(theta)], axis=-1)
    return scenes.environment(d).astype(numpy.float32)


def scene_dict(camera, spp, shape=None):
    scene = {
        "type": "scene",
        "integrator": {"type": "volpath", "max_depth": 64, "rr_depth": 32},
        "sensor": {
            "type": "perspective", "fov": scenes.VIEW_ANGLE, "fov_axis": "y",
            "to_world": mitsuba.ScalarTransform4f().look_at(
                origin=list(camera), target=[0, 0, 0], up=[0, 1, 0]),
            "film": {"type": "hdrfilm", "width": scenes.SIZE, "height": scenes.SIZE,
                     "rfilter": {"type": "box"}},
            "sampler": {"type": "independent", "sample_count": spp},
        },
        "environment": {"type": "envmap", "bitmap": mitsuba.Bitmap(panorama())},
    }
    if shape:
        scene["ice"] = shape
    return scene


def ice_shape(mesh_file, material):
    roughness = material.get("roughness", 0.0)
    if roughness > 0.0:
        # glTF's roughness: GGX with alpha = roughness^2, as vtkIceProperty::SetRoughness says.
        bsdf = {"type": "roughdielectric", "distribution": "ggx", "alpha": roughness ** 2,
                "int_ior": scenes.IOR, "ext_ior": 1.0}
    else:
        bsdf = {"type": "dielectric", "int_ior": scenes.IOR, "ext_ior": 1.0}
    shape = {"type": "ply", "filename": mesh_file, "bsdf": bsdf}
    if "attenuation" in material:
        # glTF KHR_materials_volume: white light has the colour c after the distance d.
        colour, distance = material["attenuation"]
        sigma = [-math.log(c) / distance for c in colour]
        shape["interior"] = {"type": "homogeneous", "albedo": 0.0,
                             "sigma_t": {"type": "rgb", "value": sigma}}
    return shape


def write_ply(polydata, path):
    """Points, point normals and triangles as a binary PLY (vtkPLYWriter's obj_info line is
    one Mitsuba's reader refuses)."""
    from vtk.util import numpy_support

    points = numpy_support.vtk_to_numpy(polydata.GetPoints().GetData()).astype("<f4")
    normals = numpy_support.vtk_to_numpy(polydata.GetPointData().GetNormals()).astype("<f4")
    polys = polydata.GetPolys()
    if polys.IsHomogeneous() != 3:
        raise ValueError("the mesh must be triangles")
    cells = numpy_support.vtk_to_numpy(polys.GetConnectivityArray()).reshape(-1, 3)
    faces = numpy.zeros(len(cells), dtype=[("n", "u1"), ("v", "<i4", 3)])
    faces["n"] = 3
    faces["v"] = cells
    with open(path, "wb") as ply:
        ply.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\n"
                   "property float x\nproperty float y\nproperty float z\n"
                   "property float nx\nproperty float ny\nproperty float nz\n"
                   "element face %d\nproperty list uchar int vertex_indices\nend_header\n"
                   % (len(points), len(faces))).encode("ascii"))
        ply.write(numpy.hstack([points, normals]).astype("<f4").tobytes())
        ply.write(faces.tobytes())


def render(scene):
    return numpy.array(mitsuba.render(mitsuba.load_dict(scene)))[..., :3].astype(float)


def check_environment():
    camera = scenes.SCENES["cube-corner"][1]
    image = render(scene_dict(camera, 4))
    error = numpy.abs(image - scenes.environment(scenes.pixel_directions(camera))).mean()
    if error * 255.0 > 0.5:
        sys.exit("the panorama or camera disagrees with scenes.py: %.2f/255" % (error * 255.0))


def main():
    import vtk

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--spp", type=int, default=512)
    parser.add_argument("--scene", action="append", choices=sorted(scenes.SCENES))
    parser.add_argument("--pictures")
    parser.add_argument("--output", default=os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "references.npz"))
    arguments = parser.parse_args()
    if arguments.pictures:
        os.makedirs(arguments.pictures, exist_ok=True)
    check_environment()
    references = dict(numpy.load(arguments.output)) if os.path.exists(arguments.output) else {}
    with tempfile.TemporaryDirectory() as folder:
        for name in arguments.scene or sorted(scenes.SCENES):
            mesh_name, camera, material = scenes.SCENES[name]
            mesh_file = os.path.join(folder, mesh_name + ".ply")
            write_ply(scenes.mesh(mesh_name), mesh_file)
            image = render(scene_dict(camera, arguments.spp, ice_shape(mesh_file, material)))
            references[name] = scenes.block_means(image).astype(numpy.float16)
            if arguments.pictures:
                scenes.write_png(image, os.path.join(arguments.pictures, name + "-mitsuba.png"))
            print("rendered", name, flush=True)
    numpy.savez_compressed(arguments.output, **references)


if __name__ == "__main__":
    main()
