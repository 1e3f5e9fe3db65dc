"""The settings table (Source/VoxelGISettings.json) is the single source of the settings; the
C++ that states them is generated from it (Source/GenerateSettings.cmake). This test checks
that what was generated agrees with the table, and that no hand-written copy came back:

- vtkVoxelGIPassSettings.h (generated, vtkVoxelGIPass's base class): each setting's setter
  (vtkSetClampMacro's range; enumerations: the enum's first and last values, and one constant
  per label, in the table's order, named <constant_prefix>_<LABEL>; power_of_two: a declared
  Set<Name>(int)), its member initialised to the default, and its doc comment: the table's
  "details" word for word, stating the default ("Default: ..." or "on/off by default") and,
  for numbers, the range ("in [min, max]");
- SettingsSnapshot.h/.cxx (generated, internal): one member of voxelgi::Settings per setting,
  of the setting's type (bool, int, double; enumerations int) with its default, and nothing
  else; SnapshotSettings fills each from the pass's getter;
- vtkVoxelGIPass.h and Frame.h (hand-written): no setter, getter, member or enum of a setting
  of the table, and no struct Settings;
- README.md: its settings table is exactly the one generate_settings_readme.py makes;
- the table itself: defaults in range, enumerations with one label per value and their enum's
  name and constant prefix, power-of-two settings with powers of two as range and default.

It reads the headers as text (regular expressions over the whole file, not lines), so
reformatting does not matter. Each failure names the setting and the file that disagrees.

    test_settings_copies.py SETTINGS_JSON GENERATED_DIR PASS_HEADER FRAME_HEADER README
"""
import json
import os
import re
import sys

failures = []


def fail(setting, copy, message):
    failures.append("%s: %s %s" % (setting, copy, message))


def close(a, b):
    return abs(a - b) <= 1e-9 * max(1.0, abs(b))


def blank_comments(text):
    """The text with comments replaced by spaces (newlines kept), so that offsets still match
    and code shown in comments is not taken for declarations."""
    return re.sub(r"/\*.*?\*/|//[^\n]*",
                  lambda m: re.sub(r"[^\n]", " ", m.group(0)), text, flags=re.S)


def parse_enums(code):
    """Every enum of the header: a list of [(constant, value)] per enum (value None where it
    is an expression other than a literal or an earlier constant)."""
    enums = []
    known = {}
    for body in re.findall(r"\benum\s+(?:class\s+)?\w*\s*(?::\s*\w+\s*)?\{([^}]*)\}", code):
        constants = []
        value = -1
        for entry in filter(None, (e.strip() for e in body.split(","))):
            name, _, expression = (part.strip() for part in entry.partition("="))
            if not expression:
                value = None if value is None else value + 1
            elif re.fullmatch(r"[-+]?(0[xX][0-9a-fA-F]+|\d+)", expression):
                value = int(expression, 0)
            else:
                value = known.get(expression)
            known[name] = value
            constants.append((name, value))
        enums.append(constants)
    return enums


def snake(label):
    """Enumeration label to the enum constant's suffix: EveryNFrames -> EVERY_N_FRAMES."""
    return re.sub(r"(?<=[a-z0-9])(?=[A-Z])|(?<=[A-Z])(?=[A-Z][a-z])", "_", label).upper()


