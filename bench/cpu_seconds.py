#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The CPU time of one run of a command, to the millisecond.

    bench/cpu_seconds.py [--user] [--stderr FILE] CMD [ARG...]

Runs CMD with its output thrown away (its errors to FILE, or to ours),
and prints the seconds of CPU time the kernel charged it and its children,
user plus system (--user: user only), with three decimals. GNU time's %U
and %S print two, which is 3% of a 0.3 s render: the comparison scripts
(bench/vs-povray, bench/vs-raytracercpu) time with this instead. When CMD
fails, prints nothing and exits with its status (128 + the signal's number
when a signal ended it).
"""
import os
import subprocess
import sys


def main(argv):
    user_only = False
    stderr_path = None
    while argv and argv[0].startswith("--"):
        if argv[0] == "--user":
            user_only = True
            argv = argv[1:]
        elif argv[0] == "--stderr" and len(argv) >= 2:
            stderr_path = argv[1]
            argv = argv[2:]
        elif argv[0] == "--":
            argv = argv[1:]
            break
        else:
            print(f"cpu_seconds.py: unknown option '{argv[0]}' (see the file's header)", file=sys.stderr)
            return 2
    if not argv:
        print("cpu_seconds.py: give the command to time", file=sys.stderr)
        return 2
    err = open(stderr_path, "wb") if stderr_path else None
    try:
        child = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=err)
    except OSError as e:
        print(f"cpu_seconds.py: cannot run '{argv[0]}': {e.strerror}", file=sys.stderr)
        return 127
    # wait4 gives the rusage of this child alone, its own children included.
    _, status, usage = os.wait4(child.pid, 0)
    child.returncode = 0  # reaped here; keep Popen from waiting again
    if err:
        err.close()
    code = os.waitstatus_to_exitcode(status)
    if code != 0:
        return code if code > 0 else 128 - code
    seconds = usage.ru_utime if user_only else usage.ru_utime + usage.ru_stime
    print(f"{seconds:.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
