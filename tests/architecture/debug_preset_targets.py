#!/usr/bin/python3
"""The debug preset builds only the test programs its suites live in (CMakePresets.json). A
program left off that list would drop its suites from the debug run without a word, because
ctest then sees a `<program>_NOT_BUILT` test that the name filter excludes. This check reads the
suites of a build that has every program, and names each program the debug filter needs and the
debug build does not make.

    debug_preset_targets.py CTEST BUILD_DIR PRESETS_JSON
"""
import json
import os
import re
import subprocess
import sys


def preset(presets, kind, name):
    return next(p for p in presets[kind] if p["name"] == name)


def main():
    ctest, build_dir, presets_path = sys.argv[1:4]
    with open(presets_path, encoding="utf-8") as f:
        presets = json.load(f)
    suites = preset(presets, "testPresets", "debug")["filter"]
    include = re.compile(suites["include"]["name"])
    excluded_label = re.compile(suites["exclude"]["label"])
    built = set(preset(presets, "buildPresets", "debug").get("targets", []))

    listing = subprocess.run([ctest, "--test-dir", build_dir, "--show-only=json-v1"],
                             check=True, capture_output=True, text=True).stdout
    needed = set()
    for test in json.loads(listing)["tests"]:
        labels = [label for p in test.get("properties", []) if p["name"] == "LABELS"
                  for label in p["value"]]
        if not include.search(test["name"]) or any(excluded_label.search(l) for l in labels):
            continue
        needed.add(os.path.basename(test["command"][0]))
    if not needed:
        sys.exit("debug_preset_targets: no suite matches the debug filter; wrong build dir?")
    missing = sorted(needed - built)
    if missing:
        sys.exit(f"{presets_path}: the debug build preset does not build "
                 f"{', '.join(missing)}, whose suites the debug test preset runs")
    print(f"the debug preset builds all {len(needed)} programs its suites live in")


if __name__ == "__main__":
    main()
