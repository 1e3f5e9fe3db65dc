#!/usr/bin/env bash
# What a user of an installed VoxelGI does, checked end to end:
#   test_install.sh SOURCE_DIR BUILD_DIR WORK_DIR
# installs BUILD_DIR into WORK_DIR/prefix; builds Examples/Cxx there as a project of its own
# against the install and runs its demo (the GI image must not be empty); builds the README's
# consumer (find_package(VoxelGI COMPONENTS Qt)) against the install and against the build
# tree and runs it; imports the Python package through the install's .pth file alone.
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

for tree in install build; do
  dir=$([ $tree = install ] && echo "-DCMAKE_PREFIX_PATH=$prefix" || echo "-DVoxelGI_DIR=$build/lib/cmake/VoxelGI")
  cmake -S "$src/Testing/Install/consumer" -B "$work/consumer-$tree" "$dir" -Wno-dev \
    > "$work/consumer-$tree.log"
  cmake --build "$work/consumer-$tree" -j 2 >> "$work/consumer-$tree.log"
  out=$(QT_QPA_PLATFORM=offscreen "$work/consumer-$tree/my_viewer")
  echo "consumer against the $tree: $out"
  [[ "$out" =~ ^vtkVoxelGIPass\ [1-9] ]] || { echo "FAILED: consumer against the $tree"; exit 1; }
done

site=$(/usr/bin/python3 -c 'import sys; print(f"lib/python{sys.version_info[0]}.{sys.version_info[1]}/dist-packages")')
env -u PYTHONPATH /usr/bin/python3 -c "
import site, sys
site.addsitedir('$prefix/$site')  # what python3 does with a prefix's dist-packages
import voxelgi
assert voxelgi.__file__.startswith('$prefix'), voxelgi.__file__
print('python:', voxelgi.vtkVoxelGIPass().GetClassName(), 'from', voxelgi.__file__)"
