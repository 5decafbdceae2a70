#!/bin/sh
# Checks that every ```cpp block of a document appears verbatim in a source file, so that the code a
# guide quotes is code that is compiled and run (docs/integration.md quotes
# examples/minimal_host/main.cpp):
#
#   tests/common/check_doc_snippets.sh docs/integration.md examples/minimal_host/main.cpp
#
# A block matches when its lines, each stripped of leading and trailing whitespace, are consecutive lines
# of the source, stripped the same way (blank lines included). Fails naming each block that does not
# match and its first line that does not follow; fails too when the document has no ```cpp block.
# Exit status: 0 all blocks found, 1 some block not found, 2 usage or unreadable file.
if [ "$#" -ne 2 ]; then
    echo "usage: $0 DOCUMENT.md SOURCE" >&2
    exit 2
fi
exec python3 - "$1" "$2" <<'EOF'
import sys

doc_path, source_path = sys.argv[1], sys.argv[2]
try:
    with open(doc_path, encoding="utf-8") as f:
        doc = f.read().splitlines()
    with open(source_path, encoding="utf-8") as f:
        source = [line.strip() for line in f.read().splitlines()]
except OSError as e:
    print(f"check_doc_snippets: {e}", file=sys.stderr)
    sys.exit(2)

# The ```cpp blocks: (line number of the fence, stripped lines).
blocks, current, start = [], None, 0
for number, line in enumerate(doc, 1):
    fence = line.strip()
    if current is None:
        if fence == "```cpp":
            current, start = [], number
    elif fence == "```":
        blocks.append((start, current))
        current = None
    else:
        current.append(line.strip())
if current is not None:
    print(f"{doc_path}:{start}: ```cpp block is not closed", file=sys.stderr)
    sys.exit(1)
if not blocks:
    print(f"{doc_path}: no ```cpp block to check", file=sys.stderr)
    sys.exit(1)


def matched_prefix(block):
    """The most leading lines of `block` found consecutively in the source."""
    best = 0
    for i in range(len(source)):
        n = 0
        while n < len(block) and i + n < len(source) and source[i + n] == block[n]:
            n += 1
        best = max(best, n)
        if best == len(block):
            break
    return best


failed = 0
for start, block in blocks:
    n = matched_prefix(block)
    if n < len(block):
        failed += 1
        print(f"{doc_path}:{start + 1 + n}: not in {source_path} after the block's previous lines: "
              f"{block[n]!r}", file=sys.stderr)
if failed:
    print(f"check_doc_snippets: {failed} of {len(blocks)} ```cpp blocks of {doc_path} are not in "
          f"{source_path}", file=sys.stderr)
    sys.exit(1)
print(f"check_doc_snippets: all {len(blocks)} ```cpp blocks of {doc_path} are in {source_path}")
EOF
