"""Every setting of the settings table (Source/VoxelGISettings.json) is reachable from Python
with its default, range (Get<Name>MinValue/MaxValue) and clamping, its enumeration's constants
and Set<Name>To<Label>(), and the pass has no setting the table lacks. The setters are generated
from the table (vtkVoxelGIPassSettings, the pass's base class): this checks that VTK's wrapper
wraps them.

    test_settings.py SETTINGS_JSON
"""
import json
import re
import sys

from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLRenderPass

from vtkmodules.vtkCommonCore import vtkObject

from voxelgi import vtkVoxelGIPass, vtkVoxelGISettings

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def close(a, b):
    return abs(a - b) <= 1e-9 * max(1.0, abs(b))


TABLE = []


def snake(label):
    """Enumeration label to the enum constant's suffix: EveryNFrames -> EVERY_N_FRAMES."""
    return re.sub(r"(?<=[a-z0-9])(?=[A-Z])|(?<=[A-Z])(?=[A-Z][a-z])", "_", label).upper()


def check_set_value():
    """vtkVoxelGISettings.SetValue clamps in double before converting, refuses NaN and unknown
    names (keeping the setting), and GetValue returns 0 for an unknown name."""
    gi = vtkVoxelGIPass()
    vtkObject.GlobalWarningDisplayOff()  # the refusals warn; what they do is checked here
    try:
        cases = [("Enabled", 1e30, 1), ("Enabled", -1, 0), ("Enabled", 2, 1),
                 ("Bounces", 3e9, 10), ("Bounces", -2147483649, 0), ("Bounces", float("inf"), 10),
                 ("Bounces", float("-inf"), 0), ("DiffuseConeCount", 1e30, 16),
                 ("UpdatePolicy", 1e9, 3), ("VoxelResolution", 1e30, 512),
                 ("AmbientOcclusionStrength", float("inf"), 1.0)]
        for name, value, expected in cases:
            ok = vtkVoxelGISettings.SetValue(gi, name, value)
            got = vtkVoxelGISettings.GetValue(gi, name)
            check(ok and close(got, expected), "SetValue(%s, %r) gives %r, expected %r" % (name, value, got, expected))
        before = gi.GetAmbientOcclusionStrength()
        check(not vtkVoxelGISettings.SetValue(gi, "AmbientOcclusionStrength", float("nan")),
              "SetValue accepts NaN")
        check(gi.GetAmbientOcclusionStrength() == before, "NaN through SetValue changed the setting")
        for s in [s for s in TABLE if s["type"] == "double"]:
            get, put = getattr(gi, "Get" + s["name"]), getattr(gi, "Set" + s["name"])
            before = get()
            put(float("nan"))
            check(get() == before, "Set%s(NaN) changed the setting to %r" % (s["name"], get()))
        check(not vtkVoxelGISettings.SetValue(gi, "NoSuchSetting", 1.0), "SetValue accepts an unknown name")
        check(vtkVoxelGISettings.GetValue(gi, "NoSuchSetting") == 0.0, "GetValue of an unknown name is not 0")
        check(vtkVoxelGISettings.GetIndex("Bounces") >= 0 and vtkVoxelGISettings.GetIndex("Nope") == -1,
              "GetIndex")
    finally:
        vtkObject.GlobalWarningDisplayOn()


def main(table_path):
    with open(table_path) as f:
        table = json.load(f)["settings"]
    TABLE.extend(table)

    for s in table:
        name = s["name"]
        gi = vtkVoxelGIPass()
        get = getattr(gi, "Get" + name, None)
        put = getattr(gi, "Set" + name, None)
        check(get is not None and put is not None, "%s: no Get/Set in Python" % name)
        if get is None or put is None:
            continue
        check(close(get(), s["default"]), "%s: default %s, table says %s" % (name, get(), s["default"]))
        if s["type"] == "bool":
            getattr(gi, name + "Off")()
            check(get() == 0, "%s: Off does not turn it off" % name)
            getattr(gi, name + "On")()
            check(get() == 1, "%s: On does not turn it on" % name)
            for value, expected in ((7, 1), (-5, 1), (-1000, 1), (0, 0)):
                put(value)
                check(get() == expected, "%s: Set(%s) keeps %s, expected %s" % (name, value, get(), expected))
            continue
        lo, hi = s["min"], s["max"]
        for bound, expected in (("Min", lo), ("Max", hi)):
            method = getattr(gi, "Get%s%sValue" % (name, bound), None)
            check(method is not None, "%s: no Get%s%sValue in Python" % (name, name, bound))
            if method:
                check(close(method(), expected), "%s: Get%s%sValue() is %s, the table says %s"
                      % (name, name, bound, method(), expected))
        for index, label in enumerate(s.get("values", [])):
            constant = "%s_%s" % (s["constant_prefix"], snake(label))
            value = getattr(vtkVoxelGIPass, constant, None)
            check(value == lo + index, "%s: vtkVoxelGIPass.%s is %r, expected %d"
                  % (name, constant, value, lo + index))
        delta = 1 if s["type"] in ("int", "enum") else 0.5 * (hi - lo)
        for value, expected in ((lo, lo), (hi, hi), (lo - delta, lo), (hi + delta, hi)):
            put(value)
            check(close(get(), expected), "%s: Set(%s) gives %s, expected %s" % (name, value, get(), expected))
        if s.get("power_of_two"):
            put(100)
            check(get() == 128, "%s: 100 does not round to 128" % name)
        for index, label in enumerate(s.get("values", [])):
            setter = getattr(gi, "Set%sTo%s" % (name, label), None)
            check(setter is not None, "%s: no Set%sTo%s" % (name, name, label))
            if setter:
                setter()
                check(get() == index, "%s: Set%sTo%s gives %s" % (name, name, label, get()))

    # Settings the pass has but the table lacks: Set/Get pairs beyond the render pass base.
    base = set(dir(vtkOpenGLRenderPass))
    table_names = {s["name"] for s in table}
    for attr in dir(vtkVoxelGIPass):
        if attr.startswith("Set") and attr not in base and "To" not in attr[3:]:
            name = attr[3:]
            if hasattr(vtkVoxelGIPass, "Get" + name) and name not in ("DelegatePass", "VoxelSource"):
                check(name in table_names, "%s is a setting of the pass but not in the table" % name)

    check_set_value()

    for failure in failures:
        print("FAILED:", failure)
    print("%d settings checked, %d failures" % (len(table), len(failures)))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main(sys.argv[1])
