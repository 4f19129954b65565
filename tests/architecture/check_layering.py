#!/usr/bin/env python3
"""Checks the module layering of docs/architecture.md (issue 21).

1. Includes point one way: core <- rockmass <- physics (mechanics, flow, ...)
   <- coupling <- app. A physics module never includes another one.
2. The framework names no physics: the code (comments left out) of core/,
   of the generic part of coupling/ (the coordinator and the splitting
   scheme) and of app/ never names a physics module (dda, flow, mechanics,
   thermal, continuum) or a field that belongs to one (pressure, aperture,
   flux, contact, fracture, temperature, ...). What a process exchanges or
   writes is declared by the process, by name, and moved without being
   known here.
3. No module tests another module's name: in a physics module's code
   (comments left out) no other module's physics name is asked for or
   compared (`has_physics("mechanics")` in flow/, `name() == "flow"`,
   `intervals.count("thermal")`, ...). A module asks for a field's provider
   (provides(scene, field)) instead, so that a second process that writes
   the same fields (a DEM beside the DDA) is served alike. The physics name
   of a module is its folder's name.

Usage: check_layering.py SOURCE_DIR PHYSICS_MODULE...
       (the physics modules of CMakeLists.txt's FISSURE_PHYSICS_MODULES;
       exit status 1 and one line per problem)
"""
import pathlib
import re
import sys


def allowed_includes(physics):
    """Which top-level folders each folder may include from."""
    allowed = {
        "core": {"core"},
        "rockmass": {"core", "rockmass"},
        "coupling": {"core", "rockmass", "coupling", *physics},
        "app": {"core", "coupling", "app"},
    }
    for module in physics:
        allowed[module] = {"core", "rockmass", module}
    return allowed


# Where no physics may be named: the framework.
FRAMEWORK = ["core/**/*", "coupling/coordinator*", "coupling/splitting*",
             "coupling/field_convergence*", "coupling/relaxation*", "app/**/*"]
# The framework's quantity kinds: the stress kind keeps the word users read
# in messages for Pa ("expected a pressure > 0"); the physics' own kinds
# (temperature, conductivity, ...) live in their modules.
QUANTITIES = {"core/scene/units.h"}

# Words (identifier parts, case-insensitive) that name a physics module or a
# field one of them owns.
PHYSICS_WORDS = {
    "dda", "dem", "flow", "flows", "mechanics", "hydraulic", "hm",
    "thermal", "heat", "continuum", "poroelastic",
    "pressure", "pressures", "aperture", "apertures", "flux", "fluxes",
    "contact", "contacts", "fracture", "fractures", "temperature", "temperatures",
    "viscosity",
}

# A string literal tested as a process name: asked for (has_physics, the
# coupling's maps and lists) or compared.
def name_tests(name):
    literal = re.escape(f'"{name}"')
    return re.compile(
        rf'\b(?:has_physics|count|find|contains|runs_in_pseudo_time)\s*\([^()]*{literal}'
        rf'|[!=]=\s*{literal}|{literal}\s*[!=]=')


INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)
COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)
DOC_PATH = re.compile(r"docs/[\w.-]+\.md")
WORD = re.compile(r"[A-Za-z0-9]+")


def identifier_parts(token):
    """flow_heads -> flow, heads; FractureFlowState -> fracture, flow, state."""
    for part in token.split("_"):
        for piece in re.findall(r"[A-Z]+(?![a-z])|[A-Z]?[a-z]+|[0-9]+", part):
            yield piece.lower()


def sources(root, pattern):
    return [p for p in root.glob(pattern) if p.suffix in (".h", ".cpp") and p.is_file()]


def main():
    root = pathlib.Path(sys.argv[1])
    physics = sys.argv[2:]
    if not physics:
        print("usage: check_layering.py SOURCE_DIR PHYSICS_MODULE...", file=sys.stderr)
        return 2
    allowed_by_module = allowed_includes(physics)
    problems = []

    for module, allowed in allowed_by_module.items():
        for path in sources(root, f"{module}/**/*"):
            for target in INCLUDE.findall(path.read_text()):
                top = target.split("/")[0]
                if top in allowed_by_module and top not in allowed:
                    problems.append(f"{path.relative_to(root)}: includes {target} "
                                    f"({module}/ may include only {', '.join(sorted(allowed))})")

    for pattern in FRAMEWORK:
        for path in sources(root, pattern):
            if str(path.relative_to(root)) in QUANTITIES:
                continue
            code = DOC_PATH.sub("", COMMENT.sub("", path.read_text()))
            for number, line in enumerate(code.splitlines(), 1):
                if line.lstrip().startswith("#include"):
                    continue
                for token in WORD.findall(line):
                    named = sorted({w for w in identifier_parts(token) if w in PHYSICS_WORDS})
                    if named:
                        problems.append(f"{path.relative_to(root)}:{number}: '{token}' names "
                                        f"{', '.join(named)} (the framework names no physics)")

    for module in physics:
        tests = {other: name_tests(other) for other in physics if other != module}
        for path in sources(root, f"{module}/**/*"):
            code = COMMENT.sub("", path.read_text())
            for number, line in enumerate(code.splitlines(), 1):
                for other, pattern in tests.items():
                    if pattern.search(line):
                        problems.append(f"{path.relative_to(root)}:{number}: tests the name "
                                        f"'{other}' (a module asks provides() for a field, never "
                                        f"for another module's name)")

    for p in sorted(set(problems)):
        print(p)
    if not problems:
        print("layering: ok")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
