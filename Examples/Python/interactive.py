"""Interactive voxel GI on the Cornell box. Keys:
    g  GI on/off            o  ambient occlusion on/off     s  specular cone on/off
    v  next debug view      b  bounces 0..4                 q  quit

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/interactive.py
        opens a window;
    ... interactive.py --snapshot out.png
        renders once off screen and writes the image

(from the repository root after the set-up; VTK's Python is Debian's /usr/bin/python3,
which may not be the python3 first on PATH)
"""
import sys

from vtkmodules.vtkInteractionStyle import vtkInteractorStyleTrackballCamera
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkRenderer, vtkRenderWindow,
                                         vtkRenderWindowInteractor, vtkWindowToImageFilter)

from voxelgi import vtkVoxelGIPass, vtkVoxelGIScenes

VIEWS = ["None", "VoxelAlbedo", "VoxelNormal", "VoxelEmission", "VoxelRadiance", "Direct",
         "Indirect", "AmbientOcclusion"]


def on_key(interactor, gi, window):
    key = interactor.GetKeySym()
    if key == "g":
        gi.SetEnabled(not gi.GetEnabled())
    elif key == "o":
        gi.SetAmbientOcclusionStrength(0.0 if gi.GetAmbientOcclusionStrength() > 0 else 1.0)
    elif key == "s":
        gi.SetSpecularCone(not gi.GetSpecularCone())
    elif key == "v":
        gi.SetDebugView((gi.GetDebugView() + 1) % len(VIEWS))
    elif key == "b":
        gi.SetBounces((gi.GetBounces() + 1) % 5)  # back to the default, 4
    else:
        return
    print("GI %s, AO %.1f, specular %s, bounces %d, view %s" % (
        "on" if gi.GetEnabled() else "off", gi.GetAmbientOcclusionStrength(),
        "on" if gi.GetSpecularCone() else "off", gi.GetBounces(), VIEWS[gi.GetDebugView()]))
    window.Render()


def main(argv):
    renderer = vtkRenderer()
    vtkVoxelGIScenes.AddCornellBox(renderer)
    window = vtkRenderWindow()
    window.SetSize(600, 600)
    window.AddRenderer(renderer)
    gi = vtkVoxelGIPass()
    gi.SetVoxelResolution(64)
    renderer.SetPass(gi)

    if len(argv) == 2 and argv[0] == "--snapshot":
        window.SetOffScreenRendering(True)
        window.SetSize(300, 300)
        gi.SetDebugViewToIndirect()
        window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        grab.ReadFrontBufferOff()
        writer = vtkPNGWriter()
        writer.SetInputConnection(grab.GetOutputPort())
        writer.SetFileName(argv[1])
        writer.Write()
        return

    interactor = vtkRenderWindowInteractor()
    interactor.SetRenderWindow(window)
    interactor.SetInteractorStyle(vtkInteractorStyleTrackballCamera())
    interactor.AddObserver("KeyPressEvent", lambda obj, event: on_key(obj, gi, window))
    print(__doc__)
    window.Render()
    interactor.Start()


if __name__ == "__main__":
    main(sys.argv[1:])
