"""Every setting of the settings table (Source/VoxelGISettings.json) is reachable from Python
with its default, range and clamping, and the pass has no setting the table lacks.

    test_settings.py SETTINGS_JSON
"""
import json
import sys

from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLRenderPass

from voxelgi import vtkVoxelGIPass

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def close(a, b):
    return abs(a - b) <= 1e-9 * max(1.0, abs(b))


def main(table_path):
    with open(table_path) as f:
        table = json.load(f)["settings"]

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
            continue
        lo, hi = s["min"], s["max"]
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
            if hasattr(vtkVoxelGIPass, "Get" + name) and name not in ("DelegatePass",):
                check(name in table_names, "%s is a setting of the pass but not in the table" % name)

    for failure in failures:
        print("FAILED:", failure)
    print("%d settings checked, %d failures" % (len(table), len(failures)))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main(sys.argv[1])