class Header:
    def __init__(self, path):
        with open(path) as f:
            self.text = f.read()
        self.code = blank_comments(self.text)
        self.enums = parse_enums(self.code)
        self.constants = {name: value for enum in self.enums for name, value in enum}

    def value(self, token):
        """A number, bool or enum constant of the header as a number; None if unknown."""
        token = token.strip().split("::")[-1]
        if token in self.constants:
            return self.constants[token]
        if token in ("true", "false"):
            return float(token == "true")
        try:
            return float(token.rstrip("fF"))
        except ValueError:
            return None

    def enum_of(self, constant):
        return next((e for e in self.enums if constant in dict(e)), None)

    def setter(self, name):
        """The setting's setter declaration: (match of a clamp macro or None, its offset),
        or None when the header declares no setter."""
        # vtkVoxelGISetClampMacro: vtkSetClampMacro that also refuses NaN.
        clamp = re.search(r"\b(?:vtkSetClampMacro|vtkVoxelGISetClampMacro)\(\s*%s\s*,\s*([^,]+?)\s*,\s*([^,]+?)\s*,"
                          r"\s*([^)]+?)\s*\)" % name, self.code)
        if clamp:
            return clamp, clamp.start()
        other = re.search(r"\b(?:vtkSetMacro\(\s*%s\s*,|vtkVoxelGISetBoolMacro\(\s*%s\s*\))|\bvoid\s+Set%s\s*\("
                          % (name, name, name), self.code)
        return (None, other.start()) if other else None

    def doc_comment(self, name, offset):
        """Text of the doc comment right before the declaration at offset (only the setting's
        own declarations may come between), leading '*' removed; None if there is none."""
        comments = list(re.finditer(r"/\*\*(.*?)\*/", self.text[:offset], flags=re.S))
        if not comments:
            return None
        between = self.code[comments[-1].end():offset]
        # other declarations of the setting, then the start of this one ("virtual void ")
        between = re.sub(r"[^;{}]*\b%s\b[^;{}]*;" % name, "", between)
        if re.sub(r"[^;{}]*$", "", between).strip():
            return None
        return re.sub(r"\s*\n\s*\*", " ", comments[-1].group(1))

    def initialiser(self, name):
        """The member initialiser's value text, or None when the header states none (no
        initialiser, or an empty "{}" when the constructor sets the table's default)."""
        m = re.search(r"\b(?:vtkTypeBool|bool|int|double|float)\s+%s\s*"
                      r"(?:=\s*([^;{]+?)|\{\s*([^}]*?)\s*\})\s*;" % name, self.code)
        return (m.group(1) or m.group(2) or None) if m else None


def shown(setting, value):
    if setting["type"] == "bool":
        return "on" if value else "off"
    if setting["type"] == "enum":
        return "%s (%d)" % (setting["values"][int(value) - setting["min"]], value)
    return "%g" % value


def check_table(s):
    name = s["name"]
    copy = "VoxelGISettings.json"
    if not s.get("details", "").strip():
        fail(name, copy, "has no \"details\" (the header's documentation of the setting)")
    if s["type"] == "enum" and not (s.get("enum") and s.get("constant_prefix")):
        fail(name, copy, "needs \"enum\" (the C++ enum's name) and \"constant_prefix\"")
    if s["type"] == "bool":
        return
    if not s["min"] <= s["default"] <= s["max"]:
        fail(name, copy, "default %g is outside [%g, %g]" % (s["default"], s["min"], s["max"]))
    if s["type"] == "enum" and len(s.get("values", [])) != s["max"] - s["min"] + 1:
        fail(name, copy, "has %d labels for the values %d ... %d"
             % (len(s.get("values", [])), s["min"], s["max"]))
    if s.get("power_of_two"):
        def power(v):
            return v > 0 and v == int(v) and int(v) & (int(v) - 1) == 0
        if s["type"] != "int" or not all(power(s[k]) for k in ("min", "max", "default")):
            fail(name, copy, "power_of_two needs an int setting with powers of two as min, max "
                 "and default")


