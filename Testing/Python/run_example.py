"""Runs an example script that writes a PNG and compares the PNG with a baseline through
vtkTesting (the same comparison as VTK's C++ regression tests), then strictly
(strict_image.py). Exits non-zero when the images differ or the baseline is missing (the
rendered image is then left in the output directory for review).

    run_example.py SCRIPT BASELINE OUTPUT_DIR [SCRIPT_ARGS_BEFORE_OUTPUT...]
"""
import os
import subprocess
import sys

from strict_image import mismatch


def main():
    script, baseline, output_dir = sys.argv[1:4]
    extra = sys.argv[4:]
    os.makedirs(output_dir, exist_ok=True)
    name = os.path.splitext(os.path.basename(baseline))[0]
    output = os.path.join(output_dir, name + "-rendered.png")
    subprocess.run([sys.executable, script] + extra + [output], check=True)

    problem = mismatch(baseline, output, output_dir)
    if problem:
        sys.exit("image of %s: %s" % (script, problem))
    print("image matches", baseline)


if __name__ == "__main__":
    main()
