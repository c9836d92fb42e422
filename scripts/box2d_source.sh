#!/usr/bin/env bash
# Unpacks Box2D 2.4.1's source, from Debian's source package, into the folder given (default
# build/box2d-source), for the 16-gon benchmark (bench/CMakeLists.txt, COLLIDE2D_BOX2D_SOURCE).
# apt reads a private deb-src list made from the machine's deb lines and keeps its package lists
# in a temporary folder: the machine's apt configuration is left as it was.
set -euo pipefail
dest=${1:-build/box2d-source}
if [[ -f $dest/include/box2d/b2_settings.h ]]; then
  echo "$dest"
  exit 0
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/lists/partial" "$work/parts"
cat /etc/apt/sources.list.d/*.sources 2>/dev/null | sed 's/^Types: deb$/Types: deb-src/' > "$work/parts/src.sources"
sed -n 's/^deb /deb-src /p' /etc/apt/sources.list 2>/dev/null > "$work/parts/src.list" || true
apt_options=(-o "Dir::Etc::sourcelist=$work/parts/src.list" -o "Dir::Etc::sourceparts=$work/parts"
             -o "Dir::State::Lists=$work/lists" -o "APT::Sandbox::User=root")
apt-get "${apt_options[@]}" update >&2
(cd "$work" && apt-get "${apt_options[@]}" source --download-only box2d=2.4.1-3 >&2)
mkdir -p "$dest"
tar xzf "$work"/box2d_2.4.1.orig.tar.gz -C "$dest" --strip-components=1
echo "$dest"
