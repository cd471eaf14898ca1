# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""A scene for distributed rendering: ice objects and ordinary data that ParaView's partition
spreads over the ranks, a dynamic cube map, cracks and air.

    mpiexec -n N pvbatch --symmetric distributed_scene.py image.png stats-prefix [chunks|translucent]

Every rank runs the script (--symmetric) and writes stats-prefix-<rank>.txt: its local ice (cells,
connected objects) per ice representation and the number of objects of the whole surface. With
`chunks` > 0 the scene is the benchmark's instead: that many ice chunks over a terrain, and the
stats hold frame times and memory (Documentation/paraview.md, parallel section). With
`translucent` a translucent sphere joins the scene (ParaView then composites in visibility order).
"""
import builtins
import os
import resource
import sys
import time

from paraview.simple import (AppendDatasets, ColorBy, Contour, CreateView, ExtractSurface,
                             GetColorTransferFunction, LoadPlugin, ProgrammableSource,
                             RedistributeDataSet, Render, SaveScreenshot, Show, Slice, Sphere,
                             Wavelet, WarpByScalar)
from vtkmodules.vtkFiltersCore import vtkPolyDataConnectivityFilter
from vtkmodules.vtkParallelCore import vtkMultiProcessController
from vtkmodules.vtkCommonSystem import vtkTimerLog

LoadPlugin(os.environ["VTKICE_PARAVIEW_PLUGIN"], remote=False)
controller = vtkMultiProcessController.GetGlobalController()
vtkTimerLog.SetMaxEntries(100000)
rank = controller.GetLocalProcessId()
image_path, stats_prefix = sys.argv[1], sys.argv[2]
translucent = len(sys.argv) > 3 and sys.argv[3] == "translucent"
chunks = int(sys.argv[3]) if len(sys.argv) > 3 and not translucent else 0

view = CreateView("IceView")
view.ViewSize = [480, 360]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.BackgroundColorMode = "Gradient"
view.Background = [0.55, 0.65, 0.8]
view.Background2 = [0.1, 0.15, 0.3]
view.DynamicEnvironment = 1
view.CubeMapFaceSize = 128


def ice_display(source, cracks, air):
    display = Show(source, view)
    display.Representation = "Ice"
    display.NumberOfCracks = cracks
    display.NumberOfAirPlanes = air
    display.ColorArrayName = ["POINTS", ""]
    return display


wavelet = Wavelet(WholeExtent=[-20, 20, -20, 20, -20, 20])
if chunks == 0:
    # Four spheres in one representation, each cut by the partition (pieces by theta), around
    # an iso-surface of the wavelet (split by extent); no ice in front of other ice.
    spheres = [Sphere(Center=c, Radius=r, ThetaResolution=48, PhiResolution=32)
               for c, r in (([-15, 0, 4], 4.5), ([13, 2, -8], 4), ([12, -3, 12], 3.5),
                            ([-8, 6, -16], 3.5))]
    ice = {"spheres": ice_display(AppendDatasets(Input=spheres), 3, 8),
           "iso": ice_display(Contour(Input=wavelet, ContourBy=["POINTS", "RTData"],
                                      Isosurfaces=[240.0]), 2, 6)}
    if translucent:
        glass = Show(Sphere(Center=[0, 2, 14], Radius=5, ThetaResolution=64, PhiResolution=64),
                     view)
        glass.Opacity = 0.4
        glass.DiffuseColor = [0.2, 0.9, 0.3]
    floor = Slice(Input=wavelet)
    floor.SliceType.Origin = [0, -12, 0]
    floor.SliceType.Normal = [0, 1, 0]
    floor_display = Show(floor, view)
    # Coloured by RTData with the slice's range (as one process rescales to it) set here, not by
    # ColorBy: ParaView 5.13 and 6.1 rescale there from each rank's own piece, and ranks with an
    # empty piece (4 ranks: "Could not determine array range") skip a collective the others
    # enter (6.1: "MPI_ERR_TRUNCATE", or a hang), with the plugin or without.
    lut = GetColorTransferFunction("RTData")
    lut.AutomaticRescaleRangeMode = "Never"
    lut.RescaleTransferFunction(77.9343032836914, 235.12091064453125)
    floor_display.LookupTable = lut
    floor_display.ColorArrayName = ["POINTS", "RTData"]
    try:
        lut.ApplyPreset("Inferno (matplotlib)", True)
    except RuntimeError:  # ParaView 6.1 renamed the preset
        lut.ApplyPreset("Inferno", True)
    position, focal = [38, 30, 62], [0, -1, 0]
else:
    # The benchmark: `chunks` lumpy ice chunks (about 2000 triangles each) on a grid above a
    # terrain, made on rank 0 and spread by ParaView's own RedistributeDataSet (which cuts them).
    source = ProgrammableSource(OutputDataSetType="vtkPolyData")
    source.Script = """
