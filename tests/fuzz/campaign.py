#!/usr/bin/env python3
"""Black-box mutation campaign against the mmvlab command line (issue 16's method).

Mutates the shipped scenes the way a careless or hostile user would (deleted lines,
duplicated keys, numbers replaced by -1, 0, 1e308, nan, .inf, strings, lists and maps,
huge counts, random bytes, invalid UTF-8, anchors, tabs, misspelt keys, truncation) and
runs each through a command. Every run must keep the README's contract:

  * exit 0 with no NaN/inf in standard output, or
  * exit 1 (numerical failure, named), 64, 65, 66, 69 or 73 with one message;
  * exit 65 messages carry file:line:col;
  * no signal, no exit 70 (internal error), no run past the timeout;
  * standard error carries no raw control bytes or invalid UTF-8.

Each break is written to OUT/<n>/ (scene, command, output) so it can be reduced and
added to the regression corpus (tests/fuzz/regressions/). Prints a summary.

  tests/fuzz/campaign.py build/mmvlab --runs 1700 --seed 1 --out /tmp/campaign
"""
import argparse
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "..", "..", "scenes")

REPLACEMENTS = ["-1", "0", "1e308", "-1e308", "nan", ".nan", ".inf", "-.inf", "abc", "'12'", "[1, 2]",
                "{a: 1}", "1e9", "2147483648", "1e-300", "0.5", "~", "true", "", "1e6", "100000"]
NUMBER = re.compile(r"(?<![\w.])-?\d+(\.\d+)?([eE][-+]?\d+)?(?![\w.])")

# Commands with options that keep a healthy run short; the scene decides the rest.
COMMANDS = [
    ["modes"], ["modes", "--json"], ["compare"], ["simulate", "--duration", "0.2"], ["simulate"],
    ["frf", "--points", "200"], ["rom", "--points", "200"],
    ["trade", "--integrators", "rk_merson", "--accuracies", "1e-3", "--segment-ladder", "2", "--duration", "0.1"],
]


def mutate(text: bytes, rng: random.Random) -> bytes:
    lines = text.split(b"\n")
    kind = rng.randrange(12)
    i = rng.randrange(len(lines))
    if kind == 0:  # delete a line
        del lines[i]
    elif kind == 1:  # duplicate a line (often a duplicated key)
        lines.insert(i, lines[i])
    elif kind in (2, 3, 4, 5):  # replace a number
        candidates = [j for j, l in enumerate(lines) if NUMBER.search(l.decode("utf-8", "replace")) and
                      not l.lstrip().startswith(b"#")]
        if candidates:
            j = rng.choice(candidates)
            s = lines[j].decode("utf-8", "replace")
            ms = list(NUMBER.finditer(s))
            m = rng.choice(ms)
            s = s[:m.start()] + rng.choice(REPLACEMENTS) + s[m.end():]
            lines[j] = s.encode()
    elif kind == 6:  # random bytes
        pos = rng.randrange(len(text) + 1)
        junk = bytes(rng.randrange(256) for _ in range(rng.randrange(1, 12)))
        return text[:pos] + junk + text[pos:]
    elif kind == 7:  # invalid UTF-8 in a value
        lines[i] = lines[i] + b" \xff\xfe\xc3("
    elif kind == 8:  # anchors and aliases
        lines.insert(i, b"x: &a {b: *a}" if rng.random() < 0.5 else b"y: *nothing")
    elif kind == 9:  # tabs for indentation
        lines[i] = re.sub(rb"^ +", b"\t", lines[i])
    elif kind == 10:  # misspelt key
        m = re.match(rb"^(\s*)([a-z_0-9]+):", lines[i])
        if m and len(m.group(2)) > 2:
            k = bytearray(m.group(2))
            p = rng.randrange(len(k) - 1)
            k[p], k[p + 1] = k[p + 1], k[p]
            lines[i] = m.group(1) + bytes(k) + lines[i][m.end(2):]
    else:  # truncation
        return text[: rng.randrange(len(text) + 1)]
    return b"\n".join(lines)


def verdict(code, out: bytes, err: bytes, timed_out: bool):
    if timed_out:  # a long run that says how far it is (sim/cli/progress.hpp) is slow, not hung
        return None if re.search(rb"mmvlab: [a-z ,]+: [0-9.e+]+ of ", err) else "hang"
    if code < 0:
        return f"signal {-code}"
    if code == 70:
        return "internal error"
    if code not in (0, 1, 64, 65, 66, 69, 73):
        return f"exit {code}"
    if code == 0 and re.search(rb"(?i)\b(-?nan|-?inf)\b", out) and not re.search(rb"\binf\b.*\(", out):
        return "NaN/inf in output"
    if code == 65 and not re.search(rb":\d+:\d+: ", err):
        return "exit 65 without file:line:col"
    try:
        e = err.decode("utf-8")
    except UnicodeDecodeError:
        return "invalid UTF-8 on stderr"
    if re.search(r"[\x00-\x08\x0b-\x1f\x7f]", e):
        return "control bytes on stderr"
    return None


def run_one(args, n, rng_seed):
    rng = random.Random(rng_seed)
    scenes = sorted(f for f in os.listdir(SCENES) if f.endswith(".yaml"))
    name = rng.choice(scenes)
    with open(os.path.join(SCENES, name), "rb") as f:
        text = f.read()
    for _ in range(rng.choice([1, 1, 1, 2, 3])):
        text = mutate(text, rng)
    cmd = rng.choice(COMMANDS)
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, name)
        with open(path, "wb") as f:
            f.write(text)
        argv = [args.binary, cmd[0], path] + cmd[1:]
        try:
            p = subprocess.run(argv, capture_output=True, timeout=args.timeout)
            code, out, err, to = p.returncode, p.stdout, p.stderr, False
        except subprocess.TimeoutExpired as e:
            code, out, err, to = None, e.stdout or b"", e.stderr or b"", True
    v = verdict(code, out, err, to)
    if v:
        case = os.path.join(args.out, f"{n:05d}")
        os.makedirs(case, exist_ok=True)
        with open(os.path.join(case, name), "wb") as f:
            f.write(text)
        with open(os.path.join(case, "run.txt"), "w") as f:
            f.write(" ".join(["mmvlab", cmd[0], name] + cmd[1:]) + f"\nverdict: {v}\nexit: {code}\n")
        with open(os.path.join(case, "stderr"), "wb") as f:
            f.write(err)
        with open(os.path.join(case, "stdout"), "wb") as f:
            f.write(out[-20000:])
    return code, v, cmd[0]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("binary")
    ap.add_argument("--runs", type=int, default=200)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--out", default="campaign-breaks")
    args = ap.parse_args()
    shutil.rmtree(args.out, ignore_errors=True)
    os.makedirs(args.out)
    with ThreadPoolExecutor(args.jobs) as ex:
        results = list(ex.map(lambda n: run_one(args, n, args.seed * 1000003 + n), range(args.runs)))
    ok = sum(1 for c, v, _ in results if c == 0 and not v)
    clean = sum(1 for c, v, _ in results if c not in (0, None) and not v)
    slow = sum(1 for c, v, _ in results if c is None and not v)
    broken = [(n, v, c) for n, (_, v, c) in enumerate(results) if v]
    print(f"{args.runs} runs: {ok} succeeded, {clean} clean errors, {slow} still running at {args.timeout:g} s "
          f"with progress lines, {len(broken)} broke the contract")
    for n, v, c in broken:
        print(f"  {n:05d} {c}: {v}")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
