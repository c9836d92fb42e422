#!/usr/bin/env python3
"""Checks the module boundaries of the tree's #include lines (ctest: include_boundaries).

- A public header (include/collide2d/) includes only public headers and system headers.
- A library module (shapes, broadphase, narrowphase, engine) reaches another module's private headers
  only through that module's declared internal interface, <module>/internal.h, or the registry of
  shape kinds, shapes/kinds.h.
- The command line and its libraries (tools/: scenes, the replay page) and the examples use the public
  headers, those libraries, the registry of shape kinds (its grammar and fields) and, for the command
  line's --method, the baselines library's header; nothing else private.
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
MODULES = ('shapes', 'broadphase', 'narrowphase', 'engine')
REGISTRY = 'shapes/kinds.h'
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)


def problems():
    found = []
    for path in sorted(ROOT.rglob('*')):
        if path.suffix not in ('.h', '.cpp') or 'build' in path.relative_to(ROOT).parts[0]:
            continue
        rel = path.relative_to(ROOT).as_posix()
        top = rel.split('/')[0]
        for kind, target in INCLUDE.findall(path.read_text(errors='replace')):
            first = target.split('/')[0]
            if rel.startswith('include/collide2d/'):
                if kind == '"' or (first in MODULES + ('tools', 'tests', 'bench')):
                    found.append(f'{rel}: public header includes {target}')
            elif top in MODULES:
                if first in MODULES and first != top and target not in (f'{first}/internal.h', REGISTRY):
                    found.append(f'{rel}: includes {target}, private to {first}/ (use {first}/internal.h)')
            elif top in ('tools', 'examples'):
                allowed = target.startswith('tools/') or target.startswith('examples/') or \
                    target == REGISTRY and top == 'tools' or \
                    target == 'narrowphase/baselines/baselines.h' and top == 'tools'
                if first in MODULES + ('tests', 'bench') and not allowed:
                    found.append(f'{rel}: includes {target}, private to the library')
    return found


if __name__ == '__main__':
    found = problems()
    for line in found:
        print(line)
    sys.exit(1 if found else 0)
