#!/usr/bin/env python3
"""The library's messages never name a tool or a tool's flag: an option is named by its
Options field in braces ({sum_tolerance}, core/error.h), which the tools show as their flag
(tools/common/cli.cpp, with_flags). Fails on a string literal of the library holding a flag
(--name) or a tool's name, and on a braced field that no tool has a flag for (the field's
name with dashes, or a name of cli.cpp's flag_names)."""
import pathlib
import re
import sys

ROOT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parents[2])

LITERAL = re.compile(r'"((?:[^"\\\n]|\\.)*)"')
FLAG = re.compile(r"--[a-z][a-z0-9-]*")
FIELD = re.compile(r"\{([a-z_][a-z0-9_.]*)\}")
TOOL = re.compile(r"hexadapt-(?:generate|assign|reconstruct|adapt|measure|render)\b")


def code_lines(path):
    for number, line in enumerate(path.read_text().splitlines(), 1):
        code = line.split("//", 1)[0] if not line.lstrip().startswith("//") else ""
        yield number, code


def tool_flags():
    flags = set()
    for path in (ROOT / "tools").rglob("*.cpp"):
        for _, code in code_lines(path):
            for literal in LITERAL.findall(code):
                flags.update(FLAG.findall(literal))
    renamed = re.findall(r'\{"([a-z_.]+)", "([a-z-]+)"\}',
                         (ROOT / "tools" / "common" / "cli.cpp").read_text())
    return flags, dict(renamed)


def problems():
    flags, renamed = tool_flags()
    out, fields = [], 0
    for path in sorted((ROOT / "libhexadapt").rglob("*")):
        if path.suffix not in (".h", ".cpp"):
            continue
        for number, code in code_lines(path):
            for literal in LITERAL.findall(code):
                where = f"{path.relative_to(ROOT)}:{number}"
                for tool in TOOL.findall(literal):
                    out.append(f"{where}: names the tool {tool}")
                for flag in FLAG.findall(literal):
                    out.append(f"{where}: names the flag {flag}: name the field in braces")
                for field in FIELD.findall(literal):
                    fields += 1
                    flag = "--" + renamed.get(field, field).replace("_", "-").replace(".", "-")
                    if flag not in flags:
                        out.append(f"{where}: {{{field}}} is no tool's flag ({flag})")
    if fields == 0:
        out.append("no braced option field found in the library: the scan is broken")
    return out


if __name__ == "__main__":
    found = problems()
    for p in found:
        print(p)
    sys.exit(1 if found else 0)
