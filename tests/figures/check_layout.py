"""The figure harness's judge (tests/figures/figure_layout.sh).

usage: check_layout.py LAYOUT.jsonl...

Each line is one PNG's layout (renders/layout.hpp). A figure fails when a text box leaves
the canvas, two text boxes overlap (by more than a pixel's rim), a legend entry was not
drawn, its series shows fewer than MIN_PIXELS pixels in its own colour inside the frame
(drawn over by another), or two legend entries share a colour and a style (a
limit dashed in its quantity's colour is its pair, not a clash). Prints every defect,
"command: file: what", and exits 1 if there is any.
"""
import json
import os
import sys

MIN_PIXELS = 30


def overlap(a, b):
    """Overlap area of two boxes [x, y, w, h], each shrunk by one pixel on every side."""
    ax0, ay0, ax1, ay1 = a[0] + 1, a[1] + 1, a[0] + a[2] - 1, a[1] + a[3] - 1
    bx0, by0, bx1, by1 = b[0] + 1, b[1] + 1, b[0] + b[2] - 1, b[1] + b[3] - 1
    return max(0, min(ax1, bx1) - max(ax0, bx0)) * max(0, min(ay1, by1) - max(ay0, by0))


def defects(fig):
    out = []
    w, h = fig["width"], fig["height"]
    texts = fig["texts"]
    for t, x, y, tw, th in texts:
        if x < 0 or y < 0 or x + tw > w or y + th > h:
            out.append(f"text {t!r} leaves the {w}x{h} canvas at [{x}, {y}, {tw}, {th}]")
    for i in range(len(texts)):
        for j in range(i + 1, len(texts)):
            if overlap(texts[i][1:], texts[j][1:]) > 0:
                out.append(f"text {texts[i][0]!r} overlaps {texts[j][0]!r}")
    seen = {}
    for label, b, g, r, style, pixels in fig["legend"]:
        if pixels < 0:
            out.append(f"legend entry {label!r} not drawn (no room)")
        elif pixels < MIN_PIXELS:
            out.append(f"legend entry {label!r}: its series shows {pixels} pixels in its colour (hidden)")
        # A limit drawn dashed in its quantity's colour (a joint's capacity) is that
        # quantity's pair, not a second series in the same colour.
        if (b, g, r, style) in seen:
            out.append(f"legend entries {seen[(b, g, r, style)]!r} and {label!r} share a colour and a style")
        seen.setdefault((b, g, r, style), label)
    return out


def main():
    found = 0
    figures = 0
    for path in sys.argv[1:]:
        command = os.path.basename(path).removesuffix(".jsonl")
        with open(path) as f:
            for line in f:
                fig = json.loads(line)
                figures += 1
                for d in defects(fig):
                    found += 1
                    print(f"{command}: {fig['file']}: {d}")
    print(f"figure layout: {figures} figures, {found} defects")
    if figures == 0:
        print("figure layout: no figure was logged")
        sys.exit(1)
    sys.exit(1 if found else 0)


if __name__ == "__main__":
    main()
