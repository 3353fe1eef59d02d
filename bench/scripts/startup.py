#!/usr/bin/env python3
"""Whole-process time and peak memory of mmvlab commands (docs/benchmarks.md, start-up).

    bench/scripts/startup.py build/mmvlab            # the table's commands
    bench/scripts/startup.py build/mmvlab modes --segments 64
"""
import resource
import subprocess
import sys
import time

COMMANDS = [["--version"], ["modes", "--segments", "8"], ["modes", "--segments", "16"], ["check"], ["frf", "--segments", "8"]]


def measure(binary, args, runs=15):
    times = []
    peak = 0
    for _ in range(runs):
        t = time.perf_counter()
        p = subprocess.Popen([binary] + args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        _, status, usage = __import__("os").wait4(p.pid, 0)
        times.append(time.perf_counter() - t)
        peak = max(peak, usage.ru_maxrss)
        if status != 0:
            sys.exit("%s %s failed (status %d)" % (binary, " ".join(args), status))
    times.sort()
    return times[len(times) // 2], times[0], peak // 1024


def main():
    binary = sys.argv[1] if len(sys.argv) > 1 else "build/mmvlab"
    for args in [sys.argv[2:]] if len(sys.argv) > 2 else COMMANDS:
        median, best, mb = measure(binary, args)
        print("%-28s median %.3f s  min %.3f s  peak %d MB" % (" ".join(args), median, best, mb))


if __name__ == "__main__":
    main()
