#!/usr/bin/env python3
"""product_layering.py SOURCE_DIR: fails, naming each, when a product file includes a header of a
higher layer than its own. The layers are the folders of core/CMakeLists.txt's add_subdirectory
lines in their order (the lowest first), then app/CMakeLists.txt's, then app/ itself, the
command, highest: so core never includes app. A header is found by its name, in the including
file's folder first (headers' names are unique across the product). Data flows one way; a lower
layer that needs something of a higher one wants it moved down, not included up.
product_layering.py --self-test: checks the rule on a generated tree.
"""
import pathlib
import re
import sys
import tempfile

from product_checks import report, self_test_result, usage


def layers(root):
    """The product's folders, relative to root, lowest layer first."""
    order = []
    for parent in ("core", "app"):
        cmake = (root / parent / "CMakeLists.txt").read_text(encoding="utf-8")
        for line in cmake.splitlines():
            m = re.match(r"\s*add_subdirectory\(\s*([\w/]+)\s*\)", line)
            if m:
                order.append(f"{parent}/{m.group(1)}")
    order.append("app")
    return order


def upward_includes(root):
    """'file:line: includes header (layer) from layer' for each include of a higher layer."""
    order = layers(root)
    rank = {folder: i for i, folder in enumerate(order)}
    files = [p for folder in order for p in sorted((root / folder).glob("*")) if p.suffix in (".cpp", ".h", ".in")]
    home = {}
    for p in files:
        if p.suffix == ".h":
            home.setdefault(p.name, p.parent.relative_to(root).as_posix())
    problems = []
    for p in files:
        folder = p.parent.relative_to(root).as_posix()
        for number, line in enumerate(p.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
            m = re.match(r'\s*#\s*include\s*"([^"]+)"', line)
            if not m:
                continue
            name = m.group(1)
            found = folder if (p.parent / name).is_file() else home.get(pathlib.PurePosixPath(name).name)
            if found is not None and rank[found] > rank[folder]:
                problems.append(f"  {p.relative_to(root).as_posix()}:{number}: includes {name} ({found}) from {folder}")
    return problems


def self_test():
    """A generated tree of three layers: including downwards passes, upwards fails."""
    with tempfile.TemporaryDirectory() as directory:
        root = pathlib.Path(directory)
        tree = {
            "core/CMakeLists.txt": "add_subdirectory(low)  # the lowest\nadd_subdirectory(high)\n",
            "app/CMakeLists.txt": "add_subdirectory(options)\n",
            "core/low/low.h": "#pragma once\n",
            "core/high/high.h": '#pragma once\n#include "low.h"\n',
            "app/options/options.h": '#pragma once\n#include "high.h"\n',
            "app/main.cpp": '#include "options.h"\n#include <vector>\n',
        }
        for name, text in tree.items():
            (root / name).parent.mkdir(parents=True, exist_ok=True)
            (root / name).write_text(text)
        checks = [(upward_includes(root), [])]
        (root / "core/low/low.cpp").write_text('#include "low.h"\n\n#include "high.h"\n')
        (root / "core/high/high.cpp").write_text('#include "main_options.h"\n#include "options.h"\n')
        checks.append((upward_includes(root), ["  core/high/high.cpp:2: includes options.h (app/options) from core/high",
                                               "  core/low/low.cpp:3: includes high.h (core/high) from core/low"]))
    return self_test_result("layering", [(sorted(got), sorted(want)) for got, want in checks])


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) != 2:
        return usage(__doc__)
    return report(upward_includes(pathlib.Path(argv[1])),
                  "product files that include a higher layer's header (the layers: core/CMakeLists.txt, then app/):",
                  "no product file includes a higher layer's header")


if __name__ == "__main__":
    sys.exit(main(sys.argv))
