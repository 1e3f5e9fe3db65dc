"""README.md's table of settings, generated from the settings table (Source/VoxelGISettings.json)
so that the README cannot disagree with it. After changing the settings table, rewrite the
README's table with

    python3 Source/generate_settings_readme.py

The test Python.settings_copies checks that README.md holds exactly the generated table.
"""
import json
import os
import sys

TITLE = "| setting | range | default | meaning |"
HEADER = TITLE + "\n|---|---|---|---|\n"


def number(value):
    return "%g" % value


def range_text(setting):
    if setting["type"] == "bool":
        return "on/off"
    if setting["type"] == "enum":
        return ", ".join(setting["values"])
    if setting.get("power_of_two"):
        powers = [number(2 ** k) for k in range(31) if setting["min"] <= 2 ** k <= setting["max"]]
        return ", ".join(powers if len(powers) <= 3 else powers[:2] + ["…", powers[-1]])
    return "%s … %s" % (number(setting["min"]), number(setting["max"]))


def default_text(setting):
    if setting["type"] == "bool":
        return "on" if setting["default"] else "off"
    if setting["type"] == "enum":
        return setting["values"][setting["default"] - setting["min"]]
    return number(setting["default"])


def row(setting):
    """The setting's line of the README's table."""
    meaning = setting["doc"].replace("|", "\\|")
    return "| `%s` | %s | %s | %s |\n" % (setting["name"], range_text(setting),
                                          default_text(setting), meaning)


def table(settings):
    return HEADER + "".join(row(s) for s in settings)


def find_table(text):
    """Start and end of the settings table in the README's text (its header and the lines
    after it that start with "|"), or None."""
    start = text.find(TITLE)
    if start < 0:
        return None
    end = start
    while text.startswith("|", end):
        line_end = text.find("\n", end)
        end = len(text) if line_end < 0 else line_end + 1
    return start, end


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    readme_path = os.path.join(here, "..", "README.md")
    with open(os.path.join(here, "VoxelGISettings.json")) as f:
        settings = json.load(f)["settings"]
    with open(readme_path, encoding="utf-8") as f:
        text = f.read()
    span = find_table(text)
    if span is None:
        sys.exit("README.md has no settings table (a line '%s')" % TITLE)
    updated = text[:span[0]] + table(settings) + text[span[1]:]
    if updated != text:
        with open(readme_path, "w", encoding="utf-8") as f:
            f.write(updated)


if __name__ == "__main__":
    main()
