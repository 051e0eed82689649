#!/usr/bin/env bash
# Renders every fixture with barytex and with Mesa's llvmpipe (OpenGL via moderngl), compares them
# and rewrites docs/CONFORMANCE.md and docs/conformance/*.png.
#
#   tools/conformance/run.sh [FIXTURES]     # FIXTURES: the folder holding gltf/ (default
#                                           # $BARYTEX_FIXTURES, else ../shared/fixtures)
#
# Needs target/release/barytex (cargo build --release -p barytex) and Python 3 with venv.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
venv="$here/.venv"
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet -r "$here/requirements.txt"
fi
fixtures="${1:-${BARYTEX_FIXTURES:-$root/../shared/fixtures}}"
cd "$root"
exec "$venv/bin/python" "$here/compare.py" --fixtures "$fixtures" --barytex "$root/target/release/barytex" \
    --doc "$root/docs/CONFORMANCE.md" --images "$root/docs/conformance"
