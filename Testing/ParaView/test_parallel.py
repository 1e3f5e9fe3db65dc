"""ParaView in parallel: every rank holds a piece of a scene shown in the "Render View (Voxel
GI)". Checks that GI ran on every rank, that every rank's merged voxel albedo volume is
identical and equals the one-rank run's, and, given a reference image (the same script with one
rank), that the composited image equals it within a small tolerance. Prints the numbers and the
reductions' traffic of a voxelizing frame.

Two scenes: `pieces`, a distributed isosurface of the Wavelet source (each rank holds a piece),
a floor and a block held by rank 0 only; `disjoint`, two floor tiles with a sphere each, tile i
held by rank i: the ranks' bounds are disjoint, and ranks beyond the second hold no data.

    mpiexec -n N pvbatch --symmetric test_parallel.py PLUGIN OUTPUT_PNG [REFERENCE_PNG]
        [--scene=pieces|disjoint]
        [--resolution=R]   (voxels per axis, default 64; for measuring the traffic)
        [--expect-off]     (a rank cannot run GI: none does, and the image is ParaView's own)
    pvpython test_parallel.py --connect=HOST:PORT PLUGIN OUTPUT_PNG REFERENCE_PNG [--scene=...]
        (a client of `mpiexec -n N pvserver`: the server's ranks render, the client checks)

Each rank reads its merged voxel albedo volume through the pass's GetVoxelVolume and hashes its
bytes (FNV-1a, as the testing library's VoxelAlbedoChecksum). The one-rank run writes the
checksum next to its image (OUTPUT-checksum.txt); the other runs compare theirs with it.
"""
import os
import re
import sys

import numpy

from paraview.simple import (Box, Connect, Contour, CreateView, Delete, GetSettingsProxy,
                             LoadPlugin, Plane, ProgrammableSource, Render, SaveScreenshot,
                             Show, Wavelet)
from paraview import servermanager
from paraview.modules.vtkRemotingClientServerStream import vtkClientServerStream
from paraview.modules.vtkRemotingCore import vtkPVSession
from paraview.vtk.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkIOXML import vtkXMLImageDataReader
from vtkmodules.vtkParallelCore import vtkCommunicator, vtkMultiProcessController

options = dict(a[2:].split("=", 1) for a in sys.argv[1:] if a.startswith("--") and "=" in a)
expect_off = "--expect-off" in sys.argv
arguments = [a for a in sys.argv[1:] if not a.startswith("--")]
resolution = int(options.get("resolution", 64))
scene = options.get("scene", "pieces")
plugin, image_name = os.path.abspath(arguments[0]), os.path.abspath(arguments[1])
reference = os.path.abspath(arguments[2]) if len(arguments) > 2 else None
client = "connect" in options
if client:
    host, port = options["connect"].rsplit(":", 1)
    Connect(host, int(port))
    LoadPlugin(plugin, remote=True, ns=globals())
    # Render on the server's ranks, whatever the data's size (by default ParaView ships small
    # geometry to the client and renders it there).
    GetSettingsProxy("RenderViewSettings").RemoteRenderThreshold = 0.0
LoadPlugin(plugin, remote=False, ns=globals())
# In a client, the controller is the client's own (one process): the server's ranks are
# checked through their first rank.
controller = vtkMultiProcessController.GetGlobalController()
rank = controller.GetLocalProcessId() if controller else 0
ranks = controller.GetNumberOfProcesses() if controller else 1
processes = servermanager.ActiveConnection.GetNumberOfDataPartitions() if client else ranks

view = CreateView("VoxelGIRenderView")
view.ViewSize = [300, 300]
view.OrientationAxesVisibility = 0
view.VoxelResolution = resolution
# Ranks light the voxels with voxel shadows (their shadow maps would see one piece each): the
# one-rank reference does the same.
view.LightOcclusion = "VoxelShadows"
# IceT composites single-sampled images: the one-rank reference is drawn so too.
view.GetRenderWindow().SetMultiSamples(0)

