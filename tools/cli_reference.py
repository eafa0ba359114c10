#!/usr/bin/env python3
"""Writes the option tables of docs/*.md from the woven command's own definitions.

Each table sits between `<!-- options: SUBCOMMAND -->` and `<!-- /options -->` in a page under docs/,
and is made from `woven SUBCOMMAND --help` (CLI11's help, so the names, value types, checks and
descriptions are those of app/cmd_*.cpp and app/preview/frame_options.cpp).

    tools/cli_reference.py build/app/woven            rewrite the tables in place
    tools/cli_reference.py build/app/woven --check    exit 1 where a page differs, or a subcommand has no table

The ctest test Docs.OptionTablesMatchTheCommandLine runs the second.
"""
import difflib
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
MARKER = re.compile(r"<!-- options: ([a-z0-9-]+) -->\n(.*?)<!-- /options -->", re.S)


def run_help(woven, args):
    out = subprocess.run([woven, *args, "--help"], capture_output=True, text=True, check=False)
    if out.returncode != 0:
        sys.exit(f"{woven} {' '.join(args)} --help failed ({out.returncode}): {out.stderr}")
    return out.stdout


def entries(help_text):
    """(section, name column, description) for each option in CLI11's help."""
    section, items = None, []
    for line in help_text.splitlines():
        if re.match(r"^[A-Za-z][A-Za-z ]*:\s*$", line):
            section = line.strip().rstrip(":").lower()
            continue
        if section not in ("positionals", "options", "flags") or not line.strip():
            continue
        if re.match(r"^  \S", line):
            parts = re.split(r"\s{2,}", line.strip(), maxsplit=1)
            items.append([section, parts[0], parts[1] if len(parts) > 1 else "", line])
        elif items:
            items[-1][2] = (items[-1][2] + " " + line.strip()).strip()
    for item in items:
        line = item.pop()
        # A name that fills CLI11's column exactly is followed by one space, then its description.
        if not item[2] and len(line) > 30 and line[28] != " " and line[29] == " " and line[30] != " ":
            item[1], item[2] = line[2:29], line[30:].strip()
    return items


def subcommands(help_text):
    names, inside = [], False
    for line in help_text.splitlines():
        if re.match(r"^subcommands:\s*$", line, re.I):
            inside = True
            continue
        if inside:
            m = re.match(r"^  (\S+)", line)
            if m:
                names.append(m.group(1))
            elif line.strip() and not line.startswith("   "):
                inside = False
    return names


DEFAULT_IN_TEXT = [
    re.compile(r"\(default:? ([^);]*)[);]"),
    re.compile(r"default: ([^;)]+)"),
    re.compile(r"(\S+) \(default\)"),
    re.compile(r"(\S+) by default"),
]


def row(section, name_column, description):
    tokens = name_column.split(" ", 1)
    names, rest = tokens[0], tokens[1] if len(tokens) > 1 else ""
    names = re.sub(r"\{[^}]*\}", "", names)  # CLI11's {false} after a negated flag's name
    default = ""
    m = re.search(r"\[([^\]]*)\]\s*$", rest)  # CLI11's captured default
    if m and not re.search(r"in \[", rest[max(0, m.start() - 3):m.end()]):
        default, rest = m.group(1), rest[:m.start()].strip()
    required = " REQUIRED" in " " + rest
    rest = rest.replace("REQUIRED", "").strip()
    m = re.search(r"\s*\b(Excludes|Needs): (.*)$", rest)  # CLI11's relations between options
    if m:
        word = "not with" if m.group(1) == "Excludes" else "needs"
        description += f" ({word} {', '.join(m.group(2).split())})"
        rest = rest[:m.start()].strip()
    choices = re.findall(r"[\w-]+", re.sub(r"^\w+:", "", rest)) if re.search(r"\{|\|", rest) else []
    at = description.find("(default)")
    if not default and at >= 0 and choices:
        # a choice marked "(default)": the choice named nearest before the mark
        seen = [(description.rfind(c, 0, at), c) for c in choices if description.rfind(c, 0, at) >= 0]
        if seen:
            default = max(seen)[1]
    if not default:
        for pattern in DEFAULT_IN_TEXT:
            d = pattern.search(description)
            if d:
                default = d.group(1).strip()
                break
    if section == "positionals":
        option = f"`{names}`"
        default = default or ("required" if required else "")
    else:
        option = ", ".join(f"`{n}`" for n in names.split(","))
    value = f"`{rest}`" if rest else ("flag" if section != "positionals" else "")
    if not default and value == "flag":
        default = "off"
    cells = [option, value, default or "-", description]
    return "| " + " | ".join(c.replace("|", "\\|") for c in cells) + " |"


def table(woven, subcommand):
    lines = ["| option | value | default | meaning |", "|---|---|---|---|"]
    for section, name_column, description in entries(run_help(woven, [subcommand])):
        if name_column.startswith("-h,--help") or name_column.startswith("--help-all"):
            continue
        lines.append(row(section, name_column, description))
    if len(lines) == 2:
        return f"`woven {subcommand}` takes no options but `--help`.\n"
    return "\n".join(lines) + "\n"


def main():
    args = [a for a in sys.argv[1:] if a != "--check"]
    check = "--check" in sys.argv[1:]
    if len(args) != 1:
        sys.exit(__doc__)
    woven = args[0]
    documented, failures = set(), []
    for page in sorted(DOCS.glob("*.md")):
        text = page.read_text()
        cache = {}

        def replace(m):
            sub = m.group(1)
            documented.add(sub)
            cache[sub] = table(woven, sub)
            return f"<!-- options: {sub} -->\n{cache[sub]}<!-- /options -->"

        new = MARKER.sub(replace, text)
        if new == text:
            continue
        if check:
            diff = "".join(difflib.unified_diff(text.splitlines(True), new.splitlines(True),
                                                f"{page.name} (as written)", f"{page.name} (from --help)"))
            failures.append(f"docs/{page.name} differs from the command line; run tools/cli_reference.py "
                            f"{woven} to rewrite it:\n{diff}")
        else:
            page.write_text(new)
            print(f"rewrote docs/{page.name}")
    for sub in subcommands(run_help(woven, [])):
        if sub not in documented:
            failures.append(f"woven {sub} has no option table: add `<!-- options: {sub} -->` and "
                            f"`<!-- /options -->` to its page under docs/")
    for f in failures:
        print(f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