def check_header(s, header):
    name = s["name"]
    copy = "vtkVoxelGIPassSettings.h"
    setter = header.setter(name)
    if setter is None:
        fail(name, copy, "declares no setter (vtkSetClampMacro, vtkSetMacro, vtkVoxelGISetBoolMacro "
             "or Set%s())" % name)
        return
    clamp, offset = setter

    # constants that name the setting's values: the enumeration is the enum they belong to
    constants = []
    if clamp:
        if (clamp.group(1) == "double") != (s["type"] == "double"):
            fail(name, copy + " vtkSetClampMacro", "has type %s, the table %s"
                 % (clamp.group(1), s["type"]))
        bounds = (0, 1) if s["type"] == "bool" else (s["min"], s["max"])
        for bound, token, expected in zip(("min", "max"), clamp.group(2, 3), bounds):
            value = header.value(token)
            if value is None:
                fail(name, copy + " vtkSetClampMacro", "%s '%s' is not a number or enum constant"
                     % (bound, token))
            elif not close(value, expected):
                named = "" if token.strip() == "%g" % value else " (%g)" % value
                fail(name, copy + " vtkSetClampMacro", "has %s %s%s, the table says %g"
                     % (bound, token, named, expected))
            constants.append(token.split("::")[-1])

    initialiser = header.initialiser(name)
    if initialiser is None:
        fail(name, copy, "has no member initialised to the default")
    else:
        value = header.value(initialiser)
        if value is None or not close(value, s["default"]):
            fail(name, copy + " member initialiser", "is '%s', the table's default is %s"
                 % (initialiser, shown(s, s["default"])))
        constants.append(initialiser.strip().split("::")[-1])

    doc = header.doc_comment(name, offset)
    if doc is None:
        fail(name, copy, "has no doc comment right before the setter")
    else:
        if " ".join(doc.split()) != " ".join(s.get("details", "").split()):
            fail(name, copy + " doc comment", "is not the table's details: %r" % " ".join(doc.split()))
        stated = (re.search(r"Default:\s*([A-Za-z_][\w:]*|[-+]?\d+(?:\.\d+)?)", doc)
                  or re.search(r"\b(on|off)\s+by\s+default", doc))
        if stated is None:
            fail(name, copy + " doc comment", "states no default ('Default: ...')")
        else:
            text = stated.group(1)
            if s["type"] == "bool":
                value = {"on": 1, "off": 0}.get(text)
            elif s["type"] == "enum":
                value = header.constants.get(text.split("::")[-1])
                constants.append(text.split("::")[-1])
            else:
                value = header.value(text)
            if value is None or not close(value, s["default"]):
                fail(name, copy + " doc comment", "says '%s', the table's default is %s"
                     % (stated.group(0), shown(s, s["default"])))
        number = r"\s*([-+]?\d+(?:\.\d+)?)\s*"
        stated_range = re.search(r"\bin\s+\[%s,%s\]" % (number, number), doc)
        if stated_range is None and s["type"] in ("int", "double"):
            fail(name, copy + " doc comment", "states no range ('in [%g, %g]')"
                 % (s["min"], s["max"]))
        if stated_range and s["type"] in ("int", "double"):
            lo, hi = float(stated_range.group(1)), float(stated_range.group(2))
            if not (close(lo, s["min"]) and close(hi, s["max"])):
                fail(name, copy + " doc comment", "says [%g, %g], the table's range is [%g, %g]"
                     % (lo, hi, s["min"], s["max"]))

    if s["type"] == "enum":
        enum = next(filter(None, (header.enum_of(c) for c in constants)), None)
        if enum is None:
            fail(name, copy, "names no enum constant for this enumeration")
            return
        values = [v for _, v in enum]
        if values[0] != s["min"] or values[-1] != s["max"] or len(enum) != len(s["values"]):
            fail(name, copy + " enum", "of %s has the values %s, the table %d ... %d (%d labels)"
                 % (enum[0][0], values, s["min"], s["max"], len(s["values"])))
            return
        for (constant, value), label in zip(enum, s["values"]):
            if constant != "%s_%s" % (s.get("constant_prefix"), snake(label)):
                fail(name, copy + " enum", "constant %s (%d) is not the table's label %s"
                     % (constant, value, label))
        if not re.search(r"\benum\s+%s\s*\{" % s.get("enum"), header.code):
            fail(name, copy, "has no enum %s" % s.get("enum"))
        for label in s["values"]:
            if not re.search(r"\bvoid\s+Set%sTo%s\s*\(\s*\)" % (name, label), header.code):
                fail(name, copy, "has no Set%sTo%s()" % (name, label))
    if s["type"] == "bool":
        if not re.search(r"\bvtkBooleanMacro\(\s*%s\s*," % name, header.code):
            fail(name, copy, "has no vtkBooleanMacro (%sOn/Off)" % name)


