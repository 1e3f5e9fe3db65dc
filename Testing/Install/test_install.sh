#!/usr/bin/env bash
# What a user of an installed VoxelGI does, checked end to end:
#   test_install.sh SOURCE_DIR BUILD_DIR WORK_DIR
# installs BUILD_DIR into WORK_DIR/prefix; builds Examples/Cxx there as a project of its own
# against the install and runs its demo (the GI image must not be empty); builds the README's
# consumer (find_package(VoxelGI COMPONENTS Qt)) against the install and against the build
# tree and runs it with the README's C++ snippets compiled in verbatim (their pass must trace);
# imports the Python package through the install's .pth file alone.
set -euo pipefail
src=$1; build=$2; work=$3
rm -rf "$work"; mkdir -p "$work"
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" > "$work/install.log"
for file in lib/libVoxelGIQt.so lib/libVoxelGIGlewEGLShim.so bin/VoxelGIViewer \
  include/voxelgi/vtkVoxelGISettingsWidget.h lib/cmake/VoxelGI/VoxelGIConfig.cmake; do
  [ -e "$prefix/$file" ] || { echo "FAILED: not installed: $file"; exit 1; }
done

cmake -S "$src/Examples/Cxx" -B "$work/examples" -DCMAKE_PREFIX_PATH="$prefix" -Wno-dev \
  > "$work/examples.log"
cmake --build "$work/examples" --target VoxelGIDemo -j 2 >> "$work/examples.log"
"$work/examples/VoxelGIDemo" "$work/demo" | grep -v -E "^\s*$"
/usr/bin/python3 - "$work/demo.png" "$work/demo-plain.png" <<'PY'
import sys
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy
def pixels(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3] / 255.0
gi, plain = pixels(sys.argv[1]), pixels(sys.argv[2])
print(f"demo image mean {gi.mean():.3f}, plain VTK {plain.mean():.3f}")
# The Cornell box fills the image; GI adds light to VTK's direct light.
if not (gi.mean() > 0.1 and gi.mean() > plain.mean()):
    sys.exit("FAILED: the installed demo's GI image is empty or darker than VTK's")
PY

# The README's C++ blocks as they stand, in the scope whose names they use: the "Use" block
# and the settings panel's.
cp -r "$src/Testing/Install/consumer" "$work/consumer-src"
/usr/bin/python3 - "$src/README.md" "$work/consumer-src/readme_snippets.h" <<'PY'
import re, sys
blocks = re.findall(r"```cpp\n(.*?)```", open(sys.argv[1]).read(), re.S)
if len(blocks) != 2:
    sys.exit("FAILED: README.md has %d C++ blocks, this test knows 2" % len(blocks))
lines = "".join(blocks).splitlines()
includes = [l for l in lines if l.startswith("#include")]
body = [l for l in lines if not l.startswith("#include")]
with open(sys.argv[2], "w") as out:
    out.write("// Written by test_install.sh from README.md's C++ blocks.\n")
    out.write("\n".join(includes + ['#include "vtkVoxelGISettingsWidget.h"', '#include "vtkActor.h"', '#include "vtkRenderWindow.h"',
        '#include "vtkRenderer.h"', "#include <QWidget>", ""]))
    out.write("inline vtkVoxelGIPass* RunReadmeSnippets(QWidget* parent, vtkRenderer* renderer,\n"
              "  vtkActor* lampActor, vtkActor* movingActor, vtkRenderWindow* renderWindow)\n{\n")
    out.write("\n".join("  " + l for l in body))
    out.write("\n  gi->Register(nullptr);\n  return gi;\n}\n")
PY
for tree in install build; do
  dir=$([ $tree = install ] && echo "-DCMAKE_PREFIX_PATH=$prefix" || echo "-DVoxelGI_DIR=$build/lib/cmake/VoxelGI")
  cmake -S "$work/consumer-src" -B "$work/consumer-$tree" "$dir" -Wno-dev \
    > "$work/consumer-$tree.log"
  cmake --build "$work/consumer-$tree" -j 2 >> "$work/consumer-$tree.log"
  out=$(QT_QPA_PLATFORM=offscreen "$work/consumer-$tree/my_viewer")
  echo "consumer against the $tree: $out"
  [[ "$out" =~ ^vtkVoxelGIPass\ [1-9][0-9]*\ snippets\ traced\ 1$ ]] ||
    { echo "FAILED: consumer against the $tree"; exit 1; }
done

site=$(/usr/bin/python3 -c 'import sys; print(f"lib/python{sys.version_info[0]}.{sys.version_info[1]}/dist-packages")')
env -u PYTHONPATH /usr/bin/python3 -c "
import site, sys
site.addsitedir('$prefix/$site')  # what python3 does with a prefix's dist-packages
import voxelgi
assert voxelgi.__file__.startswith('$prefix'), voxelgi.__file__
print('python:', voxelgi.vtkVoxelGIPass().GetClassName(), 'from', voxelgi.__file__)"