# Piece i of the `disjoint` scene holds tile i and its sphere (every tile in a one-rank run).
# pvbatch runs it in this script's namespace after importing numpy_interface.algorithms there,
# whose min, max, sum and abs replace Python's: the checks below use numpy's own.
TILES = """
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as pipeline
from vtkmodules.vtkFiltersCore import vtkAppendPolyData
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
info = self.GetOutputInformation(0)
piece = info.Get(pipeline.UPDATE_PIECE_NUMBER())
pieces = info.Get(pipeline.UPDATE_NUMBER_OF_PIECES())
append = vtkAppendPolyData()
for tile, x in enumerate((-10.0, 10.0)):
    if tile % pieces != piece:
        continue
    floor = vtkPlaneSource()
    floor.SetOrigin(x - 9, -11, -12)
    floor.SetPoint1(x + 9, -11, -12)
    floor.SetPoint2(x - 9, -11, 12)
    sphere = vtkSphereSource()
    sphere.SetCenter(x, -5, 0)
    sphere.SetRadius(6)
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(24)
    append.AddInputConnection(floor.GetOutputPort())
    append.AddInputConnection(sphere.GetOutputPort())
if append.GetNumberOfInputConnections(0):
    append.Update()
    self.GetPolyDataOutput().ShallowCopy(append.GetOutput())
"""
TILES_INFORMATION = """
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm
self.GetOutputInformation(0).Set(vtkAlgorithm.CAN_HANDLE_PIECE_REQUEST(), 1)
"""
if scene == "pieces":
    contour = Contour(Input=Wavelet(), ContourBy=["POINTS", "RTData"], Isosurfaces=[190.0])
    display = Show(contour, view)
    display.ColorArrayName = ["POINTS", ""]
    display.DiffuseColor = [0.9, 0.5, 0.2]
    Show(Plane(Origin=[-16, -11, -16], Point1=[16, -11, -16], Point2=[-16, -11, 16]), view)
    block = Show(Box(XLength=6, YLength=14, ZLength=6, Center=[-13, -4, 4]), view)
    block.DiffuseColor = [0.2, 0.4, 0.9]
    view.CameraPosition = [30, 20, 45]
    view.CameraFocalPoint = [0, -3, 0]
else:
    tiles = ProgrammableSource(OutputDataSetType="vtkPolyData", Script=TILES,
                               ScriptRequestInformation=TILES_INFORMATION)
    display = Show(tiles, view)
    display.ColorArrayName = ["POINTS", ""]
    display.DiffuseColor = [0.9, 0.6, 0.3]
    view.CameraPosition = [8, 22, 42]
    view.CameraFocalPoint = [0, -6, 0]
view.CameraViewUp = [0, 1, 0]
Render(view)
Render(view)

failures = []


def pass_value(name):
    if client:
        return server_value(name)
    view.SMProxy.UpdatePropertyInformation()
    return view.SMProxy.GetProperty(name).GetElement(0)


def execute(commands):
    """Runs client-server stream commands where the pass lives (this rank; in a client, the
    first server rank) and returns the last one's reply, e.g. "true" for "Reply bool(true)"."""
    session = servermanager.ActiveConnection.Session
    stream = vtkClientServerStream()
    stream.StreamFromString("\n".join(commands))
    session.ExecuteStream(vtkPVSession.DATA_SERVER_ROOT, stream, False)
    reply = session.GetLastResult(vtkPVSession.DATA_SERVER_ROOT).StreamToString()
    match = re.search(r"\(([^)]*)\)", reply)
    return match.group(1) if match else None


# The pass (the view's sub-proxy that holds the exposed GIActive), as a client-server stream
# names it.
GI_PASS = "stream_value(Invoke id_value(1) GetVTKObject uint32_value(%d))" % (
    view.SMProxy.GetProperty("GIActive").GetParent().GetGlobalID())


def server_value(name):
    """The pass's getter `name` on the first server rank. (A client pulls information
    properties from its own objects, which do not render here.)"""
    value = execute(["Invoke %s Get%s" % (GI_PASS, name)])
    return float({"true": 1, "false": 0}.get(value, value))


def albedo_checksum():
    """31 bits of the FNV-1a hash of the bytes of the merged voxel albedo volume where the pass
    lives (0 when there is none), as the testing library's VoxelAlbedoChecksum computes it. The
    pass's GetVoxelVolume fills an image there, which a writer there saves for this process to
    read (a client and its server share the machine in these tests)."""
    volume, writer = 9001, 9002  # stream ids, not taken by the session
    path = image_name.replace(".png", "-albedo-%d.vti" % rank)
    # A bare word: ParaView 5.11's stream parser drops typed string_value(...) arguments.
    assert not re.search(r"[\s()]", path), "the stream cannot name %r" % path
    if os.path.exists(path):
        os.remove(path)
    read_back = execute([
        "New vtkImageData id_value(%d)" % volume,
        "Invoke %s GetVoxelVolume int32_value(0) id_value(%d)" % (GI_PASS, volume)]) == "true"
    if read_back:
        execute(["New vtkXMLImageDataWriter id_value(%d)" % writer,
                 "Invoke id_value(%d) SetInputData id_value(%d)" % (writer, volume),
                 "Invoke id_value(%d) SetFileName %s" % (writer, path),
                 "Invoke id_value(%d) Write" % writer,
                 "Delete id_value(%d)" % writer])
    execute(["Delete id_value(%d)" % volume])
    if not read_back or not os.path.exists(path):
        return 0
    reader = vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    os.remove(path)
    voxels = reader.GetOutput().GetPointData().GetScalars()
    if voxels is None:
        return 0
    data = vtk_to_numpy(voxels).tobytes()
    value = 2166136261
    for byte in data:
        value = ((value ^ byte) * 16777619) & 0xffffffff
    return value & 0x7fffffff