import numpy, math
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkFiltersCore import vtkAppendPolyData
from vtkmodules.vtkParallelCore import vtkMultiProcessController
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.util.numpy_support import vtk_to_numpy
out = self.GetOutput()
if vtkMultiProcessController.GetGlobalController().GetLocalProcessId() == 0:
    rng = numpy.random.default_rng(7)
    append = vtkAppendPolyData()
    side = int(math.ceil(math.sqrt(%d)))
    for i in range(%d):
        s = vtkSphereSource()
        s.SetThetaResolution(40); s.SetPhiResolution(26)
        s.SetRadius(0.35 + 0.1 * rng.random())
        s.SetCenter(i %% side - side / 2.0, 0.6 + 0.3 * rng.random(), i // side - side / 2.0)
        s.Update()
        p = vtkPolyData()
        p.DeepCopy(s.GetOutput())
        p.GetPointData().SetNormals(None)
        xyz = vtk_to_numpy(p.GetPoints().GetData())
        d = xyz - numpy.array(s.GetCenter())
        xyz[:] = s.GetCenter() + d * (1.0 + 0.3 * numpy.sin(9 * d[:, :1] + 13 * d[:, 1:2] + 7 * d[:, 2:] + i))
        append.AddInputData(p)
    append.Update()
    out.ShallowCopy(append.GetOutput())
""" % (chunks, chunks)
    spread = ExtractSurface(Input=RedistributeDataSet(Input=source))
    ice = {"chunks": ice_display(spread, 2, 6)}
    side = int(chunks ** 0.5) + 2
    terrain = WarpByScalar(Input=Slice(Input=Wavelet(
        WholeExtent=[-side * 4, side * 4, -1, 1, -side * 4, side * 4],
        Center=[0, 0, 0])), Scalars=["POINTS", "RTData"], ScaleFactor=0.004)
    terrain.Input.SliceType.Normal = [0, 1, 0]
    terrain_display = Show(terrain, view)
    terrain_display.Scale = [0.25, 1, 0.25]
    ColorBy(terrain_display, ("POINTS", "RTData"))
    position, focal = [side * 0.9, side * 0.7, side * 1.1], [0, 0, 0]

view.CameraPosition = position
view.CameraFocalPoint = focal
view.CameraViewUp = [0, 1, 0]
view.CameraViewAngle = 30

start = time.time()
Render(view)
first = time.time() - start
lines = ["rank %d of %d" % (rank, controller.GetNumberOfProcesses()), "first_frame_s %.3f" % first]


def timed_frame():
    """Renders; returns the frame's seconds and, under IceT, its local rendering and compositing
    (ParaView logs them as ICET_RENDER_TIME and ICET_COMPOSITE_TIME)."""
    before = vtkTimerLog.GetNumberOfEvents()
    start = time.time()
    Render(view)
    seconds = time.time() - start
    icet = {"ICET_RENDER_TIME": 0.0, "ICET_COMPOSITE_TIME": 0.0}
    for e in range(before, vtkTimerLog.GetNumberOfEvents()):
        name = vtkTimerLog.GetEventString(e)
        if name in icet and vtkTimerLog.GetEventType(e) == 3:  # INSERTED: its time is a duration
            icet[name] += vtkTimerLog.GetEventWallTime(e)
    return seconds, icet["ICET_RENDER_TIME"], icet["ICET_COMPOSITE_TIME"]


def report(name, frames):
    # builtins: pvbatch's namespace has numpy's min (it would not compare tuples).
    seconds, local, composite = builtins.min(frames)
    lines.append("%s %.3f" % (name, seconds))
    lines.append("%s_icet_render %.3f" % (name, local))
    lines.append("%s_icet_composite %.3f" % (name, composite))


if chunks:
    # Frames with every cube-map face re-rendered and composited, then with the cube map kept.
    view.CubeMapUpdateMode = 0
    report("frame_cubemap_s", [timed_frame() for _ in range(3)])
    view.CubeMapUpdateMode = 1
    Render(view)
    frames = []
    for i in range(3):
        view.CameraPosition = [position[0] + 0.01 * (i + 1), position[1], position[2]]
        frames.append(timed_frame())
    report("frame_s", frames)
    lines.append("max_rss_mib %.1f" % (resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024))
    # Where the time went on this rank: the plugin marks its collective steps in VTK's timer log
    # (start and end events).
    totals, started = {}, {}
    for i in range(vtkTimerLog.GetNumberOfEvents()):
        name = vtkTimerLog.GetEventString(i)
        if not name.startswith("Ice:"):
            continue
        if vtkTimerLog.GetEventType(i) == 1:  # vtkTimerLogEntry::START (unwrapped)
            started[name] = vtkTimerLog.GetEventWallTime(i)
            continue
        key = name[4:].strip().replace(" ", "_")
        count, seconds = totals.get(key, (0, 0.0))
        totals[key] = (count + 1, seconds + vtkTimerLog.GetEventWallTime(i) - started[name])
    for key, (count, seconds) in sorted(totals.items()):
        lines.append("%s %d %.3f" % (key, count, seconds))
# The ice this rank holds: the mappers are ParaView's (unwrapped) vtkIceMapper, seen as VTK's.
renderer = view.GetRenderer()
props = renderer.GetViewProps()
props.InitTraversal()
ice_inputs = []
for _ in range(props.GetNumberOfItems()):
    prop = props.GetNextProp()
    mapper = prop.GetMapper() if hasattr(prop, "GetMapper") else None
    if mapper and mapper.GetClassName() == "vtkIceMapper" and prop.GetVisibility():
        ice_inputs.append(mapper.GetInput())
for number, local in enumerate(ice_inputs):
    cells = local.GetNumberOfCells() if local else 0
    objects = 0
    if cells:
        regions = vtkPolyDataConnectivityFilter()
        regions.SetInputData(local)
        regions.SetExtractionModeToAllRegions()
        regions.Update()
        objects = regions.GetNumberOfExtractedRegions()
    lines.append("ice%d local_cells %d local_objects %d" % (number, cells, objects))
with open("%s-%d.txt" % (stats_prefix, rank), "w") as stats:
    stats.write("\n".join(lines) + "\n")
SaveScreenshot(image_path, view, ImageResolution=view.ViewSize)
if not chunks:
    # The same view without the ice: where the two differ is the ice (the comparison's mask).
    for display in ice.values():
        display.Visibility = 0
    SaveScreenshot(image_path.replace(".png", "-noice.png"), view,
                   ImageResolution=view.ViewSize)