def check_snapshot(settings, header_path, source_path):
    """voxelgi::Settings has exactly the table's settings, with their types and defaults, and
    SnapshotSettings fills each from the pass."""
    with open(header_path) as f:
        code = blank_comments(f.read())
    with open(source_path) as f:
        fill = blank_comments(f.read())
    copy = os.path.basename(header_path)
    body = re.search(r"\bstruct\s+Settings\s*\{(.*?)\};", code, flags=re.S)
    if body is None:
        failures.append("%s: no struct Settings" % copy)
        return
    members = {m.group(2): (m.group(1), m.group(3)) for m in re.finditer(
        r"\b(bool|int|double)\s+(\w+)\s*=\s*([^;]+);", body.group(1))}
    enums = parse_enums(code)
    constants = {name: value for enum in enums for name, value in enum}
    for s in settings:
        name = s["name"]
        member = members.pop(name, None)
        if member is None:
            fail(name, copy, "voxelgi::Settings has no member %s" % name)
            continue
        expected = {"bool": "bool", "int": "int", "enum": "int", "double": "double"}[s["type"]]
        if member[0] != expected:
            fail(name, copy, "voxelgi::Settings has it as %s, not %s" % (member[0], expected))
        text = member[1].strip()
        value = constants.get(text, {"true": 1.0, "false": 0.0}.get(text))
        if value is None:
            try:
                value = float(text)
            except ValueError:
                value = None
        if value is None or not close(value, s["default"]):
            fail(name, copy, "voxelgi::Settings defaults it to '%s', the table to %s"
                 % (text, shown(s, s["default"])))
        getter = r"\bc\.%s\s*=\s*pass->Get%s\(\)" % (name, name)
        if not re.search(getter, fill):
            fail(name, os.path.basename(source_path), "SnapshotSettings does not fill it")
    for name in members:
        fail(name, copy, "voxelgi::Settings has it, the table does not")


def check_no_copies(settings, path):
    """A hand-written header restates no setting: no setter, getter, member or enum of one."""
    copy = os.path.basename(path) + " (hand-written)"
    with open(path) as f:
        code = blank_comments(f.read())
    if re.search(r"\bstruct\s+Settings\s*\{", code):
        failures.append("%s: defines struct Settings, which is generated" % copy)
    for s in settings:
        name = s["name"]
        patterns = [r"\bvtk(?:Set|Get|SetClamp|VoxelGISetClamp|Boolean)Macro\(\s*%s\s*," % name,
                    r"\b(?:Set|Get)%s\s*\(" % name,
                    r"\b(?:vtkTypeBool|bool|int|double)\s+%s\s*[;={]" % name]
        if s["type"] == "enum":
            patterns.append(r"\benum\s+%s\b" % s.get("enum"))
        if any(re.search(pattern, code) for pattern in patterns):
            fail(name, copy, "declares it again; the settings are generated from the table")


def check_readme(settings, path, generator):
    copy = "README.md settings table"
    with open(path, encoding="utf-8") as f:
        text = f.read()
    span = generator.find_table(text)
    if span is None:
        failures.append("%s: missing (no line '%s')" % (copy, generator.TITLE))
        return
    found = text[span[0]:span[1]]
    if found == generator.table(settings):
        return
    rows = {line.split("|")[1].strip(): line + "\n" for line in found.splitlines()[2:]}
    for s in settings:
        expected = generator.row(s)
        found_row = rows.pop("`%s`" % s["name"], None)
        if found_row is None:
            fail(s["name"], copy, "has no row; the table gives %r" % expected)
        elif found_row != expected:
            fail(s["name"], copy, "reads %r, the table gives %r" % (found_row, expected))
    for cell in rows:
        fail(cell, copy, "has a row for what is not a setting of the table")
    failures.append("%s differs from the generated one (order or header included): regenerate "
                    "it with python3 Source/generate_settings_readme.py" % copy)


def main(table_path, generated_dir, pass_header, frame_header, readme_path):
    with open(table_path) as f:
        settings = json.load(f)["settings"]
    # the README's generator lives next to the table
    sys.path.insert(0, os.path.dirname(os.path.abspath(table_path)))
    import generate_settings_readme

    header = Header(os.path.join(generated_dir, "vtkVoxelGIPassSettings.h"))
    for s in settings:
        check_table(s)
        check_header(s, header)
    check_snapshot(settings, os.path.join(generated_dir, "SettingsSnapshot.h"),
                   os.path.join(generated_dir, "SettingsSnapshot.cxx"))
    for path in (pass_header, frame_header):
        check_no_copies(settings, path)
    check_readme(settings, readme_path, generate_settings_readme)

    for failure in failures:
        print("FAILED:", failure)
    print("%d settings checked against the generated headers, vtkVoxelGIPass.h, Frame.h and "
          "README.md, %d failures" % (len(settings), len(failures)))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main(*sys.argv[1:6])
