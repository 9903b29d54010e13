#!/usr/bin/python3
"""Interrupts a run with a signal and checks that it stops cleanly and continues exactly.

    interrupt_run.py --signal TERM|INT --to process|ranks|rank1|launcher|group --exit-code N
                     --output DIR --after REGEX [--reference DIR --compare FILE ...] [--stale]
                     [--no-restart]
                     -- COMMAND [ARGS...]

Runs COMMAND --output DIR; once a line of its output matches REGEX, sends the signal to
the process itself (process), to every rank under mpiexec (ranks, as a batch system
does), to the second rank only (rank1), to mpiexec alone (launcher), or to mpiexec's
process group (group, as Ctrl-C in a terminal does; Open MPI puts each rank in a group of
its own). Then checks: the exit code, one "interrupted by SIG..." line, summary.json's
status "interrupted" and its time, no rank running 0.5 s after the launcher returned and
no file written after it; with --stale, plants the temporary files a killed writer leaves
(of a finished process, and of a live one, which must stay) and checks that the restart
removes the former. Last, COMMAND --restart DIR must finish (unless --no-restart), and
every --compare file must equal the one in --reference byte for byte.
"""
import argparse
import json
import os
import re
import signal
import subprocess
import sys
import time


def fail(message):
    print("interrupt_run: FAIL: " + message)
    sys.exit(1)


def children(pid, name):
    """The processes whose parent is `pid` and whose name is `name` (cut as /proc cuts it)."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % entry) as stat:
                fields = stat.read()
        except OSError:
            continue
        comm = fields[fields.index("(") + 1:fields.rindex(")")]
        parent = int(fields[fields.rindex(")") + 2:].split()[1])
        if parent == pid and comm == name[:15]:
            found.append(int(entry))
    return sorted(found)


def running(pid):
    """Whether `pid` exists and is not a zombie (an exited process not yet reaped)."""
    try:
        with open("/proc/%d/stat" % pid) as stat:
            fields = stat.read()
    except OSError:
        return False
    return fields[fields.rindex(")") + 2] != "Z"


def dead_pid():
    """A process id no process has now."""
    pid = 4000000
    while os.path.exists("/proc/%d" % pid):
        pid -= 1
    return pid


def interrupt(args, command):
    proc = subprocess.Popen(command + ["--output", args.output], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, start_new_session=True)
    number = getattr(signal, "SIG" + args.signal)
    after = re.compile(args.after)
    name = os.path.basename(next(c for c in command if not c.startswith("-") and "mpiexec" not in c
                                 and "mpirun" not in c and not c.isdigit()))
    lines, ranks, sent = [], [], False
    for line in proc.stdout:
        lines.append(line)
        if not sent and after.search(line):
            ranks = children(proc.pid, name) if args.to != "process" else [proc.pid]
            if not ranks:
                fail("found no process named %s under %d" % (name, proc.pid))
            targets = {"process": ranks, "ranks": ranks, "rank1": ranks[-1:], "launcher": [proc.pid]}
            if args.to == "group":
                os.killpg(proc.pid, number)
            else:
                for pid in targets[args.to]:
                    os.kill(pid, number)
            sent = True
    code = proc.wait()
    output = "".join(lines)
    print(output)
    if not sent:
        fail("no line matched %r: the run ended before the signal" % args.after)
    # mpiexec may return as soon as one rank has exited non-zero; the others must follow
    # within moments (their files are complete by then: the ranks exit only after all agree).
    deadline = time.monotonic() + 0.5
    alive = [pid for pid in ranks if running(pid)]
    while alive and time.monotonic() < deadline:
        time.sleep(0.01)
        alive = [pid for pid in ranks if running(pid)]
    if alive:
        fail("processes %s still run 0.5 s after the launcher returned" % alive)
    return code, output


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--signal", choices=["TERM", "INT"], required=True)
    parser.add_argument("--to", choices=["process", "ranks", "rank1", "launcher", "group"], default="process")
    parser.add_argument("--exit-code", type=int, required=True)
    parser.add_argument("--output", required=True)
    parser.add_argument("--after", required=True)
    parser.add_argument("--reference")
    parser.add_argument("--compare", nargs="*", default=[])
    parser.add_argument("--stale", action="store_true")
    parser.add_argument("--no-restart", action="store_true")
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    subprocess.run(["rm", "-rf", args.output], check=True)

    code, output = interrupt(args, command)
    if code != args.exit_code:
        fail("exit code %d, expected %d" % (code, args.exit_code))
    # Under mpiexec the ranks may see the signal mpiexec forwards (SIGTERM) instead.
    said = re.findall(r"interrupted by (SIG[A-Z]+) at (t|tau) = ([0-9.e+-]+)", output)
    if len(said) != 1:
        fail("expected one 'interrupted by SIG...' line, found %d" % len(said))
    if args.to in ("process", "ranks", "rank1") and said[0][0] != "SIG" + args.signal:
        fail("the line names %s, expected SIG%s" % (said[0][0], args.signal))
    checkpoint = os.path.join(args.output, "checkpoint.h5")
    if not os.path.exists(checkpoint):
        fail("no checkpoint.h5 in " + args.output)
    before = os.stat(checkpoint).st_mtime_ns
    with open(os.path.join(args.output, "summary.json")) as f:
        summary = json.load(f)
    if summary["status"] != "interrupted":
        fail("summary.json says %r, expected 'interrupted'" % summary["status"])
    if abs(summary["time"] - float(said[0][2])) > 1e-5 * max(1.0, abs(summary["time"])):
        fail("summary.json's time %r is not the %s the line names" % (summary["time"], said[0][2]))
    time.sleep(1.0)  # a rank that outlived the launcher would write again by now
    if os.stat(checkpoint).st_mtime_ns != before:
        fail("checkpoint.h5 was written after the launcher returned")

    if args.no_restart:
        print("interrupt_run: OK (stopped at %s = %s, exit code %d)" % (said[0][1], said[0][2], code))
        return
    planted = []
    if args.stale:
        dead, live = dead_pid(), os.getpid()
        planted = ["checkpoint.h5.tmp.%d" % dead, "snapshots.h5.tmp.%d" % dead, "summary.json.tmp.%d" % dead]
        for name in planted + ["metrics.csv.tmp.%d" % live]:
            with open(os.path.join(args.output, name), "w") as f:
                f.write("left by a killed writer")

    restart = subprocess.run(command + ["--restart", args.output], stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True)
    print(restart.stdout)
    if restart.returncode != 0:
        fail("the restart exited with %d" % restart.returncode)
    left = [name for name in planted if os.path.exists(os.path.join(args.output, name))]
    if left:
        fail("the restart left the stale temporary files %s" % left)
    if args.stale:
        live_file = os.path.join(args.output, "metrics.csv.tmp.%d" % os.getpid())
        if not os.path.exists(live_file):
            fail("the restart removed the temporary file of a live process")
        os.remove(live_file)
    for name in args.compare:
        with open(os.path.join(args.output, name), "rb") as a, open(os.path.join(args.reference, name), "rb") as b:
            if a.read() != b.read():
                fail("%s differs from the uninterrupted run's" % name)
    print("interrupt_run: OK (stopped at %s = %s, exit code %d)" % (said[0][1], said[0][2], code))


if __name__ == "__main__":
    main()
