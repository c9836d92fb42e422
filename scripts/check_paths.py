#!/usr/bin/env python3
"""Fails, listing them, where a comment of the code or the prose of a page names a file of the tree
that does not exist (ctest: file_paths).

Looked at: the comments of C++, CMake, Python, shell and JavaScript files, and the prose and links of
the Markdown pages but CHANGELOG.md (not their code blocks, whose commands name the files they
write). A name with a folder (narrowphase/pairs.h, ../world.md) must exist from the repository's
root, from the file's folder or one above it, or, for a public header, under include/. In comments,
a bare name of code or a page (pairs.h) must be some file's name; a page's bare names are the files
its examples write. Patterns (*_cores.cpp) and placeholders in capitals (OUT.html) are not names."""
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
NAME = re.compile(r'(?<![\w./@*-])((?:\.\./|\./)?(?:[\w-]+/)*[\w-]+(?:\.[\w-]+)*\.(?:h|cpp|md|py|sh|mjs|cmake|in|html|json|txt))(?![\w/-])')
COMMENT = {'.h': r'//(.*)', '.cpp': r'//(.*)', '.mjs': r'//(.*)', '.py': r'#(.*)', '.sh': r'#(.*)',
           '.txt': r'#(.*)', '.cmake': r'#(.*)'}


def tracked():
    out = subprocess.run(['git', 'ls-files'], cwd=ROOT, capture_output=True, text=True, check=True).stdout
    return [ROOT / line for line in out.splitlines() if not line.startswith(('tests/fuzz/corpus/', 'bench/results/'))]


def prose(text):
    """The lines of a page outside its fenced blocks and inline code spans that hold commands."""
    inside = False
    for number, line in enumerate(text.split('\n'), 1):
        if line.startswith('```'):
            inside = not inside
            continue
        if not inside:
            yield number, line


def comments(path, text):
    pattern = COMMENT.get(path.suffix) or (r'#(.*)' if path.name == 'CMakeLists.txt' else None)
    if pattern is None:
        return
    for number, line in enumerate(text.split('\n'), 1):
        match = re.search(pattern, line)
        if match:
            yield number, match.group(1)


def exists(name, path, names):
    if '/' not in name.lstrip('./'):
        return pathlib.PurePath(name).name in names
    bases = [ROOT, ROOT / 'include', path.parent] + list(path.parent.parents)
    return any((base / name).exists() for base in bases)


def checked(name, page):
    """Whether a name found is one to check: a name of the tree, not a pattern's part, a placeholder or
    a page's example file."""
    stem = pathlib.PurePath(name).name.split('.')[0]
    if stem.isupper():
        return False
    if '/' in name.lstrip('./'):
        return True
    return not page and pathlib.PurePath(name).suffix in ('.h', '.cpp', '.md', '.py', '.mjs')


def problems():
    files = tracked()
    names = {f.name for f in files}
    found = []
    for path in files:
        if path.suffix not in ('.md', '.h', '.cpp', '.mjs', '.py', '.sh', '.cmake') and path.name != 'CMakeLists.txt':
            continue
        if path.name == 'CHANGELOG.md':
            continue
        text = path.read_text(errors='replace')
        lines = prose(text) if path.suffix == '.md' else comments(path, text)
        for number, line in lines:
            if path.suffix == '.md':
                line = re.sub(r'https?://\S+', '', line)
            for name in NAME.findall(line):
                if checked(name, path.suffix == '.md') and not exists(name, path, names):
                    found.append(f'{path.relative_to(ROOT)}:{number}: names {name}, which does not exist')
    return found


if __name__ == '__main__':
    found = problems()
    for line in found:
        print(line)
    sys.exit(1 if found else 0)
