"""Strict comparison of a rendered PNG with its baseline. VTK 9.1's vtkTesting ignores pixels
that differ by less than its threshold (a change of 74 levels in a channel passed it), so
the Python and ParaView tests also fail when more than 0.1 % of the pixels differ by more
than 12 levels in a channel or the mean difference exceeds 0.5 levels, as the C++ tests do.
"""
import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkTestingRendering import vtkTesting


def rgb(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].astype(float)


def differs(baseline, rendered):
    """None when `rendered` matches `baseline`, else what differs. Prints the numbers."""
    expected, actual = rgb(baseline), rgb(rendered)
    if expected.shape != actual.shape:
        return "%s has another size than %s" % (rendered, baseline)
    difference = numpy.abs(actual - expected)
    mean = difference.mean()
    over = (difference.max(axis=1) > 12).mean()
    print("strict image comparison: mean difference %.3f levels, %.3f %% of pixels differ by "
          "more than 12 levels" % (mean, 100 * over))
    if mean > 0.5 or over > 0.001:
        return "%s differs from %s (VTK's threshold hid it)" % (rendered, baseline)
    return None


def mismatch(baseline, rendered, output_dir):
    """None when `rendered` matches `baseline` through vtkTesting (which writes the test and
    difference images to `output_dir` when it fails) and strictly, else what differs."""
    reader = vtkPNGReader()
    reader.SetFileName(rendered)
    testing = vtkTesting()
    for arg in ("-V", baseline, "-T", output_dir):
        testing.AddArgument(arg)
    if testing.RegressionTest(reader, 10.0) != vtkTesting.PASSED:
        return "%s does not match %s (see %s)" % (rendered, baseline, output_dir)
    return differs(baseline, rendered)
