#!/usr/bin/python3
"""Memory per rank of a suspension3d deck as the ranks are added.

  suspension_memory.py --build BUILD [--deck DECK] [--ranks 1,2,4] [--runs DIR]
                       [--set KEY=VALUE ...]

For each number of ranks P (oversubscribed where P exceeds the cores), runs suspension3d on the
deck (default: the margination deck, input/suspension3d/margination/h10-hct0.2.xml) until its
first progress line, which the app prints once the scene is built, the preconditioner blocks
factorised and the output at t = 0 written, then stops the run. Per rank it reports the peak
resident memory (VmHWM of /proc/PID/status), and per P the largest rank's and its ratio to one
rank's. What the first output has not reached (the stiff stage solves, whose Krylov vectors are
replicated) is not in the figure. It names the source tree's version (git describe --always
--dirty), the CPU, and per row the version the app reports (its build may be another's). Exits 1 if a run ends before its first progress line. Debian's /usr/bin/python3.
"""
import argparse
import os
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import accuracy_cost_report as report_helpers  # noqa: E402 (git_sha, cpu_model)

DECK = os.path.join(ROOT, "input", "suspension3d", "margination", "h10-hct0.2.xml")
FIRST_PROGRESS = "t = 0 /"


def app_processes(executable, session):
    """The PIDs of the processes of `executable` in the session `session` (the run's own ranks,
    not another run of the same binary beside it)."""
    pids = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                if os.readlink(f"/proc/{entry}/exe") == executable and os.getsid(int(entry)) == session:
                    pids.append(int(entry))
            except OSError:
                continue
    return sorted(pids)


def peak_resident_mib(pid):
    with open(f"/proc/{pid}/status") as status:
        for line in status:
            if line.startswith("VmHWM:"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


def measure(args, ranks):
    """Every rank's VmHWM (MiB) at the first progress line, and the seconds it took."""
    executable = os.path.realpath(os.path.join(args.build, "apps", "suspension3d", "suspension3d"))
    out = os.path.join(args.runs, f"np{ranks}")
    os.makedirs(out, exist_ok=True)
    command = ["mpiexec", "-n", str(ranks), "--oversubscribe", executable, args.deck,
               "--set", f"Output/Directory={os.path.join(out, 'output')}"]
    for setting in args.set:
        command += ["--set", setting]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    log_path = os.path.join(out, "log.txt")
    start = time.time()
    with open(log_path, "w") as log:
        job = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT, env=env, start_new_session=True)
        try:
            while True:
                time.sleep(1.0)
                with open(log_path) as text:
                    if any(line.startswith(FIRST_PROGRESS) for line in text):
                        break
                if job.poll() is not None:
                    sys.exit(f"suspension_memory: the {ranks}-rank run ended before its first progress line; "
                             f"see {log_path}")
            seconds = time.time() - start
            peaks = [peak_resident_mib(pid) for pid in app_processes(executable, job.pid)]
        finally:
            try:
                os.killpg(job.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            job.wait()
    if len(peaks) != ranks:
        sys.exit(f"suspension_memory: found {len(peaks)} processes of {executable} in the run's session "
                 f"for {ranks} ranks")
    with open(log_path) as text:
        banner = text.readline()
    version = banner.split("(git ", 1)[1].split(",", 1)[0] if "(git " in banner else "?"
    return sorted(peaks), seconds, version


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", required=True, help="the build directory (apps/suspension3d/suspension3d)")
    parser.add_argument("--deck", default=DECK, help="the suspension3d deck (default: the margination deck)")
    parser.add_argument("--ranks", default="1,2,4", help="the numbers of ranks, comma-separated (default 1,2,4)")
    parser.add_argument("--runs", default="out/suspension-memory", help="where the runs write (default %(default)s)")
    parser.add_argument("--set", action="append", default=[], help="a deck override KEY=VALUE, passed to the app")
    args = parser.parse_args()
    try:
        counts = [int(n) for n in args.ranks.split(",")]
    except ValueError:
        counts = []
    if not counts or min(counts) < 1:
        parser.error(f"--ranks '{args.ranks}' must be positive integers, comma-separated")
    if not os.access(os.path.join(args.build, "apps", "suspension3d", "suspension3d"), os.X_OK):
        parser.error(f"--build '{args.build}' has no apps/suspension3d/suspension3d")
    if not os.path.isfile(args.deck):
        parser.error(f"--deck '{args.deck}' is not a file")
    print(f"suspension_memory.py (source tree at git {report_helpers.git_sha()}) on {report_helpers.cpu_model()}, "
          f"{os.cpu_count()} cores; deck {os.path.relpath(args.deck, ROOT)}"
          + "".join(f" --set '{s}'" for s in args.set))
    print("| ranks | peak resident memory per rank (MiB) | largest | largest / one rank's | s to the first output "
          "| app at git |")
    print("|---|---|---|---|---|---|")
    reference = None
    for ranks in counts:
        peaks, seconds, version = measure(args, ranks)
        largest = max(peaks)
        reference = reference if reference is not None else largest
        print(f"| {ranks} | {', '.join(f'{p:.0f}' for p in peaks)} | {largest:.0f} | {largest / reference:.2f} "
              f"| {seconds:.0f} | {version} |", flush=True)


if __name__ == "__main__":
    main()
