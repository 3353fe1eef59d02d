#!/usr/bin/env python3
"""Compares two text files as the golden tests do (tests/golden/golden_test.cpp): the
words must match exactly, the numbers to 1e-9 relative or one unit in the last printed
digit. UFF dates (26-NOV-26 20:00:14) are masked. Exit 0 when the same, 1 with the first
difference on stdout. Round-off differs between CPUs (an EPYC's SIMD paths move the
12th digit of an FRF near zero); a byte comparison failed there on unchanged code."""
import re
import sys

NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
DATE = re.compile(r"\d{2}-[A-Z]{3}-\d{2} [0-9:]{8}")


def last_digit(text):
    mantissa = re.split(r"[eE]", text)[0]
    exponent = int(re.split(r"[eE]", text)[1]) if re.search(r"[eE]", text) else 0
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return 10.0 ** (exponent - decimals)


def tokens(line):
    out, at = [], 0
    for m in NUMBER.finditer(line):
        out.append(("w", line[at:m.start()]))
        out.append(("n", m.group()))
        at = m.end()
    out.append(("w", line[at:]))
    return out


def main(a_path, b_path):
    with open(a_path, encoding="utf-8", errors="replace") as f:
        a = DATE.sub("<date>", f.read()).splitlines()
    with open(b_path, encoding="utf-8", errors="replace") as f:
        b = DATE.sub("<date>", f.read()).splitlines()
    if len(a) != len(b):
        print(f"{len(a)} lines against {len(b)}")
        return 1
    for k, (x, y) in enumerate(zip(a, b), 1):
        tx, ty = tokens(x), tokens(y)
        same = len(tx) == len(ty)
        for (kx, vx), (ky, vy) in zip(tx, ty) if same else []:
            if kx != ky or (kx == "w" and vx != vy):
                same = False
            elif kx == "n":
                fx, fy = float(vx), float(vy)
                tol = 1e-9 * max(abs(fx), abs(fy)) + 1.000001 * max(last_digit(vx), last_digit(vy))
                same = same and abs(fx - fy) <= tol
        if not same:
            print(f"line {k}:\n  committed: {x}\n  new:       {y}")
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
