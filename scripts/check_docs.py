#!/usr/bin/env python3
"""Runs what README.md and docs/ show (ctest: docs). Every fenced block carries a marker comment on
the line above it, and the test fails on a block without one:

  <!-- test: run -->        a shell session: each `$ command` runs in bash, and its output must be
                            the lines that follow it, exactly;
  <!-- test: form -->       the same, where the placeholders <number>, <ms> and <text> in the shown
                            output stand for what varies from run to run (timings);
  <!-- test: file NAME -->  the block is written to NAME, for the commands that follow to read;
  <!-- test: copy PATH -->  the block is the source tree's file PATH, exactly (so that a page and an
                            example share one source), written to PATH for the commands that follow;
  <!-- test: compile -->    a C++ program, compiled against the installed package with -Wall -Wextra
                            -Werror and run; an `output` block right after it holds what it prints;
  <!-- test: compile collide2d-replay --> the same, linked with a module's pkg-config package too;
  <!-- test: output -->     the output of the program above;
  <!-- test: not run (WHY) --> set-up and benchmark commands, which take minutes or install
                            packages; WHY says which.

Each page runs in a scratch folder of its own, in order, with the build's programs on PATH; in
commands, /opt/collide2d stands for the folder the test installed the package in, and
~/src/collide2d for the source tree.

  check_docs.py --bin DIR [--bin DIR...] --prefix INSTALLED_PREFIX --source ROOT FILE.md...
"""
import argparse
import os
import pathlib
import re
import subprocess
import sys
import tempfile

FENCE = re.compile(r'^```([\w+-]*)\s*$')
MARKER = re.compile(r'^<!-- test: (run|form|file \S+|copy \S+|compile(?: \S+)*|output|not run \(.+\)) -->\s*$')
PLACEHOLDERS = {'<number>': r'-?[0-9][0-9.,e+-]*', '<ms>': r'[0-9.]+', '<text>': r'.*'}


def blocks(path):
    """(marker, language, lines, line number) for each fenced block of the page."""
    lines = path.read_text().split('\n')
    out = []
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        start = i
        j = i + 1
        while j < len(lines) and lines[j].strip() != '```':
            j += 1
        k = start - 1
        while k >= 0 and not lines[k].strip():
            k -= 1
        marker = MARKER.match(lines[k]) if k >= 0 else None
        out.append((marker.group(1) if marker else None, m.group(1), lines[start + 1:j], start + 1))
        i = j + 1
    return out


def session(lines):
    """[(command, expected output lines)] of a shell session."""
    steps = []
    for line in lines:
        if line.startswith('$ '):
            steps.append((line[2:], []))
        elif steps:
            steps[-1][1].append(line)
        else:
            raise ValueError('output before the first $ command')
    return steps


def matches(shown, got, form):
    if not form:
        return shown == got
    if len(shown) != len(got):
        return False
    for s, g in zip(shown, got):
        pattern = re.escape(s)
        for word, regex in PLACEHOLDERS.items():
            pattern = pattern.replace(re.escape(word), regex)
        if not re.fullmatch(pattern, g):
            return False
    return True


def run_page(page, args, failures):
    work = pathlib.Path(tempfile.mkdtemp(prefix='docs-'))
    env = dict(os.environ)
    env['PATH'] = os.pathsep.join(args.bin + [env.get('PATH', '')])
    env['COLLIDE2D_SOURCE'] = args.source
    # The pages show mpirun as a user runs it; the tests run as root, which Open MPI refuses unless told.
    env['OMPI_ALLOW_RUN_AS_ROOT'] = env['OMPI_ALLOW_RUN_AS_ROOT_CONFIRM'] = '1'
    found = blocks(page)
    for index, (marker, language, lines, number) in enumerate(found):
        where = f'{page}:{number}'
        if marker is None:
            failures.append(f'{where}: a fenced block without a <!-- test: ... --> marker')
        elif marker in ('run', 'form'):
            for command, shown in session(lines):
                command = command.replace('/opt/collide2d', args.prefix).replace('~/src/collide2d', args.source)
                result = subprocess.run(['bash', '-o', 'pipefail', '-c', command],
                                        cwd=work, env=env,
                                        capture_output=True, text=True)
                got = result.stdout.rstrip('\n').split('\n') if result.stdout.strip() else []
                shown = shown[:-1] if shown and not shown[-1] else shown
                if not matches(shown, got, marker == 'form'):
                    failures.append(f'{where}: `{command}` printed\n' + '\n'.join(got) + '\ninstead of\n' +
                                    '\n'.join(shown) + (f'\n(stderr: {result.stderr.strip()})' if result.stderr else ''))
        elif marker.startswith('file '):
            (work / marker[5:]).write_text('\n'.join(lines) + '\n')
        elif marker.startswith('copy '):
            text = '\n'.join(lines) + '\n'
            source = pathlib.Path(args.source) / marker[5:]
            if not source.is_file() or source.read_text() != text:
                failures.append(f'{where}: the block is not {marker[5:]} as the source tree holds it')
            (work / marker[5:]).parent.mkdir(parents=True, exist_ok=True)
            (work / marker[5:]).write_text(text)
        elif marker.split()[0] == 'compile':
            source = work / f'snippet_{number}.cpp'
            source.write_text('\n'.join(lines) + '\n')
            binary = work / f'snippet_{number}'
            flags = subprocess.run(['pkg-config', '--cflags', '--libs', '--static'] + marker.split()[1:] + ['collide2d'],
                                   capture_output=True,
                                   text=True, env=dict(env, PKG_CONFIG_PATH=str(pathlib.Path(args.prefix) / 'lib' / 'pkgconfig')),
                                   check=True).stdout.split()
            build = subprocess.run([args.cxx, '-std=c++20', '-O1', '-Wall', '-Wextra', '-Wpedantic', '-Werror', str(source), '-o',
                                    str(binary)] + flags, capture_output=True, text=True)
            if build.returncode != 0:
                failures.append(f'{where}: the snippet does not compile cleanly:\n{build.stderr}')
                continue
            result = subprocess.run([str(binary)], cwd=work, capture_output=True, text=True)
            if result.returncode != 0:
                failures.append(f'{where}: the snippet exits with status {result.returncode}')
            following = found[index + 1] if index + 1 < len(found) else None
            if following and following[0] == 'output':
                got = result.stdout.rstrip('\n').split('\n') if result.stdout.strip() else []
                if got != following[2]:
                    failures.append(f'{where}: the snippet printed\n' + '\n'.join(got) + '\ninstead of\n' +
                                    '\n'.join(following[2]))
        elif marker == 'output':
            previous = found[index - 1][0] if index > 0 else None
            if not previous or previous.split()[0] != 'compile':
                failures.append(f'{where}: an output block must follow a compiled snippet')
    return len(found)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument('--bin', action='append', default=[])
    parser.add_argument('--prefix', required=True)
    parser.add_argument('--source', required=True)
    parser.add_argument('--cxx', default='c++')
    parser.add_argument('pages', nargs='+')
    args = parser.parse_args()
    args.bin = [str(pathlib.Path(b).resolve()) for b in args.bin]
    args.prefix = str(pathlib.Path(args.prefix).resolve())
    failures = []
    total = 0
    for page in args.pages:
        total += run_page(pathlib.Path(page), args, failures)
    for f in failures:
        print(f + '\n')
    print(f'{total} blocks in {len(args.pages)} pages, {len(failures)} failures')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