def reduce(values, operation):
    if ranks == 1:
        return list(values)
    send, received = vtkDoubleArray(), vtkDoubleArray()
    for v in values:
        send.InsertNextValue(v)
    controller.AllReduce(send, received, operation)
    return [received.GetValue(i) for i in range(received.GetNumberOfTuples())]


def read(name):
    reader = vtkPNGReader()
    reader.SetFileName(name)
    reader.Update()
    return reader.GetOutput().GetPointData().GetScalars()


def differences(a, b):
    """Per pixel, the largest difference of the colour channels, in levels."""
    a, b = vtk_to_numpy(a)[:, :3].astype(numpy.int32), vtk_to_numpy(b)[:, :3].astype(numpy.int32)
    return numpy.abs(a - b).max(axis=1)


def screenshots():
    """The view's image, then ParaView's own (GI off) next to it; returns the latter's name."""
    SaveScreenshot(image_name, view, ImageResolution=[300, 300])
    view.EnableVoxelGI = 0
    Render(view)
    plain_output = image_name.replace(".png", "-plain.png")
    SaveScreenshot(plain_output, view, ImageResolution=[300, 300])
    return plain_output


def check_off():
    """A rank cannot run GI: none runs it, and the image is ParaView's own."""
    if reduce([float(pass_value("GIActive"))], vtkCommunicator.MAX_OP)[0] > 0.0:
        failures.append("GI ran on a rank although another cannot run it")
    plain_output = screenshots()
    if rank == 0:
        largest = differences(read(image_name), read(plain_output)).max()
        print("GI off on every rank; largest difference to ParaView's own image: %d levels"
              % largest)
        if largest > 0:
            failures.append("the image is not ParaView's own")


def check_merged():
    """Every rank runs GI on the same merged voxels; the image equals one rank's. (The ranks
    agree on running GI, so a client's view of the first rank speaks for all.)"""
    if processes < 2 and reference:
        failures.append("one rank renders: nothing is distributed")
    if reduce([float(pass_value("GIActive"))], vtkCommunicator.MIN_OP)[0] < 1.0:
        failures.append("GI did not run on every rank")
    checksum = float(albedo_checksum())
    if checksum == 0.0:
        failures.append("rank %d has no voxel albedo" % rank)
    if reduce([checksum], vtkCommunicator.MIN_OP) != reduce([checksum], vtkCommunicator.MAX_OP):
        failures.append("the ranks' merged voxel albedo volumes differ")
    if rank == 0 and not reference:
        with open(image_name.replace(".png", "-checksum.txt"), "w") as f:
            f.write("%d\n" % checksum)
    elif reference:
        with open(reference.replace(".png", "-checksum.txt")) as f:
            expected = int(f.read())
        # Exact integer sums: the merged grid equals the one-rank grid bit for bit.
        if checksum != expected:
            failures.append("rank %d's merged voxel albedo (checksum %d) differs from one rank's "
                            "(%d)" % (rank, checksum, expected))

    # The traffic of a voxelizing frame.
    view.InvokeCommand("Invalidate")
    Render(view)
    traffic = reduce([pass_value("RankTrafficBytes"), pass_value("RankTrafficMilliseconds")],
                     vtkCommunicator.MAX_OP)
    # ParaView's own image of the scene: where it differs between rank counts (IceT's
    # compositing of silhouettes), GI's cannot be compared.
    plain_output = screenshots()
    if rank == 0:
        print("%s: %d %s, %d^3: a voxelizing frame reduced %.1f MiB per rank in %.1f ms; "
              "voxel albedo checksum %d" % (scene, processes, "server ranks" if client else
                                            "rank(s)", resolution, traffic[0] / 2.0**20,
                                            traffic[1], checksum))
        if reference:
            gi_diff = differences(read(image_name), read(reference))
            plain_diff = differences(read(plain_output), read(reference.replace(".png", "-plain.png")))
            kept = gi_diff[plain_diff <= 8]
            over = numpy.count_nonzero(kept > 8)
            mean = kept.mean()
            print("against one rank, where ParaView's own images agree (%.1f %% of the pixels): "
                  "mean difference %.3f levels, largest %d, %.3f %% over 8 levels"
                  % (100.0 * kept.size / gi_diff.size, mean, kept.max(), 100.0 * over / kept.size))
            # Each rank's G-buffer holds its own piece: next to the silhouette of another rank's
            # piece the edge-aware filters see other neighbours than one rank's.
            if mean > 0.5 or over > 0.01 * kept.size:
                failures.append("the composited GI image differs from one rank's")


if expect_off:
    check_off()
else:
    check_merged()
if rank == 0:
    for failure in failures:
        print("FAILED:", failure)
failed = reduce([1.0 if failures else 0.0], vtkCommunicator.MAX_OP)[0]
# ParaView 5.11 crashes in sys.exit() while views are alive; a passing run ends normally (MPI
# must finalize).
Delete(view)
del view
if failed:
    sys.exit(1)
