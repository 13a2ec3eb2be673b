#!/usr/bin/env python3
"""The library's units depend one way (docs/architecture.md, "Dependency direction"): a unit
includes only the public headers of the units to its left, and no file reaches into another
unit's src/. Inside a unit's src/, a room (a folder: io/vtk_xml, io/exodus, ...) includes its
own private headers and the unit's shared ones (src/<unit>/*.h), and another room's only where
ROOM_USES allows it. The tools include public headers only. Prints every include that breaks this and
fails; a known crossing, if one is ever allowed, is listed below with the file that makes it."""
import pathlib
import re
import sys

ROOT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parents[2])

# Level of each unit: a unit may include the public headers of units of a lower level.
LEVEL = {"core": 0, "dist": 1, "quality": 1, "mesh": 2, "io": 3, "assign": 4, "generate": 4,
         "reconstruct": 5, "adapt": 6, "measure": 7}

# Rooms of a unit's src/ that build on another room's private headers.
ROOM_USES = {"io/collection": {"io/vtk_xml"}}

# Known crossings, each (file, what it includes: a unit, or another unit's private header).
KNOWN = set()

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def unit_of(path):
    parts = path.relative_to(ROOT).parts
    if parts[:1] == ("libhexadapt",) and len(parts) > 2:
        return parts[3] if parts[1] == "include" else parts[2]
    return None


def room_of(path):
    """The room of a file under libhexadapt/src ("io/vtk_xml"; "io" for the unit's own
    shared files), or None elsewhere."""
    parts = path.relative_to(ROOT).parts
    if parts[:2] != ("libhexadapt", "src") or len(parts) < 4:
        return None
    return "/".join(parts[2:-1])


def private_include_problem(path, target):
    """Why `path` may not include the private header `target` ("../x.h"), or None."""
    here, there = room_of(path), room_of((path.parent / target).resolve())
    if here is None or there is None or here.split("/")[0] != there.split("/")[0]:
        return "another unit's private header"
    if there == here.split("/")[0] or there == here or there in ROOM_USES.get(here, ()):
        return None
    return f"a private header of the room {there}, which {here} does not build on"


def problems():
    out = []
    files = [p for p in (ROOT / "libhexadapt").rglob("*") if p.suffix in (".h", ".cpp")]
    files += [p for p in (ROOT / "tools").rglob("*") if p.suffix in (".h", ".cpp")]
    for path in sorted(files):
        rel = str(path.relative_to(ROOT))
        unit = unit_of(path)
        for target in INCLUDE.findall(path.read_text(errors="replace")):
            if "libhexadapt/src" in target or target.startswith("../"):
                why = ("another unit's private header" if "libhexadapt/src" in target else
                       private_include_problem(path, target))
                if why and (rel, target) not in KNOWN:
                    out.append(f"{rel}: includes {target}, {why}")
                continue
            m = re.match(r"hexadapt/([a-z_]+)/", target)
            if not m or unit is None or m.group(1) == unit:
                continue
            other = m.group(1)
            if other not in LEVEL or unit not in LEVEL:
                out.append(f"{rel}: unit {unit} or {other} has no level in this check")
            elif LEVEL[other] >= LEVEL[unit] and (rel, other) not in KNOWN:
                out.append(f"{rel}: {unit} includes {target} ({other} is not to its left)")
    for rel, other in sorted(KNOWN):
        text = (ROOT / rel).read_text() if (ROOT / rel).exists() else ""
        if f'"hexadapt/{other}/' not in text and f'"{other}"' not in text:
            out.append(f"{rel}: listed as a known crossing into {other}, which it no longer is: "
                       "remove it from KNOWN")
    return out


if __name__ == "__main__":
    found = problems()
    for p in found:
        print(p)
    print(f"layering: {len(found)} problem(s)")
    sys.exit(1 if found else 0)
