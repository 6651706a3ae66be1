#!/usr/bin/env bash
# scene_docs.sh - keeps the key tables of docs/scene-format.md equal to the
# parameter tables the loader reads (printed by build/scene_keys).
#   tools/scene_docs.sh SCENE_KEYS           check: every section is in the
#                                            docs once, exactly as printed
#   tools/scene_docs.sh SCENE_KEYS --write   rewrite the docs' sections
# A section in the docs is the lines between "<!-- keys: NAME -->" and
# "<!-- /keys -->". Exit 1, naming the section, when a check fails.
set -euo pipefail
tool=${1:?usage: tools/scene_docs.sh SCENE_KEYS [--write]}
mode=${2:-check}
doc="$(cd "$(dirname "$0")/.." && pwd)/docs/scene-format.md"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The docs with every section's body replaced by what the tool prints now.
cp "$doc" "$tmp/new.md"
status=0
while IFS= read -r name; do
    "$tool" "$name" >"$tmp/table.md"
    count=$(grep -c -x -F "<!-- keys: $name -->" "$doc" || true)
    if [ "$count" != 1 ]; then
        echo "scene_docs: docs/scene-format.md has $count sections '<!-- keys: $name -->', not 1" >&2
        status=1
        continue
    fi
    awk -v start="<!-- keys: $name -->" -v table="$tmp/table.md" '
        $0 == start { print; while ((getline line < table) > 0) print line; skip = 1; next }
        skip && $0 == "<!-- /keys -->" { skip = 0 }
        !skip { print }' "$tmp/new.md" >"$tmp/next.md"
    mv "$tmp/next.md" "$tmp/new.md"
done < <("$tool")

if [ "$mode" = --write ]; then
    cp "$tmp/new.md" "$doc"
    exit "$status"
fi
if ! diff -u "$doc" "$tmp/new.md" >"$tmp/diff"; then
    echo "scene_docs: docs/scene-format.md's key tables differ from the code's (tools/scene_docs.sh BUILD/scene_keys --write):" >&2
    cat "$tmp/diff" >&2
    status=1
fi
[ "$status" -ne 0 ] || echo "scene_docs: $("$tool" | wc -l) key tables match the code"
exit "$status"
