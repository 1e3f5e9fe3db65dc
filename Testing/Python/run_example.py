"""Runs an example script that writes a PNG and compares the PNG with a baseline through
vtkTesting (the same comparison as VTK's C++ regression tests), then strictly
(strict_image.py). Exits non-zero when the images differ or the baseline is missing (the
rendered image is then left in the output directory for review).

    run_example.py SCRIPT BASELINE OUTPUT_DIR [SCRIPT_ARGS_BEFORE_OUTPUT...]
"""
import os
import subprocess
import sys

from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkTestingRendering import vtkTesting

from strict_image import differs


def main():
    script, baseline, output_dir = sys.argv[1:4]
    extra = sys.argv[4:]
    os.makedirs(output_dir, exist_ok=True)
    name = os.path.splitext(os.path.basename(baseline))[0]
    output = os.path.join(output_dir, name + "-rendered.png")
    subprocess.run([sys.executable, script] + extra + [output], check=True)

    reader = vtkPNGReader()
    reader.SetFileName(output)
    testing = vtkTesting()
    for arg in ("-V", baseline, "-T", output_dir):
        testing.AddArgument(arg)
    result = testing.RegressionTest(reader, 10.0)
    if result != vtkTesting.PASSED:
        sys.exit("image of %s does not match %s (see %s)" % (script, baseline, output_dir))
    problem = differs(baseline, output)
    if problem:
        sys.exit("image of %s: %s" % (script, problem))
    print("image matches", baseline)


if __name__ == "__main__":
    main()
