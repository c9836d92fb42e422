#!/usr/bin/env python3
"""The public API of collide2d as text: every declaration of include/collide2d/*.h with comments,
private and protected sections and function bodies stripped, one header after another. docs/api.txt
holds the dump of the released API; ctest compares (api_dump), so that an API change is a visible
diff. Regenerate: python3 scripts/api_dump.py > docs/api.txt"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent


def strip_comments(text):
    text = re.sub(r'/\*.*?\*/', '', text, flags=re.S)
    return re.sub(r'//[^\n]*', '', text)


def matching_brace(text, open_at):
    depth = 0
    for i in range(open_at, len(text)):
        if text[i] == '{':
            depth += 1
        elif text[i] == '}':
            depth -= 1
            if depth == 0:
                return i
    raise ValueError('unbalanced braces')


def strip_bodies(text):
    """Replaces each function body by ';' and drops private and protected sections."""
    out = []
    i = 0
    while i < len(text):
        c = text[i]
        if c == '{':
            before = text[:i].rstrip()
            # A function body follows a parameter list, a qualifier or a constructor's initializers.
            if re.search(r'(\)|\bconst|\bnoexcept|\boverride|\)\s*->\s*[\w:<>&\s]+)$', before) and not re.search(
                    r'\b(if|for|while|switch)\s*\(.*\)$', before):
                end = matching_brace(text, i)
                # A constructor's member initializers go with its body.
                joined = ''.join(out)
                m = re.search(r'\)\s*:\s*[^;{}]*$', joined)
                if m:
                    out = [joined[:m.start() + 1]]
                out.append(';')
                i = end + 1
                if i < len(text) and text[i] == ';':
                    i += 1
                continue
        out.append(c)
        i += 1
    text = ''.join(out)
    # private: and protected: sections run to the next access label or the class's closing brace.
    result = []
    hidden = False
    depth = 0
    hidden_depth = 0
    for line in text.split('\n'):
        stripped = line.strip()
        if re.match(r'^(private|protected)\s*:', stripped):
            hidden, hidden_depth = True, depth
            continue
        if re.match(r'^public\s*:', stripped) and depth == hidden_depth:
            hidden = False
        opens, closes = line.count('{'), line.count('}')
        if hidden and depth + opens - closes < hidden_depth:
            hidden = False
        depth += opens - closes
        if not hidden:
            result.append(line)
    return '\n'.join(result)


def normalise(text):
    """One declaration a line, whatever the formatting: preprocessor lines as they are, the rest
    joined and cut after each ';', '{' and '}' and at each access label."""
    lines = []
    code = []

    def flush():
        joined = re.sub(r'\s+', ' ', ' '.join(code)).strip()
        joined = re.sub(r'\{\s*\}', '\0', joined)  # an empty initializer stays on its line
        joined = re.sub(r'\s*([;{}])\s*', r'\1\n', joined)
        joined = re.sub(r'\b(public|private|protected)\s*:(?!:)\s*', r'\1:\n', joined)
        joined = re.sub(r'\s+;', ';', joined)
        lines.extend(l.strip().replace('\0', '{}') for l in joined.split('\n') if l.strip() and l.strip() != ';')
        code.clear()

    for line in text.split('\n'):
        if line.lstrip().startswith('#'):
            flush()
            lines.append(line.strip())
        else:
            code.append(line)
    flush()
    return '\n'.join(lines)


def dump():
    parts = []
    for header in sorted((ROOT / 'include' / 'collide2d').glob('*.h')):
        lines = normalise(strip_bodies(strip_comments(header.read_text()))).split('\n')
        directives = [l for l in lines if l.startswith('#') and not l.startswith('#include')]
        includes = sorted(l for l in lines if l.startswith('#include'))  # their order is formatting
        code = [l for l in lines if not l.startswith('#')]
        text = '\n'.join(directives + includes + code)
        parts.append('// ' + header.relative_to(ROOT).as_posix() + '\n' + text)
    return '\n\n'.join(parts) + '\n'


if __name__ == '__main__':
    if len(sys.argv) == 3 and sys.argv[1] == '--check':
        expected = pathlib.Path(sys.argv[2]).read_text()
        got = dump()
        if got != expected:
            import difflib
            sys.stdout.writelines(difflib.unified_diff(expected.splitlines(True), got.splitlines(True),
                                                       'docs/api.txt', 'include/collide2d/*.h'))
            print('\nThe public API differs from docs/api.txt. If the change is meant, record it '
                  '(python3 scripts/api_dump.py > docs/api.txt), say so in CHANGELOG.md and raise the '
                  'version as include/collide2d/version.h says.')
            sys.exit(1)
        sys.exit(0)
    sys.stdout.write(dump())
