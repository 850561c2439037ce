#!/usr/bin/env python3
"""A stop signal sent to crosscheck alone stops the run it started too.

Usage: crosscheck_stop_test.py CROSSCHECK WORKDIR

crosscheck micro runs with a stand-in for YADE (a shell script that records its pid and
sleeps); once the stand-in runs, SIGTERM, then (in a second round) SIGINT is sent to
crosscheck's pid only, not its process group. Passes when crosscheck ends by that signal
within seconds and the stand-in is gone (child_process.hpp). Before, SIGTERM left the
stand-in running, orphaned, and SIGINT was ignored until the stand-in ended.
"""
import os
import signal
import subprocess
import sys
import time

FAKE_YADE = """#!/bin/sh
# stands in for yade (crosscheck_stop_test.py): records its pid, then runs until stopped
echo $$ > "$(dirname "$0")/fake-yade.pid"
exec sleep 300
"""


def wait_for(predicate, seconds):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(0.05)
    return predicate()


def alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    # a zombie not yet reaped by init counts as gone
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().split(")")[-1].split()[0] != "Z"
    except FileNotFoundError:
        return False


def one_round(crosscheck, work, sig):
    os.makedirs(work, exist_ok=True)
    fake = os.path.join(work, "fake-yade")
    pid_file = os.path.join(work, "fake-yade.pid")
    with open(fake, "w") as f:
        f.write(FAKE_YADE)
    os.chmod(fake, 0o755)
    if os.path.exists(pid_file):
        os.remove(pid_file)
    proc = subprocess.Popen([crosscheck, "micro", "--yade", fake, "--workdir", os.path.join(work, "runs")],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        if not wait_for(lambda: os.path.exists(pid_file) and open(pid_file).read().strip(), 120):
            print(f"FAIL: the stand-in for YADE never started\n{proc.stdout.read() if proc.poll() is not None else ''}")
            return False
        fake_pid = int(open(pid_file).read())
        os.kill(proc.pid, sig)  # crosscheck alone, not its group
        try:
            proc.wait(timeout=30)
        except subprocess.TimeoutExpired:
            print(f"FAIL: {signal.Signals(sig).name}: crosscheck still runs 30 s after the signal")
            return False
        ok = True
        if proc.returncode != -sig:
            print(f"FAIL: {signal.Signals(sig).name}: crosscheck ended with {proc.returncode}, expected {-sig} "
                  f"(killed by the signal)\n{proc.stdout.read()}")
            ok = False
        if not wait_for(lambda: not alive(fake_pid), 10):
            print(f"FAIL: {signal.Signals(sig).name}: the stand-in for YADE (pid {fake_pid}) still runs")
            os.kill(fake_pid, signal.SIGKILL)
            ok = False
        if ok:
            print(f"ok: {signal.Signals(sig).name} stopped crosscheck and its YADE run")
        return ok
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()


def main():
    crosscheck, work = sys.argv[1], sys.argv[2]
    results = [one_round(crosscheck, os.path.join(work, name), sig)
               for name, sig in (("term", signal.SIGTERM), ("int", signal.SIGINT))]
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
