#!/usr/bin/env python3
"""Fails, listing them, where a public declaration has no contract (ctest: contracts).

Every declaration of include/collide2d/*.h outside a private section and a function's body has a
`///` comment: above it, above the group of declarations it belongs to (no blank line between), or
after it on its line (`///<`). Each `///` comment opens with a one-line contract: its first clause
ends on its first line (with '.', ':' or ';'); the details follow. Out-of-class definitions of
members declared above, and the namespace `detail`, are not declarations of the API."""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
DECLARATION = re.compile(r'(template|struct|class|enum|using|inline|constexpr|static|explicit|~|[A-Z]\w*\(|'
                         r'[A-Za-z_][\w:<>,\s\*&]*\s+[\w~]+\s*(\(|=|;|\{))')
SCOPE = re.compile(r'(struct|class|enum|union)\b[^;(]*\{$')


def problems(path):
    found = []
    lines = path.read_text().split('\n')
    documented = False  # the group the line is in has a contract
    private = False
    skip_depth = 0  # inside a function body or namespace detail: braces still open
    continued = False  # the line continues a declaration begun above
    for number, line in enumerate(lines, 1):
        text = line.strip()
        if skip_depth:
            skip_depth += text.count('{') - text.count('}')
            continue
        if text.startswith('///') and not text.startswith('///<'):
            if not lines[number - 2].strip().startswith('///'):
                first = text[3:].strip()
                if not first.startswith('@file') and not re.search(r'[.:;]( |$)|\)$', first):
                    found.append(f'{path.name}:{number}: the contract does not end its first clause on its first line')
            documented = True
            continue
        if not text:
            documented = False
            continue
        if re.match(r'(public|private|protected):', text):
            private = not text.startswith('public')
            continue
        if text.startswith('namespace detail'):
            skip_depth = text.count('{')
            continue
        if text.startswith(('namespace', '#', '//')) or text.startswith('}'):
            if text.startswith('}'):
                documented = False
                private = False if text.startswith('};') and not private else private
            continue
        declaration = not continued and bool(DECLARATION.match(text)) and not text.startswith('friend')
        qualified = re.search(r'\b\w+::\w+\(', text) and not text.startswith(('static', 'using'))
        if declaration and not private and not qualified and not documented and '///<' not in line:
            found.append(f'{path.name}:{number}: no contract for `{text[:70]}`')
        # A body opened here (not a class, struct or enum scope) is skipped to its end.
        opens = text.count('{') - text.count('}')
        if opens > 0 and not SCOPE.search(text):
            skip_depth = opens
        continued = not re.search(r'[;{}]$|^template\b', text)
    return found


if __name__ == '__main__':
    found = [p for path in sorted((ROOT / 'include' / 'collide2d').glob('*.h')) for p in problems(path)]
    for line in found:
        print(line)
    sys.exit(1 if found else 0)
